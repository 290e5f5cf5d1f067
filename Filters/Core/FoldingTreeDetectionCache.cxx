#include "FoldingTreeDetectionCache.h"

#include <cstring>

namespace foldingmeshes
{
namespace treebuilder
{
namespace
{
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
}

bool DetectionCache::Key::operator==(const Key& other) const
{
  // Bit for bit (-0.0 and 0.0 differ: the same input to the detection only when identical).
  auto sameBytes = [](const auto& a, const auto& b)
  {
    return a.size() == b.size() &&
      (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
  };
  return std::memcmp(&eps, &other.eps, sizeof(eps)) == 0 && sameBytes(points, other.points) &&
    sameBytes(triangles, other.triangles) && sameBytes(pointIds, other.pointIds);
}

uint64_t DetectionCache::Hash(const Key& key)
{
  uint64_t h = 14695981039346656037ull;
  h = HashBytes(h, &key.eps, sizeof(key.eps));
  h = HashBytes(h, key.points.data(), key.points.size() * sizeof(Vec3));
  h = HashBytes(h, key.triangles.data(), key.triangles.size() * sizeof(Triangle));
  return HashBytes(h, key.pointIds.data(), key.pointIds.size() * sizeof(int));
}

std::shared_ptr<const SymmetryResult>& DetectionCache::For(const WorkMesh& w,
  bool withPointIds,
  double eps)
{
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Triangle) == 3 * sizeof(int),
    "the key's vectors are compared and hashed as packed bytes");
  Key key;
  key.eps = eps;
  key.points = w.points;
  key.triangles = w.triangles;
  if (withPointIds)
    key.pointIds = w.pointOrig;
  const uint64_t h = Hash(key);
  const auto range = this->Entries.equal_range(h);
  for (auto it = range.first; it != range.second; ++it)
    if (it->second.first == key)
      return *it->second.second;
  auto slot = std::make_unique<std::shared_ptr<const SymmetryResult>>();
  std::shared_ptr<const SymmetryResult>& made = *slot;
  this->Entries.emplace(h, std::make_pair(std::move(key), std::move(slot)));
  return made;
}

std::shared_ptr<const SymmetryResult> DetectOrReuse(std::shared_ptr<const SymmetryResult>* slot,
  const PreparedMesh& pm,
  const SymmetryOptions& options,
  const FaceTree* faces,
  const TraceSink& trace,
  int index)
{
  if (slot && *slot)
  {
    if (trace)
      trace(FormatTrace(
        "[detect] node %d: the region and epsilon of an earlier build's detection, its result "
        "reused",
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
