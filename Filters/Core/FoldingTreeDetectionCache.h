// The plane detections of one BuildFoldingTree call, for its later builds to reuse; internal,
// not installed.
#ifndef foldingmeshes_FoldingTreeDetectionCache_h
#define foldingmeshes_FoldingTreeDetectionCache_h

#include "FoldingWorkMesh.h"
#include "SymmetryDetection.h"
#include "Trace.h"

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace foldingmeshes
{
namespace treebuilder
{
/**
 * BuildFoldingTree builds a tree again when the first one misses its verification (faces
 * pinned, rotation nodes off, second orders off); the regions of those builds are often the
 * first build's regions bit for bit - the root always, and the nodes the pins do not reach.
 * Plane detection is a function of what Builder::Prepare reads of a region (its points and
 * triangles, and its points' input ids when the input has normals) and of epsilon, the
 * options being the same in every build of one call; so a region met again takes the
 * detection stored for it instead of running it: the same result, the same tree. Matching
 * compares those inputs exactly (a hash finds the candidates). Rotation detection is not kept:
 * its minimum order depends on the node's trimmed region, which pins change (on the spider the
 * root's differs between the two builds). Not thread-safe (the builder is sequential).
 */
class DetectionCache
{
public:
  /// The detection stored for region w at epsilon eps (empty: none yet; the caller stores
  /// it there). withPointIds: the detection reads the input's normals through w.pointOrig.
  /// The reference stays valid for the cache's lifetime.
  std::shared_ptr<const SymmetryResult>& For(const WorkMesh& w, bool withPointIds, double eps);

private:
  struct Key
  {
    double eps = 0.0;
    std::vector<Vec3> points;
    std::vector<Triangle> triangles;
    std::vector<int> pointIds; ///< empty unless withPointIds
    bool operator==(const Key& other) const;
  };
  static uint64_t Hash(const Key& key);
  std::unordered_multimap<uint64_t,
    std::pair<Key, std::unique_ptr<std::shared_ptr<const SymmetryResult>>>>
    Entries;
};

/// The plane detection of region pm (node `index`): the one in `slot` (an earlier build's,
/// with a trace line saying so), else DetectSymmetry's, stored in the slot unless aborted.
/// Null slot: detect, store nothing.
std::shared_ptr<const SymmetryResult> DetectOrReuse(std::shared_ptr<const SymmetryResult>* slot,
  const PreparedMesh& pm,
  const SymmetryOptions& options,
  const FaceTree* faces,
  const TraceSink& trace,
  int index);
}
}

#endif
