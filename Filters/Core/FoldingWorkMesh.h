// WorkMesh (a region being built by BuildFoldingTree) and its helpers; internal, not installed.
#ifndef foldingmeshes_FoldingWorkMesh_h
#define foldingmeshes_FoldingWorkMesh_h

#include "TriangleMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace foldingmeshes
{
namespace treebuilder
{
/// A region being built: mesh data plus everything that travels into the leaves.
struct WorkMesh
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<int> pointOrig;
  std::vector<int> faceOrig;
  std::vector<uint64_t> tear;
  std::vector<uint64_t> onPlane;
  std::vector<char> projected;
  /// Per point: (2 * level + flag, mirror mask), flag 0 tear, 1 plane; see MirroredFlag.
  std::vector<std::vector<std::pair<int, uint64_t>>> mirrorFlags;
  /// Per point: the unfolding error the folds below may still add here (errorBudget).
  std::vector<double> budget;

  int NumberOfFaces() const { return static_cast<int>(triangles.size()); }
  int NumberOfPoints() const { return static_cast<int>(points.size()); }

  /// Appends point v of `from` with everything it carries.
  void AppendPoint(const WorkMesh& from, int v)
  {
    points.push_back(from.points[v]);
    pointOrig.push_back(from.pointOrig[v]);
    tear.push_back(from.tear[v]);
    onPlane.push_back(from.onPlane[v]);
    projected.push_back(from.projected[v]);
    mirrorFlags.push_back(from.mirrorFlags[v]);
    budget.push_back(from.budget[v]);
  }
};

double TriangleArea(const WorkMesh& w, const Triangle& t);

double Area(const WorkMesh& w);

/// The faces selected by `mask`, with their points (renumbered in increasing old order).
WorkMesh Extract(const WorkMesh& w, const std::vector<char>& mask);

/// The faces `faces` (increasing ids), with their points (renumbered in increasing old order).
WorkMesh ExtractFaces(const WorkMesh& w, const std::vector<int>& faces);

/**
 * Welds points with identical coordinates (their flags are OR-ed; the lowest point keeps
 * its original id), drops faces with a repeated vertex and unused points. Returns the
 * original ids of the dropped faces.
 */
std::vector<int> WeldAndDropCollapsed(WorkMesh& w);

/// Tear vertices of the segmentation at `depth`: used by faces of two different children (S
/// is child 0, remaining component c is child 1 + c, labels per face).
void MarkTears(WorkMesh& w, const std::vector<char>& S, const std::vector<int>& labels, int depth);
}
}

#endif
