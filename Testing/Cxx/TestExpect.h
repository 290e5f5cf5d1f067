// The failure check of the test programs: FOLDINGMESHES_EXPECT(counter, cond, msg) prints
// "FAIL (file:line): msg" (msg is streamed, e.g. "faces " << n) and increments counter when
// cond is false. Each program defines its own short EXPECT(cond, msg) with its counter.
#ifndef foldingmeshes_TestExpect_h
#define foldingmeshes_TestExpect_h

#include <cstdio>
#include <sstream>

#define FOLDINGMESHES_EXPECT(counter, cond, msg)                                                   \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::ostringstream os_;                                                                      \
      os_ << msg;                                                                                  \
      std::printf("FAIL (%s:%d): %s\n", __FILE__, __LINE__, os_.str().c_str());                    \
      ++(counter);                                                                                 \
    }                                                                                              \
  } while (0)

#endif
