#include "FoldingTreeDetectionCache.h"

#include <cstring>

namespace foldingmeshes
{
namespace treebuilder
{
namespace
{
static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Triangle) == 3 * sizeof(int),
  "regions are compared and hashed as packed bytes");

/// FNV-1a over raw bytes, eight at a time (a region's points and triangles: megabytes at the
/// root of a large mesh), continued from `h`.
uint64_t HashBytes(uint64_t h, const void* data, size_t size)
{
  const unsigned char* bytes = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= size; i += 8)
  {
    uint64_t word;
    std::memcpy(&word, bytes + i, 8);
    h ^= word;
    h *= 1099511628211ull;
  }
  for (; i < size; ++i)
  {
    h ^= bytes[i];
    h *= 1099511628211ull;
  }
  return h;
}

/// Bit for bit (-0.0 and 0.0 differ: the same input to the detection only when identical).
template <typename T>
bool SameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() &&
    (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool SamePlane(const Plane& a, const Plane& b)
{
  return a.origin == b.origin && a.normal == b.normal;
}
}

DetectionCache::Slot& DetectionCache::For(const WorkMesh& w, bool withPointIds, double eps)
{
  static const std::vector<int> none;
  const std::vector<int>& ids = withPointIds ? w.pointOrig : none;
  uint64_t h = 14695981039346656037ull;
  h = HashBytes(h, &eps, sizeof(eps));
  h = HashBytes(h, w.points.data(), w.points.size() * sizeof(Vec3));
  h = HashBytes(h, w.triangles.data(), w.triangles.size() * sizeof(Triangle));
  h = HashBytes(h, ids.data(), ids.size() * sizeof(int));
  const auto range = this->Entries.equal_range(h);
  for (auto it = range.first; it != range.second; ++it)
  {
    const Entry& e = it->second;
    if (std::memcmp(&e.eps, &eps, sizeof(eps)) == 0 && SameBytes(e.points, w.points) &&
      SameBytes(e.triangles, w.triangles) && SameBytes(e.pointIds, ids))
      return it->second.result;
  }
  // Elements of an unordered container stay where they are when others are inserted.
  return this->Entries.emplace(h, Entry{ eps, w.points, w.triangles, ids, nullptr })->second.result;
}

bool SameDetectionOptions(const FoldingTreeOptions& a, const FoldingTreeOptions& b)
{
  const SymmetryOptions &x = a.symmetry, &y = b.symmetry;
  return x.robust == y.robust && x.useInitialPlane == y.useInitialPlane &&
    SamePlane(x.initialPlane, y.initialPlane) && x.numberOfCandidates == y.numberOfCandidates &&
    x.maximumIterations == y.maximumIterations && x.compatibilityAngle == y.compatibilityAngle &&
    x.minimumSymmetricAreaFraction == y.minimumSymmetricAreaFraction && x.seed == y.seed &&
    x.sampledSearchAboveFaces == y.sampledSearchAboveFaces &&
    x.refineSampledFinalists == y.refineSampledFinalists &&
    x.scoreEveryFinalist == y.scoreEveryFinalist &&
    x.distancesUpTo3Sigma == y.distancesUpTo3Sigma && x.fastPathQuery == y.fastPathQuery &&
    static_cast<bool>(x.closestFaceFastPath) == static_cast<bool>(y.closestFaceFastPath) &&
    a.sampledSearchAboveFaces == b.sampledSearchAboveFaces &&
    a.connectNearbyParts == b.connectNearbyParts;
}

DetectionCache::Slot DetectOrReuse(DetectionCache::Slot* slot,
  const PreparedMesh& pm,
  const SymmetryOptions& options,
  const FaceTree* faces,
  const TraceSink& trace,
  int index)
{
  if (slot && *slot)
  {
    if (trace)
      trace(FormatTrace("[detect] node %d: the region and epsilon of an earlier detection, its "
                        "result reused",
        index));
    return *slot;
  }
  auto detected = std::make_shared<const SymmetryResult>(DetectSymmetry(pm, options, faces));
  if (slot && !detected->aborted)
    *slot = detected;
  return detected;
}
}
}
