#include "ProcessMemory.h"

#include <cstdlib> // defines __GLIBC__ with the GNU C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace foldingmeshes
{
namespace cli
{
void KeepFreedMemoryForReuse()
{
#if defined(__GLIBC__)
  // glibc's largest threshold on 64-bit systems; where it is refused (32-bit: 512 kB at most),
  // nothing else is set either (setting the others alone would fix the threshold at 128 kB).
  if (mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024) == 0)
    return;
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
  mallopt(M_TOP_PAD, 64 * 1024 * 1024);
#endif
}
}
}
