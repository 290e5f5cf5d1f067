// The plane detections of one BuildFoldingTree call, for its later builds to reuse; internal,
// not installed.
#ifndef foldingmeshes_FoldingTreeDetectionCache_h
#define foldingmeshes_FoldingTreeDetectionCache_h

#include "FoldingTreeBuilder.h"
#include "FoldingWorkMesh.h"
#include "SymmetryDetection.h"
#include "Trace.h"

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace foldingmeshes
{
namespace treebuilder
{
/**
 * BuildFoldingTree builds a tree again when the first one misses its verification (faces
 * pinned, rotation nodes off, second orders off); the regions of those builds are often the
 * first build's regions bit for bit - the root unless epsilon changed (a near miss), and the
 * nodes whose regions the pins leave as they were. Plane detection is a function of what
 * Builder::Prepare reads of a region (its points and triangles, and its points' input ids when
 * the input has normals), of epsilon and of the detection's options; so a region met again at
 * the same epsilon, with the same options (SameDetectionOptions), takes the detection stored
 * for it instead of running it: the same result, the same tree. Matching compares those inputs
 * exactly (a hash finds the candidates). A region met twice within one build (the alternatives
 * of a rotation node) is reused too. Rotation detection is not kept: its minimum order depends
 * on the node's trimmed region, which pins change (the spider's root differs between its two
 * builds). Memory: per region detected, a copy of its points, triangles (and input ids) and the
 * detection's result (per-vertex distances and weights), for the whole call. Not thread-safe
 * (the builder is sequential).
 */
class DetectionCache
{
public:
  using Slot = std::shared_ptr<const SymmetryResult>;

  /// The detection stored for region w at epsilon eps (empty: none yet; the caller stores it
  /// there). withPointIds: the detection reads the input's normals through w.pointOrig. The
  /// reference stays valid for the cache's lifetime.
  Slot& For(const WorkMesh& w, bool withPointIds, double eps);

private:
  struct Entry
  {
    double eps = 0.0;
    std::vector<Vec3> points;
    std::vector<Triangle> triangles;
    std::vector<int> pointIds; ///< empty unless withPointIds
    Slot result;
  };
  std::unordered_multimap<uint64_t, Entry> Entries;
};

/// Whether builds with options a and b detect alike on the same region and epsilon: every
/// option the builder passes to DetectSymmetry or reads in Builder::Prepare but epsilon (the
/// fast-path factory, a function, is taken to be the same; BuildFoldingTree's builds copy it).
bool SameDetectionOptions(const FoldingTreeOptions& a, const FoldingTreeOptions& b);

/// The plane detection of region pm (node `index`): the one in `slot` (an earlier build's,
/// with a trace line saying so), else DetectSymmetry's, stored in the slot unless aborted.
/// Null slot: detect, store nothing.
DetectionCache::Slot DetectOrReuse(DetectionCache::Slot* slot,
  const PreparedMesh& pm,
  const SymmetryOptions& options,
  const FaceTree* faces,
  const TraceSink& trace,
  int index);
}
}

#endif
