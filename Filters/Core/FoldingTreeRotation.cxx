// Rotation nodes of the builder (FoldingTreeOptions::rotationNodes, issue 22): the order, the
// sector cut, the seams and the error the k - 1 turned copies add.
//
// The rule, for a region with no fold and no rotation above it:
// 1. DetectRotationalSymmetry gives an axis and an order (or "continuous": a surface of
//    revolution, then every order up to maximumRotationOrder is a candidate, largest first;
//    a discrete order k gives k and its divisors, largest first). Orders 2 are tried only
//    when the mirror plane's S is not the whole region (a global mirror fold is as good).
// 2. The sector of order k: the faces whose centroid's angle about the axis lies in
//    [phi0, phi0 + 360/k) (whole faces only), phi0 the angle (modulo 360/k) that most
//    vertices share - a column of vertices, where a tessellation with k-fold symmetry has its
//    own seams. k times its area must be the region's within a quarter of a sector's (else
//    the copies would overlap or leave gaps).
// 3. Its seams: the edges its faces use once that other faces of the region use too; a seam
//    vertex on the axis (within 1e-6 of the diagonal) is moved onto it. When every seam vertex
//    on the phi0 side pairs one-to-one (mutual nearest, within the seam snap of epsilon / 4)
//    with a seam vertex on the other side turned back by 360/k, each pair moves to agree
//    exactly (the mean of the one and the other turned back, and that turned): the unfolder's
//    copies meet there; when every seam vertex lies within the snap of its bounding half-plane,
//    the pairs are moved onto the half-planes too, so a mirror fold of the sector through its
//    bisector (a dihedral part) maps one seam onto the other. Seams that do not pair are turned
//    about the axis onto their half-planes (a surface of revolution keeps its points; step 4
//    measures where they land) and joined by the unfolder's zipper, like segmentation seams.
//    No moved face may flip.
// 3b. When the whole faces cover the region once but their seams fail step 3 (triangles that
//    span much of a sector: the bearing's CAD fans, rings spaced unevenly), the faces are cut
//    along the two half-planes (SplitAtHalfPlanes; the pieces keep their input face; a face
//    the axis passes through is first cut at the axis, SplitAtAxis) and step
//    3 is tried on the cut region, whose seams lie on the half-planes, as long as k such
//    sectors hold at most three times the region's faces (the pieces multiply with k); so are
//    whole faces that pass step 3 but miss the bound in step 4 (a polygon across the axis in
//    large faces). The first order with a sector is the candidate (surfaces of revolution:
//    the largest k whose sector keeps the bound).
// 3c. A second pass cuts the orders whose whole faces do not cover the region once (rings
//    spaced unevenly, each its own count: the queen). Its first order that passes replaces the
//    first pass's when its sector holds fewer faces (the first pass found none: always), and
//    the other is built too where the caller compares subtrees (Builder::Build); on a part of
//    the region (InvariantRegion), an order's whole faces are tried first, then its cut ones.
// 4. The error: each kept point turned by j * 360/k (j = 0 .. k - 1; j = 0 measures where the
//    seams moved it) and each removed point turned back into the sector must lie within
//    epsilon of the region (turned kept points measured against the region, removed points
//    against the sector), and so must the centroids and edge midpoints of the kept faces whose
//    seam vertices moved and (turned back, against the sector) those of the removed faces -
//    a removed face can span surface no copy reproduces although its corners all have
//    partners; each kept point is charged the largest distance of its own turns and
//    faces, and each corner of the sector face nearest a removed point (or removed face's
//    sample) turned back that distance, from its error budget (which must cover it). A turn is an
//    isometry: the k copies do not compound like nested folds, so the subtree gets epsilon / 2,
//    like a fold's half (and what its budgets hold), for any k; the builder's verification
//    (verifyBound) proves the whole. Up to MaximumCheckedOrders orders get this check; each stops
//    at the first turn beyond the limit.
// Seam vertices carry the tear bit of the rotation node's depth; the unfolder stitches the
// copies' seams like segmentation seams (Unfolder::Turn).
#include "FoldingTreeBuilderInternal.h"

#include "CandidatePlanes.h"
#include "FoldingTreeRotationSector.h"

#include <algorithm>
#include <chrono>

namespace foldingmeshes
{
namespace treebuilder
{
using namespace sector;
namespace
{
/// The share of the node's epsilon the turned copies may add (the rest goes to the subtree).
constexpr double RotationShareOfEpsilon = 1.0;
/// Seam vertices move at most this share of the node's epsilon to make the seams meet.
constexpr double SeamSnapOfEpsilon = 0.25;
/// Orders whose seams pair up that get the error check before the node gives up (each check
/// stops at its first turn beyond the limit).
constexpr int MaximumCheckedOrders = 16;
/// Orders whose invariant part of the detector's region gets a sector planned (the first of
/// those whose k sectors covered the whole region once, else the detector's, largest first).
constexpr int MaximumRegionOrders = 4;

/// Orders to try, largest first (see the file comment, step 1).
std::vector<int> CandidateOrders(const RotationResult& r, int maximumOrder, bool allowTwo)
{
  std::vector<int> orders;
  const int top = r.continuous ? maximumOrder : r.order;
  for (int k = top; k >= (allowTwo ? 2 : 3); --k)
    if (r.continuous || top % k == 0)
      orders.push_back(k);
  return orders;
}

}

int Builder::SubtreeStoredFaces(int index) const
{
  int faces = 0;
  for (int i = index; i < this->Tree.NumberOfNodes(); ++i)
    if (this->Tree.nodes[i].kind == FoldingNodeKind::Leaf)
      faces += this->Tree.nodes[i].mesh.NumberOfFaces();
  return faces;
}

bool Builder::HasRotationAbove(int index) const
{
  for (int a = this->Tree.nodes[index].parent; a >= 0; a = this->Tree.nodes[a].parent)
    if (this->Tree.nodes[a].kind == FoldingNodeKind::Rotation)
      return true;
  return false;
}

/// The sector of the first of `orders` that passes (CutSector, ChargeTurns) on `region`;
/// `covered` (optional) gets the orders whose k sectors covered the region's area once.
bool Builder::PlanSector(const RotationResult& r,
  const WorkMesh& region,
  const std::vector<int>& orders,
  double eps,
  RotationPlan& plan,
  std::vector<int>* covered,
  bool cutUncovered) const
{
  const FoldingTreeOptions& O = this->Options;
  const AxisFrame frame(r.axis);
  const double snap = std::max(SeamSnapOfEpsilon * eps, 1e-12 * this->Tree.diagonal);
  const double limit = RotationShareOfEpsilon * eps;
  const EdgeTable edges = EdgeFaces(region.triangles);
  TriangleMesh surface;
  surface.points = region.points;
  surface.triangles = region.triangles;
  const SurfaceDistanceQuery toRegion(surface);
  SectorCut cut;
  int checked = 0;
  const double offAxis = 1e-9 * this->Tree.diagonal;
  WorkMesh split;
  // The region's faces cut along order k's half-planes from the sector's start (step 3b): the
  // sector of `split` in `cut`; why there is none (nullptr: there is).
  auto cutAlongHalfPlanes = [&](int k)
  {
    const double start = cut.start;
    split = SplitAtHalfPlanes(frame, region, start, TwoPi / k, offAxis);
    return CutSector(frame,
      split,
      EdgeFaces(split.triangles),
      k,
      snap,
      offAxis,
      cut,
      start,
      region.NumberOfFaces());
  };
  for (int k : orders)
  {
    const char* why = CutSector(frame, region, edges, k, snap, offAxis, cut);
    // Whole faces cover the region once (a sector that would hold too many faces is checked
    // first: whether it covers once is not known, and cut along its half-planes it only holds
    // more).
    const bool coversOnce = why != NotCoveredOnce && why != NoSector && why != TooManyPieces;
    if (covered && coversOnce)
      covered->push_back(k);
    if (cutUncovered && why != NotCoveredOnce)
      continue; // the orders of the first pass
    // Whole faces cover the region once but their seams do not meet (or, `cutUncovered`, they
    // do not cover it once): cut the faces along the half-planes (step 3b).
    bool cutFaces = false;
    if (why && (coversOnce || cutUncovered))
    {
      const char* whySplit = cutAlongHalfPlanes(k);
      if (O.trace)
        O.trace(FormatTrace("[rotation]   order %d: %s (farthest seam vertex %.3g from its "
                            "half-plane, snap %.3g); cut along the half-planes: %s",
          k,
          why,
          cut.halfPlaneMove,
          snap,
          whySplit ? whySplit : "a sector"));
      why = whySplit;
      cutFaces = !whySplit;
    }
    if (why)
    {
      if (O.trace)
        O.trace(FormatTrace("[rotation]   order %d: %s (farthest seam vertex %.3g from its "
                            "half-plane, snap %.3g)",
          k,
          why,
          cut.halfPlaneMove,
          snap));
      continue;
    }
    double worst = 0.0;
    int stage = 0;
    bool within = ChargeTurns(
      frame, cutFaces ? split : region, toRegion, cut, limit, plan.charge, worst, &stage);
    if (O.trace)
      O.trace(FormatTrace("[rotation]   order %d: error %.3g of the limit %.3g%s",
        k,
        worst,
        limit,
        within ? "" : " (or a budget): rejected"));
    if (!within && !cutFaces && stage >= 2) // not a wrong order (its kept points' turns pass)
    {
      // Whole faces whose copies miss the bound (faces that span much of a sector, a polygon
      // across the axis in large triangles): the faces cut along the half-planes (step 3b)
      // may keep it.
      const char* whySplit = cutAlongHalfPlanes(k);
      if (!whySplit)
      {
        cutFaces = true;
        within = ChargeTurns(frame, split, toRegion, cut, limit, plan.charge, worst);
      }
      if (O.trace && whySplit)
        O.trace(FormatTrace("[rotation]   order %d cut along the half-planes: %s", k, whySplit));
      else if (O.trace)
        O.trace(FormatTrace("[rotation]   order %d cut along the half-planes: error %.3g of the "
                            "limit %.3g%s",
          k,
          worst,
          limit,
          within ? "" : " (or a budget): rejected"));
    }
    if (within)
    {
      plan.axis = r.axis;
      plan.order = k;
      plan.cutFaces = cutFaces;
      plan.start = cut.start;
      plan.keep = std::move(cut.keep);
      plan.points = std::move(cut.points);
      plan.seam = std::move(cut.seam);
      plan.secondPass = cutUncovered;
      return true;
    }
    if (++checked == MaximumCheckedOrders)
      break;
  }
  return false;
}

bool Builder::PlanRotation(int index,
  const WorkMesh& w,
  const PreparedMesh& pm,
  const FaceTree& regionFaces,
  const SymmetryResult& planes,
  bool wholeMirror,
  int depth,
  double eps,
  RotationPlan& plan,
  RotationPlan* second,
  RotationPlan* cutSecond) const
{
  const FoldingTreeOptions& O = this->Options;
  plan = RotationPlan();
  for (RotationPlan* other : { second, cutSecond })
    if (other)
      *other = RotationPlan();
  if (!O.rotationNodes || this->HasRotationAbove(index) || depth + 3 > this->MaximumDepth)
    return false;
  const auto started = std::chrono::steady_clock::now();
  RotationOptions ro;
  ro.epsilon = eps;
  ro.maximumOrder = O.maximumRotationOrder;
  ro.minimumOrder = wholeMirror ? 3 : 2; // CandidateOrders: no order 2 where a fold covers all
  ro.compatibilityAngle = O.symmetry.compatibilityAngle;
  // (A floor of half the region's area was tried: the spider's search 2.1 -> 1.0 s, but the
  // fandisk's rotation of 11% of its area, which beats the fold there, was lost.)
  ro.minimumSymmetricAreaFraction = O.symmetry.minimumSymmetricAreaFraction;
  ro.mirrorPlanes = planes.finalists;
  ro.mirrorPlanes.push_back(planes.plane);
  ro.rankByArea = true;
  ro.progress = [this](double)
  {
    return !this->Aborted && this->Options.progress ? this->Options.progress(this->LastProgress)
                                                    : !this->Aborted;
  };
  const RotationResult r = DetectRotationalSymmetry(pm, ro, &regionFaces);
  if (r.aborted)
    return false; // the caller's next Report sees the abort
  const double detectSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  bool planned = false;
  if (r.found)
  {
    // The whole region, unless a face is pinned; else the rotational region (faces whose
    // vertices map within epsilon under both tested turns, degenerate faces following), which
    // becomes child 0 of a segmentation.
    bool pinned = false;
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      pinned = pinned || this->IsPinned(w, f);
    std::vector<int> covered;
    const std::vector<int> orders = CandidateOrders(r, O.maximumRotationOrder, !wholeMirror);
    planned = !pinned && this->PlanSector(r, w, orders, eps, plan, &covered);
    const int firstPassOrder = plan.order;
    // The first order whose whole faces do not cover the region once but whose faces cut along
    // the half-planes pass (step 3b, second pass: rings spaced unevenly, polygons across the
    // axis in large faces). Its sector replaces the first pass's when it holds fewer faces
    // (not on a tie: its copies are cut, the unfolded mesh finer), and the other is handed to
    // the caller to compare (`cutSecond`).
    RotationPlan cut;
    if (!pinned && this->SecondOrders && this->PlanSector(r, w, orders, eps, cut, nullptr, true))
    {
      auto faces = [](const RotationPlan& p)
      { return static_cast<int>(std::count(p.keep.begin(), p.keep.end(), 1)); };
      const bool replaces = !planned || faces(cut) < faces(plan);
      if (O.trace)
        O.trace(FormatTrace("[rotation]   order %d, cut along the half-planes, passes too "
                            "(%d faces in its sector%s): %s",
          cut.order,
          faces(cut),
          planned ? FormatTrace(", order %d's %d", plan.order, faces(plan)).c_str() : "",
          replaces ? "it is the sector" : "its sector is built too"));
      if (replaces)
        std::swap(plan, cut);
      if (cutSecond && cut.order > 0)
        *cutSecond = std::move(cut);
      planned = true;
    }
    if (firstPassOrder > 0 && second) // the next smaller order that passes, to compare
    {
      std::vector<int> smaller;
      for (int k : orders)
        if (k < firstPassOrder)
          smaller.push_back(k);
      if (!this->PlanSector(r, w, smaller, eps, *second, nullptr))
        *second = RotationPlan();
      else if (O.trace)
        O.trace(
          FormatTrace("[rotation]   order %d passes too: both sectors are built", second->order));
    }
    // Else: the part of the detector's region (faces whose vertices map within epsilon under
    // both tested turns, degenerate faces following, pinned faces left out) that the turns
    // of an order map onto itself, for the orders whose sectors covered the whole region
    // once (the tessellation's own orders); it becomes child 0 of a segmentation.
    std::vector<char> label = r.faceLabel;
    AddDegenerateFaces(w, pm, label);
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      label[f] = label[f] && !this->IsPinned(w, f);
    if (covered.empty()) // e.g. an asymmetric part beside: the detector's orders
      covered = CandidateOrders(r, O.maximumRotationOrder, !wholeMirror);
    const double minimumArea = O.symmetry.minimumSymmetricAreaFraction * Area(w);
    for (size_t i = 0; !planned && i < covered.size() && i < size_t(MaximumRegionOrders); ++i)
    {
      // The region that reaches up to its asymmetric surroundings first, then the strict one
      // that stays clear of them (InvariantRegion; a subset of the loose one), when it differs
      // and the loose one was the whole region or its sector failed (a smaller or empty loose
      // region leaves the strict one smaller still).
      std::vector<char> loose;
      for (const bool strict : { false, true })
      {
        std::vector<char> region = InvariantRegion(w, label, r.axis, covered[i], eps, strict);
        if (strict && region == loose)
          break;
        int faces = 0;
        double area = 0.0;
        for (int f = 0; f < w.NumberOfFaces(); ++f)
          if (region[f])
          {
            ++faces;
            area += TriangleArea(w, w.triangles[f]);
          }
        if (O.trace)
          O.trace(FormatTrace("[rotation]   order %d: the turns map %d faces (%.1f%% of the "
                              "area) onto the %s rotational region",
            covered[i],
            faces,
            100.0 * area / Area(w),
            strict ? "strict" : "loose"));
        const bool part = faces > 0 && faces < w.NumberOfFaces() && area >= minimumArea;
        // Whole faces first, then (their sector not covering the part once) cut ones.
        const WorkMesh sub = part ? Extract(w, region) : WorkMesh();
        if (part &&
          (this->PlanSector(r, sub, { covered[i] }, eps, plan, nullptr) ||
            (this->SecondOrders &&
              this->PlanSector(r, sub, { covered[i] }, eps, plan, nullptr, true))))
        {
          planned = true;
          plan.region = std::move(region);
          plan.regionFaces = faces;
          break;
        }
        if (!part && faces < w.NumberOfFaces())
          break;
        loose = std::move(region);
      }
    }
  }
  if (!planned)
    plan = RotationPlan();
  if (O.trace)
    O.trace(FormatTrace("[rotation] node %d depth %d eps %.3g (%d faces, %.3f s detection, "
                        "%.3f s planning): detected order %d%s, %s",
      index,
      depth,
      eps,
      w.NumberOfFaces(),
      detectSeconds,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() -
        detectSeconds,
      r.order,
      r.continuous ? " (continuous)" : "",
      !planned ? "no sector kept"
        : plan.region.empty()
        ? FormatTrace("a sector of order %d", plan.order).c_str()
        : FormatTrace("a sector of order %d of %d faces", plan.order, plan.regionFaces).c_str()));
  return planned;
}

FoldingTreeOptions RotationNodesDecided(const TriangleMesh& input,
  const FoldingTreeOptions& options)
{
  FoldingTreeOptions decided = options;
  decided.rotationNodesWhenAxial = false;
  decided.rotationNodes =
    options.rotationNodes || AxiallySymmetricSecondMoments(input, AxialMomentsGap);
  if (options.trace)
    options.trace(FormatTrace("[rotation] rotation nodes %s: the surface's second moments are "
                              "%saxially symmetric",
      decided.rotationNodes ? "on" : "off",
      decided.rotationNodes ? "" : "not "));
  return decided;
}

void Builder::Rotate(int index,
  WorkMesh w,
  const RotationPlan& plan,
  int depth,
  double eps,
  int folds)
{
  if (plan.cutFaces) // the same cut as PlanSector's (same points, faces and order)
    w = SplitAtHalfPlanes(
      AxisFrame(plan.axis), w, plan.start, TwoPi / plan.order, 1e-9 * this->Tree.diagonal);
  const uint64_t bit = uint64_t(1) << depth;
  std::vector<int> discarded;
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (!plan.keep[f])
      discarded.push_back(w.faceOrig[f]);
  w.points = plan.points;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    w.budget[v] = std::max(0.0, w.budget[v] - plan.charge[v]);
    if (plan.seam[v])
      w.tear[v] |= bit;
  }
  this->KeptSecondOrder = this->KeptSecondOrder || plan.secondPass;
  FoldingNode& node = this->Tree.nodes[index];
  node.kind = FoldingNodeKind::Rotation;
  node.axis = plan.axis;
  node.rotationOrder = plan.order;
  node.symmetricAreaFraction = 1.0;
  std::sort(discarded.begin(), discarded.end());
  node.discardedFaces = static_cast<int>(discarded.size());
  node.discardedOriginalFaces = std::move(discarded);
  this->DoneFaces += node.discardedFaces;
  this->Report(this->Fraction(this->DoneFaces));
  WorkMesh sector = Extract(w, plan.keep);
  this->Build(std::move(sector), index, depth + 1, 0.5 * eps, folds, 0);
}
}
}
