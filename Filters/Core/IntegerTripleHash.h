// A hash of three integers (a grid cell's key, a triangle's sorted corner ids) for unordered
// containers.
#ifndef foldingmeshes_IntegerTripleHash_h
#define foldingmeshes_IntegerTripleHash_h

#include <array>
#include <cstddef>
#include <cstdint>

namespace foldingmeshes
{
struct IntegerTripleHash
{
  template <typename Integer>
  size_t operator()(const std::array<Integer, 3>& k) const
  {
    const uint64_t h = static_cast<uint64_t>(k[0]) * 0x9E3779B97F4A7C15ull ^
      static_cast<uint64_t>(k[1]) * 0xC2B2AE3D27D4EB4Full ^
      static_cast<uint64_t>(k[2]) * 0x165667B19E3779F9ull;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};
}

#endif
