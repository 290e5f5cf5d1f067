#include "FoldingTreeBuilder.h"

#include "CandidatePlanes.h"
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "RegionGrowing.h"
#include "SurfaceDistance.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

namespace foldingmeshes
{
namespace
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
};

double TriangleArea(const WorkMesh& w, const Triangle& t)
{
  return 0.5 * (w.points[t[1]] - w.points[t[0]]).cross(w.points[t[2]] - w.points[t[0]]).norm();
}

double Area(const WorkMesh& w)
{
  double area = 0.0;
  for (const Triangle& t : w.triangles)
    area += TriangleArea(w, t);
  return area;
}

/// The faces selected by `mask`, with their points (renumbered in increasing old order).
WorkMesh Extract(const WorkMesh& w, const std::vector<char>& mask)
{
  WorkMesh out;
  std::vector<int> newId(w.points.size(), -1);
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (mask[f])
      for (int v : w.triangles[f])
        newId[v] = 0;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    if (newId[v] == 0)
    {
      newId[v] = out.NumberOfPoints();
      out.points.push_back(w.points[v]);
      out.pointOrig.push_back(w.pointOrig[v]);
      out.tear.push_back(w.tear[v]);
      out.onPlane.push_back(w.onPlane[v]);
      out.projected.push_back(w.projected[v]);
      out.mirrorFlags.push_back(w.mirrorFlags[v]);
      out.budget.push_back(w.budget[v]);
    }
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (mask[f])
    {
      const Triangle& t = w.triangles[f];
      out.triangles.push_back({ newId[t[0]], newId[t[1]], newId[t[2]] });
      out.faceOrig.push_back(w.faceOrig[f]);
    }
  return out;
}

/// The faces `faces` (increasing ids), with their points (renumbered in increasing old order).
WorkMesh ExtractFaces(const WorkMesh& w, const std::vector<int>& faces)
{
  std::vector<int> points;
  for (int f : faces)
    points.insert(points.end(), w.triangles[f].begin(), w.triangles[f].end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  WorkMesh out;
  for (int v : points)
  {
    out.points.push_back(w.points[v]);
    out.pointOrig.push_back(w.pointOrig[v]);
    out.tear.push_back(w.tear[v]);
    out.onPlane.push_back(w.onPlane[v]);
    out.projected.push_back(w.projected[v]);
    out.mirrorFlags.push_back(w.mirrorFlags[v]);
    out.budget.push_back(w.budget[v]);
  }
  auto id = [&](int v)
  { return static_cast<int>(std::lower_bound(points.begin(), points.end(), v) - points.begin()); };
  for (int f : faces)
  {
    const Triangle& t = w.triangles[f];
    out.triangles.push_back({ id(t[0]), id(t[1]), id(t[2]) });
    out.faceOrig.push_back(w.faceOrig[f]);
  }
  return out;
}

/**
 * Welds points with identical coordinates (their flags are OR-ed; the lowest point keeps
 * its original id), drops faces with a repeated vertex and unused points. Returns the
 * original ids of the dropped faces.
 */
std::vector<int> WeldAndDropCollapsed(WorkMesh& w)
{
  const int n = w.NumberOfPoints();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto& p = w.points;
  std::sort(order.begin(),
    order.end(),
    [&](int i, int j)
    {
      if (p[i].x() != p[j].x())
        return p[i].x() < p[j].x();
      if (p[i].y() != p[j].y())
        return p[i].y() < p[j].y();
      if (p[i].z() != p[j].z())
        return p[i].z() < p[j].z();
      return i < j;
    });
  std::vector<int> rep(n);
  for (int k = 0; k < n;)
  {
    int e = k;
    while (e < n && p[order[e]] == p[order[k]])
      ++e;
    for (int m = k; m < e; ++m)
      rep[order[m]] = order[k];
    k = e;
  }
  for (int v = 0; v < n; ++v)
    if (rep[v] != v)
    {
      w.tear[rep[v]] |= w.tear[v];
      w.onPlane[rep[v]] |= w.onPlane[v];
      w.projected[rep[v]] |= w.projected[v];
      w.budget[rep[v]] = std::min(w.budget[rep[v]], w.budget[v]);
      auto& into = w.mirrorFlags[rep[v]];
      into.insert(into.end(), w.mirrorFlags[v].begin(), w.mirrorFlags[v].end());
      std::sort(into.begin(), into.end());
      into.erase(std::unique(into.begin(), into.end()), into.end());
    }
  std::vector<char> keep(w.triangles.size(), 1);
  std::vector<int> dropped;
  for (size_t f = 0; f < w.triangles.size(); ++f)
  {
    Triangle& t = w.triangles[f];
    for (int& v : t)
      v = rep[v];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      keep[f] = 0;
      dropped.push_back(w.faceOrig[f]);
    }
  }
  w = Extract(w, keep);
  return dropped;
}

/**
 * The point of the intersection of the planes closest to x (planes[0] is the new fold plane,
 * the others ancestors' planes x already lies on). Planes nearly dependent on the others
 * (e.g. three planes through almost the same line) are treated as redundant (relative
 * singular-value threshold 1e-3); if the result is inconsistent - it misses a plane by more
 * than `tolerance`, or moves x much farther than the distances to the planes - x is only
 * projected onto planes[0] and false is returned (the caller then drops the ancestors'
 * flags the point no longer satisfies).
 */
bool ProjectOntoPlanes(Vec3& x, const std::vector<Plane>& planes, double tolerance)
{
  if (planes.size() == 1)
  {
    x = planes[0].Project(x);
    return true;
  }
  Eigen::MatrixXd A(planes.size(), 3);
  Eigen::VectorXd r(planes.size());
  double largest = 0.0;
  for (size_t k = 0; k < planes.size(); ++k)
  {
    A.row(k) = planes[k].normal.transpose();
    r[k] = -planes[k].SignedDistance(x);
    largest = std::max(largest, std::abs(r[k]));
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-3);
  const Eigen::Vector3d delta = cod.solve(r);
  const Vec3 y = x + delta;
  bool consistent = delta.allFinite() && delta.norm() <= 4.0 * largest + tolerance;
  for (const Plane& p : planes)
    consistent = consistent && std::abs(p.SignedDistance(y)) <= tolerance;
  x = consistent ? y : planes[0].Project(x);
  return consistent;
}

class Builder
{
public:
  Builder(const FoldingTreeOptions& options,
    const std::vector<Vec3>& inputNormals,
    FoldingTree& tree)
    : Options(options)
    , InputNormals(inputNormals)
    , Tree(tree)
  {
    this->MaximumDepth = std::max(1, std::min(options.maximumDepth, MaximumFoldingTreeLevels - 1));
  }

  void Run(WorkMesh root)
  {
    this->PlaneAtDepth.assign(MaximumFoldingTreeLevels, Plane());
    this->EpsilonAtDepth.assign(MaximumFoldingTreeLevels, 0.0);
    {
      TriangleMesh input;
      input.points = root.points;
      input.triangles = root.triangles;
      this->ToInput.reset(new SurfaceDistanceQuery(input));
    }
    this->Build(std::move(root), -1, 0, this->Options.epsilon, 0, 0);
    this->Report(1.0);
  }

  bool Aborted = false;

private:
  /// Reports monotonic progress; false once the callback asked to stop.
  bool Report(double value)
  {
    if (this->Aborted)
      return false;
    value = std::min(1.0, std::max(value, this->LastProgress));
    this->LastProgress = value;
    if (this->Options.progress && !this->Options.progress(value))
      this->Aborted = true;
    return !this->Aborted;
  }

  double Fraction(double faces) const
  {
    return this->Tree.numberOfOriginalFaces > 0 ? faces / this->Tree.numberOfOriginalFaces : 1.0;
  }

  int NewNode(int parent, int depth, double eps, int folds, const WorkMesh& w)
  {
    FoldingNode node;
    node.parent = parent;
    node.depth = depth;
    node.epsilon = eps;
    node.foldsAbove = folds;
    node.numberOfFaces = w.NumberOfFaces();
    node.area = Area(w);
    node.originalFaces = w.faceOrig;
    std::sort(node.originalFaces.begin(), node.originalFaces.end());
    this->Tree.nodes.push_back(std::move(node));
    const int index = this->Tree.NumberOfNodes() - 1;
    if (parent >= 0)
      this->Tree.nodes[parent].children.push_back(index);
    return index;
  }

  void MakeLeaf(int index, WorkMesh& w, LeafReason reason)
  {
    FoldingNode& node = this->Tree.nodes[index];
    node.kind = FoldingNodeKind::Leaf;
    node.leafReason = reason;
    FoldingLeafMesh& m = node.mesh;
    m.points = std::move(w.points);
    m.triangles = std::move(w.triangles);
    m.originalPointIds = std::move(w.pointOrig);
    m.originalFaceIds = std::move(w.faceOrig);
    m.tearMask = std::move(w.tear);
    m.planeMask = std::move(w.onPlane);
    m.projected = std::move(w.projected);
    if (this->Options.errorBudget)
      m.errorBudget = std::move(w.budget);
    for (int v = 0; v < static_cast<int>(w.mirrorFlags.size()); ++v)
    {
      auto entries = w.mirrorFlags[v];
      std::sort(entries.begin(), entries.end());
      for (const auto& e : entries)
        m.mirroredFlags.push_back(
          { v, e.first / 2, e.second, e.first % 2 ? LevelFlag::Plane : LevelFlag::Tear });
    }
    this->DoneFaces += m.NumberOfFaces();
    this->Report(this->Fraction(this->DoneFaces));
  }

  bool Prepare(const WorkMesh& w, double eps, PreparedMesh& pm) const
  {
    TriangleMesh soup;
    soup.points = w.points;
    soup.triangles = w.triangles;
    std::vector<Vec3> normals;
    if (!this->InputNormals.empty())
      for (int v = 0; v < w.NumberOfPoints(); ++v)
        normals.push_back(this->InputNormals[w.pointOrig[v]]);
    std::string error;
    if (!PrepareMesh(soup, normals, pm, error))
      return false;
    if (this->Options.connectNearbyParts)
      LinkNearbyParts(pm, eps);
    return true;
  }

  /// S minus the faces whose mirrored vertices are not within eps of S (see the header).
  /// The faces of S as a prepared mesh (face order kept) with the region's vertex normals.
  static bool PrepareSubset(const WorkMesh& w,
    const PreparedMesh& pm,
    const std::vector<char>& S,
    PreparedMesh& spm)
  {
    WorkMesh sub = Extract(w, S);
    if (sub.NumberOfFaces() == 0)
      return false;
    TriangleMesh soup;
    soup.points = sub.points;
    soup.triangles = sub.triangles;
    // The region's vertex normals (not the sub-mesh's), as detection used them.
    std::vector<Vec3> normals(sub.NumberOfPoints());
    int next = 0;
    std::vector<char> used(w.points.size(), 0);
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      if (S[f])
        for (int v : w.triangles[f])
          used[v] = 1;
    for (int v = 0; v < w.NumberOfPoints(); ++v)
      if (used[v])
        normals[next++] = pm.vertexNormals[v];
    std::string error;
    return PrepareMesh(soup, normals, spm, error);
  }

  /**
   * Polishes the plane on S alone: Gauss-Newton steps of the point-to-tangent-plane fit
   * (RefinePlaneFromCorrespondences) with every vertex of S weighted by its area, partners =
   * closest compatible points of S itself. Detection weighs vertices near the remaining
   * faces down and can stop a fraction of a degree off; on the trimmed S there are no
   * outliers. The plane with the lowest area-weighted residual is returned (the input plane
   * unless a step improves it).
   */
  Plane Polish(const WorkMesh& w,
    const PreparedMesh& pm,
    const std::vector<char>& S,
    const Plane& plane,
    double eps) const
  {
    PreparedMesh spm;
    if (!PrepareSubset(w, pm, S, spm))
      return plane;
    MirrorDistance distances(spm, this->Options.symmetry.compatibilityAngle);
    std::vector<double> d;
    std::vector<Vec3> closest, closestNormals;
    Plane current = plane, best = plane;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < 12; ++iteration)
    {
      distances.Compute(current, DistanceMetric::Fine, eps, d, &closest, &closestNormals);
      double cost = 0.0;
      std::vector<double> weights(d.size(), 0.0);
      for (size_t v = 0; v < d.size(); ++v)
      {
        const double dv = std::isfinite(d[v]) ? d[v] : eps;
        cost += spm.vertexAreas[v] * dv * dv;
        if (std::isfinite(d[v]))
          weights[v] = spm.vertexAreas[v];
      }
      if (!(cost < bestCost))
        break;
      bestCost = cost;
      best = current;
      Plane next;
      if (!RefinePlaneFromCorrespondences(
            spm.points, closest, closestNormals, weights, current, next))
        break;
      const bool small = PlaneAngleDegrees(next, current) < 1e-7 &&
        PlaneOffsetAt(current, next, next.origin) < 1e-12 * this->Tree.diagonal;
      current = next;
      if (small)
        break;
    }
    return CanonicalPlane(best, plane.origin);
  }

  /**
   * For the points `ids` of w: the error a fold through `plane` may add there, the least of
   * eps and the budgets of the point and of the point of `ids` nearest to its mirror image
   * (within eps; else the least budget of all): a copy made by the fold lands there.
   */
  std::vector<double> MirrorBudget(const WorkMesh& w,
    const std::vector<int>& ids,
    const Plane& plane,
    double eps) const
  {
    Buckets buckets;
    buckets.cell = std::max(eps, 1e-12 * this->Tree.diagonal);
    double least = eps;
    for (int v : ids)
    {
      buckets.Add(w.points[v], v);
      least = std::min(least, w.budget[v]);
    }
    std::vector<double> limit(ids.size());
    for (size_t k = 0; k < ids.size(); ++k)
    {
      const int v = ids[k];
      const int p = buckets.Nearest(w.points, plane.Reflect(w.points[v]), eps);
      limit[k] = std::min({ eps, w.budget[v], p >= 0 ? w.budget[p] : least });
    }
    return limit;
  }

  std::vector<char> Trim(const WorkMesh& w,
    const PreparedMesh& pm,
    std::vector<char> S,
    const Plane& plane,
    double eps) const
  {
    for (int iteration = 0; iteration < 8; ++iteration)
    {
      PreparedMesh spm;
      if (!PrepareSubset(w, pm, S, spm))
        break;
      MirrorDistance distances(spm, this->Options.symmetry.compatibilityAngle);
      std::vector<double> d;
      distances.Compute(plane, DistanceMetric::Fine, eps, d);
      if (this->Options.errorBudget)
      {
        // The vertices of S are spm's points, in increasing order of their ids in w.
        std::vector<int> ids;
        {
          std::vector<char> inS(w.points.size(), 0);
          for (int f = 0; f < w.NumberOfFaces(); ++f)
            if (S[f])
              for (int v : w.triangles[f])
                inS[v] = 1;
          for (int v = 0; v < w.NumberOfPoints(); ++v)
            if (inS[v])
              ids.push_back(v);
        }
        const std::vector<double> limit = this->MirrorBudget(w, ids, plane, eps);
        for (size_t k = 0; k < d.size() && k < ids.size(); ++k)
          if (!(d[k] < limit[k]))
            d[k] = std::numeric_limits<double>::infinity();
      }
      const std::vector<char> ok = FacesWithVerticesWithin(spm, d, eps, true);
      std::vector<char> next = S;
      bool changed = false;
      int k = 0;
      for (int f = 0; f < w.NumberOfFaces(); ++f)
        if (S[f])
        {
          // Degenerate faces have no distance of their own: judged with their neighbours.
          if (!ok[k] && !spm.faceDegenerate[k])
          {
            next[f] = 0;
            changed = true;
          }
          ++k;
        }
      if (!changed)
        break;
      S = LargestConnectedRegion(pm, next);
    }
    return S;
  }

  bool IsAncestorPlane(const Plane& p, uint64_t pathFolds, const Vec3& at, double eps) const
  {
    for (int d = 0; d < MaximumFoldingTreeLevels; ++d)
      if (pathFolds & (uint64_t(1) << d))
      {
        const Plane& q = this->PlaneAtDepth[d];
        if (PlaneAngleDegrees(p, q) < 2.0 && PlaneOffsetAt(q, p, at) < eps)
          return true;
      }
    return false;
  }

  /// Builds the subtree of region w; returns its node index.
  int Build(WorkMesh w, int parent, int depth, double eps, int folds, uint64_t pathFolds)
  {
    const std::vector<int> dropped = WeldAndDropCollapsed(w);
    if (parent < 0)
      this->Tree.numberOfDroppedFaces = static_cast<int>(dropped.size());
    else if (!dropped.empty())
    {
      // Only projections onto a fold plane make points coincide below the root: the faces
      // they collapse count as removed by that fold.
      FoldingNode& fold = this->Tree.nodes[parent];
      fold.discardedOriginalFaces.insert(
        fold.discardedOriginalFaces.end(), dropped.begin(), dropped.end());
      std::sort(fold.discardedOriginalFaces.begin(), fold.discardedOriginalFaces.end());
      fold.discardedFaces = static_cast<int>(fold.discardedOriginalFaces.size());
    }
    const int index = this->NewNode(parent, depth, eps, folds, w);
    const FoldingTreeOptions& O = this->Options;
    const int nf = w.NumberOfFaces();
    const double area = this->Tree.nodes[index].area;

    if (this->Aborted)
      return this->MakeLeaf(index, w, LeafReason::Aborted), index;
    if (O.useMinimumFaces && nf < O.minimumFaces)
      return this->MakeLeaf(index, w, LeafReason::MinimumFaces), index;
    if (O.useMinimumAreaFraction && area < O.minimumAreaFraction * this->Tree.originalArea)
      return this->MakeLeaf(index, w, LeafReason::MinimumArea), index;
    if (O.useMaximumFolds && folds >= O.maximumFolds)
      return this->MakeLeaf(index, w, LeafReason::MaximumFolds), index;
    // A segmentation needs two more levels (its folding child and the kept half).
    if (depth + 2 > this->MaximumDepth)
      return this->MakeLeaf(index, w, LeafReason::MaximumDepth), index;

    PreparedMesh pm;
    if (nf == 0 || !this->Prepare(w, eps, pm) || pm.NumberOfPoints() != w.NumberOfPoints())
      return this->MakeLeaf(index, w, LeafReason::DetectionFailed), index;
    w.triangles = pm.triangles; // oriented

    SymmetryOptions so = O.symmetry;
    so.epsilon = eps;
    const double base = this->Fraction(this->DoneFaces);
    const double span = 0.5 * this->Fraction(nf);
    so.progress = [&](double p) { return this->Report(base + p * span); };
    const SymmetryResult result = DetectSymmetry(pm, so);
    FoldingNode& node = this->Tree.nodes[index];
    node.detectionRun = true;
    if (result.aborted || this->Aborted)
    {
      this->Aborted = true;
      return this->MakeLeaf(index, w, LeafReason::Aborted), index;
    }

    std::vector<char> S(nf, 0);
    bool any = false;
    for (int f = 0; f < nf; ++f)
    {
      S[f] = result.faceLabel[f] == 2;
      any = any || S[f];
    }
    Plane plane = result.plane;
    // Trimming keeps the faces whose mirrored vertices are within eps of S - or within the
    // error budget left there, if less (errorBudget).
    if (any && O.trimToMirrorConsistent)
      S = this->Trim(w, pm, S, plane, eps);
    if (any && O.polishPlane)
    {
      plane = this->Polish(w, pm, S, plane, eps);
      if (O.trimToMirrorConsistent)
        S = this->Trim(w, pm, S, plane, eps);
    }
    // Input-degenerate faces (never in S: detection ignores them) follow S when all their
    // vertices are vertices of S.
    {
      std::vector<char> inS(w.points.size(), 0);
      for (int f = 0; f < nf; ++f)
        if (S[f])
          for (int v : w.triangles[f])
            inS[v] = 1;
      for (int f = 0; f < nf; ++f)
        if (pm.faceDegenerate[f] && inS[w.triangles[f][0]] && inS[w.triangles[f][1]] &&
          inS[w.triangles[f][2]])
          S[f] = 1;
    }
    const double sArea = RegionArea(pm, S);
    int sFaces = 0;
    for (char s : S)
      sFaces += s;
    node.symmetricAreaFraction = pm.totalArea > 0 ? sArea / pm.totalArea : 0.0;

    bool meaningful = sFaces > 0;
    if (O.requireMeaningfulSymmetry)
    {
      meaningful = meaningful && (result.found || !O.requireTightSymmetry) &&
        node.symmetricAreaFraction >= O.symmetry.minimumSymmetricAreaFraction &&
        sFaces >= (O.useMinimumFaces ? std::max(1, O.minimumFaces) : 1);
      Vec3 centroid = Vec3::Zero();
      double total = 0.0;
      for (int f = 0; f < nf; ++f)
        if (S[f])
        {
          centroid += pm.faceAreas[f] * pm.faceCentroids[f];
          total += pm.faceAreas[f];
        }
      if (total > 0)
        centroid /= total;
      meaningful = meaningful && !this->IsAncestorPlane(plane, pathFolds, centroid, eps);
    }
    if (!meaningful)
      return this->MakeLeaf(index, w, LeafReason::NoSymmetry), index;

    std::vector<char> rest(nf, 0);
    for (int f = 0; f < nf; ++f)
      rest[f] = !S[f];
    std::vector<int> labels;
    const int n = LabelConnectedRegions(pm, rest, labels);
    if (n == 0)
    {
      this->Fold(index, std::move(w), plane, depth, eps, folds, pathFolds);
      return index;
    }

    node.kind = FoldingNodeKind::Segmentation;
    // Tear vertices: used by faces of two different children (S is child 0).
    {
      std::vector<int> firstChild(w.points.size(), -1);
      std::vector<char> tear(w.points.size(), 0);
      for (int f = 0; f < nf; ++f)
      {
        const int child = S[f] ? 0 : 1 + labels[f];
        for (int v : w.triangles[f])
        {
          if (firstChild[v] < 0)
            firstChild[v] = child;
          else if (firstChild[v] != child)
            tear[v] = 1;
        }
      }
      for (int v = 0; v < w.NumberOfPoints(); ++v)
        if (tear[v])
          w.tear[v] |= uint64_t(1) << depth;
    }
    WorkMesh ws = Extract(w, S);
    std::vector<WorkMesh> regions(n);
    {
      std::vector<std::vector<int>> facesOf(n);
      for (int f = 0; f < nf; ++f)
        if (labels[f] >= 0)
          facesOf[labels[f]].push_back(f);
      for (int r = 0; r < n; ++r)
        regions[r] = ExtractFaces(w, facesOf[r]);
    }
    // fold(S): a folding node one level down, then the remaining components.
    {
      const int foldIndex = this->NewNode(index, depth + 1, eps, folds, ws);
      this->Tree.nodes[foldIndex].symmetricAreaFraction = 1.0;
      this->Fold(foldIndex, std::move(ws), plane, depth + 1, eps, folds, pathFolds);
    }
    for (int r = 0; r < n; ++r)
      this->Build(std::move(regions[r]), index, depth + 1, eps, folds, pathFolds);
    return index;
  }

  /// Nearest of `points` (indices into w.points, bucketed in `cells`) to x within `radius`.
  struct Buckets
  {
    double cell = 1.0;
    std::map<std::array<long long, 3>, std::vector<int>> cells;
    std::array<long long, 3> Key(const Vec3& x) const
    {
      return { static_cast<long long>(std::floor(x.x() / cell)),
        static_cast<long long>(std::floor(x.y() / cell)),
        static_cast<long long>(std::floor(x.z() / cell)) };
    }
    void Add(const Vec3& x, int id) { cells[Key(x)].push_back(id); }
    int Nearest(const std::vector<Vec3>& points, const Vec3& x, double radius) const
    {
      const auto c = Key(x);
      int best = -1;
      double bestDistance = radius;
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz)
          {
            auto it = cells.find({ c[0] + dx, c[1] + dy, c[2] + dz });
            if (it == cells.end())
              continue;
            for (int v : it->second)
            {
              const double d = (points[v] - x).norm();
              if (d <= bestDistance && (best < 0 || d < bestDistance || v < best))
              {
                bestDistance = d;
                best = v;
              }
            }
          }
      return best;
    }
  };

  /**
   * Tear vertices that the fold at `depth` removes (not used by a kept face) are recorded on
   * kept vertices of the region's boundary (see MirroredFlag): each removed tear vertex t on
   * the nearest one to reflect(t), and each kept boundary vertex v whose mirror image lies
   * within eps of a removed tear vertex gets that vertex's flags. Both directions, because
   * with approximately symmetric tessellations the two sides of the seam need not have the
   * same number of vertices; the zipper of the unfolder then closes the seam.
   */
  void TransferDiscardedTears(WorkMesh& w,
    const std::vector<char>& used,
    const Plane& plane,
    int depth,
    double eps) const
  {
    const uint64_t bit = uint64_t(1) << depth;
    std::vector<int> lost;
    for (int v = 0; v < w.NumberOfPoints(); ++v)
      if (!used[v] && (w.tear[v] != 0 || !w.mirrorFlags[v].empty()))
        lost.push_back(v);
    if (lost.empty())
      return;
    // Boundary vertices of the region (all its faces, before the fold).
    std::map<std::pair<int, int>, int> edges;
    for (const Triangle& t : w.triangles)
      for (int k = 0; k < 3; ++k)
        ++edges[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }];
    std::vector<char> boundary(w.points.size(), 0);
    for (const auto& e : edges)
      if (e.second == 1)
        boundary[e.first.first] = boundary[e.first.second] = 1;
    Buckets kept, removed;
    kept.cell = removed.cell = std::max(eps, 1e-12 * this->Tree.diagonal);
    for (int v = 0; v < w.NumberOfPoints(); ++v)
      if (used[v] && boundary[v])
        kept.Add(w.points[v], v);
    for (int t : lost)
      removed.Add(w.points[t], t);
    auto transfer = [&](int t, int v)
    {
      auto& into = w.mirrorFlags[v];
      for (int level = 0; level < depth; ++level)
        if (w.tear[t] & (uint64_t(1) << level))
          into.push_back({ 2 * level, bit });
      for (const auto& e : w.mirrorFlags[t])
        if (e.first % 2 == 0) // plane flags are recomputed by FlagMirroredFoldLines
          into.push_back({ e.first, e.second | bit });
    };
    std::vector<std::pair<int, int>> pairs; // (kept, removed)
    for (int t : lost)
    {
      const int v = kept.Nearest(w.points, plane.Reflect(w.points[t]), eps);
      if (v >= 0)
        pairs.push_back({ v, t });
    }
    for (int v = 0; v < w.NumberOfPoints(); ++v)
      if (used[v] && boundary[v])
      {
        const int t = removed.Nearest(w.points, plane.Reflect(w.points[v]), eps);
        if (t >= 0)
          pairs.push_back({ v, t });
      }
    for (const auto& pr : pairs)
      transfer(pr.second, pr.first);
    for (const auto& pr : pairs)
    {
      auto& into = w.mirrorFlags[pr.first];
      std::sort(into.begin(), into.end());
      into.erase(std::unique(into.begin(), into.end()), into.end());
    }
  }

  /**
   * Fold lines of ancestor folds in the mirror copies: a boundary vertex v of the kept half
   * whose copy R_M(R_f(v)) (reflected by this fold f, then by the ancestor folds M between
   * an ancestor fold a and f, deepest first) lies within a's snap distance of a's plane gets
   * the plane flag (a, M + f). Only boundary vertices can lie on a fold line; M ranges over
   * all subsets (at most 2^(maximumFolds - 1)). Copies without this fold were flagged by
   * earlier folds. Plane flags of removed vertices are not transferred: this computes the
   * flags from the geometry the unfolder will produce.
   */
  void FlagMirroredFoldLines(WorkMesh& w,
    const std::vector<char>& keep,
    const Plane& plane,
    int depth,
    uint64_t pathFolds) const
  {
    std::vector<int> ancestors; // increasing depth
    for (int d = 0; d < depth; ++d)
      if (pathFolds & (uint64_t(1) << d))
        ancestors.push_back(d);
    if (ancestors.empty())
      return;
    std::map<std::pair<int, int>, int> edges;
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      if (keep[f])
        for (int k = 0; k < 3; ++k)
        {
          const int a = w.triangles[f][k], b = w.triangles[f][(k + 1) % 3];
          ++edges[{ std::min(a, b), std::max(a, b) }];
        }
    std::vector<char> boundary(w.points.size(), 0);
    for (const auto& e : edges)
      if (e.second == 1)
        boundary[e.first.first] = boundary[e.first.second] = 1;
    const uint64_t bit = uint64_t(1) << depth;
    for (int v = 0; v < w.NumberOfPoints(); ++v)
    {
      if (!boundary[v])
        continue;
      const Vec3 x = plane.Reflect(w.points[v]);
      for (size_t i = 0; i < ancestors.size(); ++i)
      {
        const int a = ancestors[i];
        const Plane& pa = this->PlaneAtDepth[a];
        const double tolerance = std::max(
          this->Options.planeSnapFraction * this->EpsilonAtDepth[a], 1e-12 * this->Tree.diagonal);
        // Folds between a and this fold, deepest first.
        std::vector<int> between(ancestors.begin() + i + 1, ancestors.end());
        std::reverse(between.begin(), between.end());
        const size_t combinations = size_t(1) << between.size();
        for (size_t m = 0; m < combinations; ++m)
        {
          Vec3 y = x;
          uint64_t mask = bit;
          for (size_t k = 0; k < between.size(); ++k)
            if (m & (size_t(1) << k))
            {
              y = this->PlaneAtDepth[between[k]].Reflect(y);
              mask |= uint64_t(1) << between[k];
            }
          if (std::abs(pa.SignedDistance(y)) <= tolerance)
            w.mirrorFlags[v].push_back({ 2 * a + 1, mask });
        }
      }
      std::sort(w.mirrorFlags[v].begin(), w.mirrorFlags[v].end());
      w.mirrorFlags[v].erase(
        std::unique(w.mirrorFlags[v].begin(), w.mirrorFlags[v].end()), w.mirrorFlags[v].end());
    }
  }

  /// Turns node `index` (region w) into a folding node and builds the kept half below it.
  void
  Fold(int index, WorkMesh w, Plane plane, int depth, double eps, int folds, uint64_t pathFolds)
  {
    const FoldingTreeOptions& O = this->Options;
    const int nf = w.NumberOfFaces();
    int positive = 0, negative = 0;
    for (const Triangle& t : w.triangles)
    {
      const Vec3 c = (w.points[t[0]] + w.points[t[1]] + w.points[t[2]]) / 3.0;
      const double s = plane.SignedDistance(c);
      positive += s > 0;
      negative += s < 0;
    }
    const bool keepPositive =
      O.keepSide == KeepSide::MoreFaces ? positive >= negative : positive <= negative;
    if (!keepPositive)
      plane.normal = -plane.normal;

    const double snap = std::max(O.planeSnapFraction * eps, 1e-12 * this->Tree.diagonal);
    std::vector<int> side(w.points.size());
    for (int v = 0; v < w.NumberOfPoints(); ++v)
    {
      const double s = plane.SignedDistance(w.points[v]);
      side[v] = s > snap ? 1 : (s < -snap ? -1 : 0);
    }
    std::vector<char> keep(nf, 0);
    std::vector<int> discarded;
    for (int f = 0; f < nf; ++f)
    {
      const Triangle& t = w.triangles[f];
      const int hi = std::max({ side[t[0]], side[t[1]], side[t[2]] });
      const int lo = std::min({ side[t[0]], side[t[1]], side[t[2]] });
      keep[f] = hi == 1 || (hi == 0 && lo == 0);
      if (!keep[f])
        discarded.push_back(w.faceOrig[f]);
    }
    std::vector<char> used(w.points.size(), 0);
    for (int f = 0; f < nf; ++f)
      if (keep[f])
        for (int v : w.triangles[f])
          used[v] = 1;
    // The error this fold adds to unfold(): the largest distance of a mirrored vertex of the
    // region to the region (both halves: either may be the one reproduced), before projection.
    TriangleMesh region;
    region.points = w.points;
    region.triangles = w.triangles;
    const SurfaceDistanceQuery toRegion(region);
    // Per kept point: what the copies made by this fold add there. A kept point's mirror
    // copy must lie near the input (error: its distance to the input); a discarded point must
    // be reproduced by the mirror copy of the kept half (error: the distance of its mirror
    // image to the region), charged to the kept point nearest to that image. Either lands
    // where the budget of the partner point applies too.
    std::vector<double> charge(w.points.size(), 0.0),
      limit(w.points.size(), std::numeric_limits<double>::infinity());
    double mirrorError = 0.0;
    if (O.errorBudget)
    {
      std::vector<Vec3> mirrored(w.points.size());
      for (int v = 0; v < w.NumberOfPoints(); ++v)
        mirrored[v] = plane.Reflect(w.points[v]);
      const std::vector<double> toS = toRegion.Distances(mirrored);
      const std::vector<double> toM = this->ToInput->Distances(mirrored);
      Buckets all, kept;
      all.cell = kept.cell = std::max(eps, 1e-12 * this->Tree.diagonal);
      double least = std::numeric_limits<double>::infinity();
      for (int v = 0; v < w.NumberOfPoints(); ++v)
      {
        all.Add(w.points[v], v);
        if (used[v])
          kept.Add(w.points[v], v);
        least = std::min(least, w.budget[v]);
      }
      for (int v = 0; v < w.NumberOfPoints(); ++v)
      {
        const double e = used[v] ? toM[v] : toS[v];
        mirrorError = std::max(mirrorError, e);
        const int k = used[v] ? v : kept.Nearest(w.points, mirrored[v], eps);
        if (k < 0)
          continue; // no kept point there: its copy reproduces nothing of v
        const int p = all.Nearest(w.points, mirrored[v], eps);
        charge[k] = std::max(charge[k], e);
        limit[k] = std::min({ limit[k], w.budget[v], p >= 0 ? w.budget[p] : least });
      }
      for (int v = 0; v < w.NumberOfPoints(); ++v)
        limit[v] = std::min(limit[v], w.budget[v]);
    }
    this->TransferDiscardedTears(w, used, plane, depth, eps);
    int projected = 0;
    const uint64_t bit = uint64_t(1) << depth;
    // Sliding (see FoldingTreeOptions::slideOntoPlane): per discarded-side vertex, the point
    // where one of its edges to a kept-side vertex of a kept face crosses the plane, nearest
    // to its orthogonal projection. That point lies on the input surface.
    std::vector<Vec3> slide(w.points.size());
    std::vector<char> slides(w.points.size(), 0);
    if (O.slideOntoPlane || O.errorBudget)
    {
      std::vector<double> slideMove(w.points.size(), std::numeric_limits<double>::infinity());
      for (int f = 0; f < nf; ++f)
        if (keep[f])
          for (int k = 0; k < 3; ++k)
            for (int j = 1; j <= 2; ++j)
            {
              const int v = w.triangles[f][k], a = w.triangles[f][(k + j) % 3];
              if (side[v] >= 0 || side[a] <= 0)
                continue;
              const double sv = plane.SignedDistance(w.points[v]);
              const double sa = plane.SignedDistance(w.points[a]);
              const Vec3 q = w.points[v] + (sv / (sv - sa)) * (w.points[a] - w.points[v]);
              const double move = (q - plane.Project(w.points[v])).norm();
              if (move < slideMove[v])
              {
                slideMove[v] = move;
                slide[v] = plane.Project(q); // exactly on the plane
                slides[v] = 1;
              }
            }
    }
    for (int v = 0; v < w.NumberOfPoints(); ++v)
    {
      if (!used[v] || side[v] > 0)
        continue;
      bool onAncestorPlane = false;
      for (int d = 0; d < depth; ++d)
        onAncestorPlane = onAncestorPlane ||
          ((w.onPlane[v] & (uint64_t(1) << d)) && (pathFolds & (uint64_t(1) << d)));
      // Projecting is the default; sliding when asked for, or when the projected point
      // would be farther from the region than the error budget left there.
      bool slideIt = slides[v] && !onAncestorPlane && side[v] < 0;
      if (slideIt && !O.slideOntoPlane)
        slideIt = charge[v] + toRegion.Distance(plane.Project(w.points[v])) > limit[v];
      if (slideIt)
      {
        w.points[v] = slide[v];
        w.onPlane[v] |= bit;
        w.projected[v] = 1;
        ++projected;
        continue;
      }
      std::vector<Plane> constraints{ plane };
      for (int d = 0; d < depth; ++d)
        if ((w.onPlane[v] & (uint64_t(1) << d)) && (pathFolds & (uint64_t(1) << d)))
          constraints.push_back(this->PlaneAtDepth[d]);
      const double tolerance = 1e-9 * this->Tree.diagonal;
      if (!ProjectOntoPlanes(w.points[v], constraints, tolerance))
        for (int d = 0; d < depth; ++d)
          if ((w.onPlane[v] & (uint64_t(1) << d)) &&
            std::abs(this->PlaneAtDepth[d].SignedDistance(w.points[v])) > tolerance)
            w.onPlane[v] &= ~(uint64_t(1) << d);
      w.onPlane[v] |= bit;
      if (side[v] < 0)
      {
        w.projected[v] = 1;
        ++projected;
      }
    }

    // ... plus the largest distance of a point projected (or snapped) onto the plane(s) to
    // the region as it was.
    double projectionError = 0.0;
    if (O.errorBudget)
    {
      std::vector<Vec3> moved;
      std::vector<int> movedPoint, movedFace;
      for (int v = 0; v < w.NumberOfPoints(); ++v)
        if (used[v] && side[v] <= 0)
        {
          moved.push_back(w.points[v]);
          movedPoint.push_back(v);
        }
      // Faces changed by a move: their centroids too (a slid vertex is on the surface, its
      // faces need not be).
      for (int f = 0; f < nf; ++f)
      {
        const Triangle& t = w.triangles[f];
        if (keep[f] && (side[t[0]] < 0 || side[t[1]] < 0 || side[t[2]] < 0))
        {
          moved.push_back((w.points[t[0]] + w.points[t[1]] + w.points[t[2]]) / 3.0);
          movedFace.push_back(f);
        }
      }
      const std::vector<double> d = toRegion.Distances(moved);
      std::vector<double> displacement(w.points.size(), 0.0);
      for (size_t k = 0; k < movedPoint.size(); ++k)
        displacement[movedPoint[k]] = std::max(displacement[movedPoint[k]], d[k]);
      for (size_t k = 0; k < movedFace.size(); ++k)
        for (int v : w.triangles[movedFace[k]])
          displacement[v] = std::max(displacement[v], d[movedPoint.size() + k]);
      for (int v = 0; v < w.NumberOfPoints(); ++v)
      {
        projectionError = std::max(projectionError, displacement[v]);
        w.budget[v] = std::max(0.0, limit[v] - charge[v] - displacement[v]);
      }
    }
    double childBudget = eps;
    for (int v = 0; v < w.NumberOfPoints(); ++v)
      if (used[v])
        childBudget = std::min(childBudget, w.budget[v]);
    if (std::getenv("FOLDINGMESHES_DEBUG"))
      std::printf("[fold] node %d depth %d eps %.3g: mirror error %.3g, projection "
                  "error %.3g, least child budget %.3g\n",
        index,
        depth,
        eps,
        mirrorError,
        projectionError,
        childBudget);

    this->FlagMirroredFoldLines(w, keep, plane, depth, pathFolds);

    FoldingNode& node = this->Tree.nodes[index];
    node.kind = FoldingNodeKind::Folding;
    node.plane = plane;
    node.discardedFaces = static_cast<int>(discarded.size());
    node.projectedPoints = projected;
    std::sort(discarded.begin(), discarded.end());
    node.discardedOriginalFaces = std::move(discarded);
    this->DoneFaces += node.discardedFaces;
    this->Report(this->Fraction(this->DoneFaces));

    this->PlaneAtDepth[depth] = plane;
    this->EpsilonAtDepth[depth] = eps;
    WorkMesh half = Extract(w, keep);
    this->Build(std::move(half), index, depth + 1, 0.5 * eps, folds + 1, pathFolds | bit);
  }

  const FoldingTreeOptions& Options;
  const std::vector<Vec3>& InputNormals;
  FoldingTree& Tree;
  std::unique_ptr<SurfaceDistanceQuery> ToInput; ///< distances to the input surface
  std::vector<Plane> PlaneAtDepth;
  std::vector<double> EpsilonAtDepth;
  int MaximumDepth = 48;
  double DoneFaces = 0.0;
  double LastProgress = 0.0;
};
}

bool BuildFoldingTree(const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals,
  const FoldingTreeOptions& options,
  FoldingTree& tree,
  std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  tree = FoldingTree();
  error.clear();
  if (!(options.epsilon > 0.0) || !std::isfinite(options.epsilon))
  {
    error = "the root epsilon must be a positive, finite length";
    return false;
  }
  if (!(options.minimumAreaFraction >= 0.0 && options.minimumAreaFraction <= 1.0))
  {
    error = "minimumAreaFraction must be within [0, 1]";
    return false;
  }
  if (!(options.planeSnapFraction >= 0.0 && options.planeSnapFraction < 1.0))
  {
    error = "planeSnapFraction must be within [0, 1)";
    return false;
  }
  if (input.points.empty() || input.triangles.empty())
  {
    error = "the input mesh is empty";
    return false;
  }
  const int np = static_cast<int>(input.points.size());
  if (!inputNormals.empty() && static_cast<int>(inputNormals.size()) != np)
  {
    error = "inputNormals must be empty or have one normal per input point";
    return false;
  }
  for (const Vec3& p : input.points)
    if (!p.allFinite())
    {
      error = "the input has non-finite point coordinates";
      return false;
    }
  for (const Triangle& t : input.triangles)
    for (int v : t)
      if (v < 0 || v >= np)
      {
        error = "a triangle refers to a point index out of range";
        return false;
      }

  WorkMesh root;
  root.points = input.points;
  root.triangles = input.triangles;
  root.pointOrig.resize(np);
  std::iota(root.pointOrig.begin(), root.pointOrig.end(), 0);
  root.faceOrig.resize(input.triangles.size());
  std::iota(root.faceOrig.begin(), root.faceOrig.end(), 0);
  root.tear.assign(np, 0);
  root.onPlane.assign(np, 0);
  root.projected.assign(np, 0);
  root.mirrorFlags.assign(np, {});
  root.budget.assign(np, options.epsilon);

  tree.numberOfOriginalFaces = static_cast<int>(input.triangles.size());
  tree.numberOfOriginalPoints = np;
  tree.rootEpsilon = options.epsilon;
  {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = -lo;
    for (const Triangle& t : input.triangles)
      for (int v : t)
      {
        lo = lo.cwiseMin(input.points[v]);
        hi = hi.cwiseMax(input.points[v]);
      }
    tree.diagonal = (hi - lo).norm();
    double area = 0.0;
    for (const Triangle& t : input.triangles)
      area += TriangleArea(root, t);
    tree.originalArea = area;
  }
  if (!(tree.originalArea > 0.0))
  {
    error = "the input mesh has zero area";
    tree = FoldingTree();
    return false;
  }

  Builder builder(options, inputNormals, tree);
  builder.Run(std::move(root));
  tree.aborted = builder.Aborted;
  tree.buildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}
}
