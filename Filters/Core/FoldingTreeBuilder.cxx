// BuildFoldingTree: the recursion, stop criteria and segmentation (Builder::Build, paper 4.2).
#include "FoldingTreeBuilder.h"
#include "FoldingTreeBuilderInternal.h"
#include "FoldingTreeVerification.h"

#include "CandidatePlanes.h"
#include "EdgeTable.h"
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "RegionGrowing.h"
#include "SurfaceDistance.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace foldingmeshes
{
namespace treebuilder
{
void Builder::Run(WorkMesh root)
{
  this->PlaneAtDepth.assign(MaximumFoldingTreeLevels, Plane());
  this->EpsilonAtDepth.assign(MaximumFoldingTreeLevels, 0.0);
  this->Build(std::move(root), -1, 0, this->Options.epsilon, 0, 0);
  this->Report(1.0);
}

bool Builder::Report(double value)
{
  if (this->Aborted)
    return false;
  value = std::min(1.0, std::max(value, this->LastProgress));
  this->LastProgress = value;
  if (this->Options.progress && !this->Options.progress(value))
    this->Aborted = true;
  return !this->Aborted;
}

double Builder::Fraction(double faces) const
{
  return this->Tree.numberOfOriginalFaces > 0 ? faces / this->Tree.numberOfOriginalFaces : 1.0;
}

int Builder::NewNode(int parent, int depth, double eps, int folds, const WorkMesh& w)
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

void Builder::MakeLeaf(int index, WorkMesh& w, LeafReason reason)
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
  m.inputBoundary.resize(m.points.size(), 0);
  for (size_t v = 0; v < m.points.size(); ++v)
  {
    const int id = m.originalPointIds[v];
    m.inputBoundary[v] =
      id >= 0 && id < static_cast<int>(this->InputBoundary.size()) && this->InputBoundary[id];
  }
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

bool Builder::Prepare(const WorkMesh& w, double eps, PreparedMesh& pm) const
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

bool Builder::IsAncestorPlane(const Plane& p, uint64_t pathFolds, const Vec3& at, double eps) const
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

void Builder::RecordInputEdges(const WorkMesh& w)
{
  // The input's own border (edges of one face), by input point id: recorded in the
  // leaves (FoldingLeafMesh::inputBoundary); does not change any folding decision.
  const EdgeTable uses = EdgeFaces(w.triangles);
  this->InputBoundary.assign(this->Tree.numberOfOriginalPoints, 0);
  this->Tree.inputBorderEdges.clear();
  for (const auto& e : uses)
    if (e.second.size() == 1)
    {
      const int a = w.pointOrig[e.first.first], b = w.pointOrig[e.first.second];
      this->Tree.inputBorderEdges.push_back({ std::min(a, b), std::max(a, b) });
      for (int v : { a, b })
        if (v >= 0 && v < this->Tree.numberOfOriginalPoints)
          this->InputBoundary[v] = 1;
    }
  std::sort(this->Tree.inputBorderEdges.begin(), this->Tree.inputBorderEdges.end());
  // And its non-manifold edges (more than two faces, duplicate faces included): the
  // unfolder's repair keeps their faces (FoldingTree::inputNonManifoldEdges).
  this->Tree.inputNonManifoldEdges.clear();
  for (const auto& e : uses)
    if (e.second.size() > 2)
    {
      const int a = w.pointOrig[e.first.first], b = w.pointOrig[e.first.second];
      this->Tree.inputNonManifoldEdges.push_back(
        { std::min(a, b), std::max(a, b), static_cast<int>(e.second.size()) });
    }
  std::sort(this->Tree.inputNonManifoldEdges.begin(), this->Tree.inputNonManifoldEdges.end());
}

void AddDegenerateFaces(const WorkMesh& w, const PreparedMesh& pm, std::vector<char>& S)
{
  std::vector<char> inS(w.points.size(), 0);
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (S[f])
      for (int v : w.triangles[f])
        inS[v] = 1;
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (pm.faceDegenerate[f] && inS[w.triangles[f][0]] && inS[w.triangles[f][1]] &&
      inS[w.triangles[f][2]])
      S[f] = 1;
}

// The recursion of the paper's section 4 (FoldingTreeBuilderInternal.h): leaf tests, detection,
// the choice of S, the fold, the segmentation of the rest - named helpers, in their order.
int Builder::Build(WorkMesh w, int parent, int depth, double eps, int folds, uint64_t pathFolds)
{
  const std::vector<int> dropped = WeldAndDropCollapsed(w);
  if (parent < 0)
  {
    this->Tree.numberOfDroppedFaces = static_cast<int>(dropped.size());
    this->RecordInputEdges(w);
  }
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
  // The detection an earlier build ran on this very region (DetectionCache: what Prepare read).
  DetectionCache::Slot* stored =
    this->Detections ? &this->Detections->For(w, !this->InputNormals.empty(), eps) : nullptr;
  w.triangles = pm.triangles; // oriented

  SymmetryOptions so = O.symmetry;
  so.epsilon = eps;
  so.sampledSearchAboveFaces = O.sampledSearchAboveFaces;
  so.refineSampledFinalists = false;
  so.distancesUpTo3Sigma = false;
  // ChooseSymmetricRegion tries the runner-up planes with whole parts on regions of several parts.
  so.scoreEveryFinalist = HasSeveralParts(pm);
  const double base = this->Fraction(this->DoneFaces);
  const double span = 0.5 * this->Fraction(nf);
  so.progress = [&](double p) { return this->Report(base + p * span); };
  so.trace = O.trace;
  const auto detectionStart = std::chrono::steady_clock::now();
  // One face tree of the region for detection, the trim's face bound and the runner-up
  // planes of ChooseSymmetricRegion; released before the recursion below.
  auto regionFaces = std::make_unique<FaceTree>(pm);
  const DetectionCache::Slot detected =
    DetectOrReuse(stored, pm, so, regionFaces.get(), O.trace, index);
  const SymmetryResult& result = *detected;
  FoldingNode& node = this->Tree.nodes[index];
  node.detectionRun = true;
  node.detectionStarts = result.startsTried;
  node.detectionSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - detectionStart).count();
  if (result.aborted || this->Aborted)
  {
    this->Aborted = true;
    return this->MakeLeaf(index, w, LeafReason::Aborted), index;
  }

  Plane plane;
  int provenSide = 0;
  std::vector<char> S =
    this->ChooseSymmetricRegion(w, pm, *regionFaces, result, eps, pathFolds, plane, provenSide);
  AddDegenerateFaces(w, pm, S);
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
    meaningful = meaningful && !this->IsAncestorPlane(plane, pathFolds, RegionCentroid(pm, S), eps);
  }
  // A rotation node instead (FoldingTreeRotation.cxx), where no fold lies above: of the whole
  // region, or of its rotational region (child 0 of a segmentation).
  RotationPlan rotation, second, cutSecond;
  const bool others = this->BuildingAlternatives == 0 && this->SecondOrders;
  const bool rotates = pathFolds == 0 &&
    this->PlanRotation(index,
      w,
      pm,
      *regionFaces,
      result,
      meaningful && sFaces == nf,
      depth,
      eps,
      rotation,
      others ? &second : nullptr,
      others ? &cutSecond : nullptr);
  regionFaces.reset();
  const SymmetricChild fold = [&](int at, WorkMesh region, int atDepth)
  { this->Fold(at, std::move(region), plane, atDepth, eps, folds, pathFolds, provenSide); };
  if (!rotates)
  {
    if (!meaningful)
      return this->MakeLeaf(index, w, LeafReason::NoSymmetry), index;
    this->Segment(index, std::move(w), pm, S, depth, eps, folds, pathFolds, fold);
    return index;
  }
  const SymmetricChild turn = [&](int at, WorkMesh region, int atDepth)
  { this->Rotate(at, std::move(region), rotation, atDepth, eps, folds); };
  const std::vector<char> turned =
    rotation.region.empty() ? std::vector<char>(nf, 1) : rotation.region;
  if (!meaningful && second.order == 0 && cutSecond.order == 0)
  {
    this->Segment(index, std::move(w), pm, turned, depth, eps, folds, pathFolds, turn);
    return index;
  }
  // The fold, the order planned, a second order, the other pass's order: the subtree that
  // stores fewest faces (ties: the fold's, the paper's; then in that order), each built in full,
  // the rotations' first; the nodes from `index` on are the subtree (preorder). Within one of
  // them (a remaining component with its own rotation), the faces each saves at its own node
  // decide instead, so that the builds do not multiply down a chain.
  if (this->BuildingAlternatives > 0)
  {
    const int regionFaces = rotation.region.empty() ? nf : rotation.regionFaces;
    if (regionFaces * (1.0 - 1.0 / rotation.order) > 0.5 * sFaces)
      this->Segment(index, std::move(w), pm, turned, depth, eps, folds, pathFolds, turn);
    else
      this->Segment(index, std::move(w), pm, S, depth, eps, folds, pathFolds, fold);
    return index;
  }
  ++this->BuildingAlternatives;
  const FoldingNode fresh = this->Tree.nodes[index];
  const double done = this->DoneFaces;
  const bool keptSecond = this->KeptSecondOrder;
  struct Built
  {
    int faces = std::numeric_limits<int>::max();
    std::vector<FoldingNode> nodes;
    double done = 0.0;
    bool keptSecond = false; ///< it holds a second order (Builder::KeptSecondOrder)
  };
  // Builds one alternative at `index` and sets it aside (the node back as it was).
  auto buildAside = [&](const std::vector<char>& region, const SymmetricChild& child)
  {
    this->Segment(index, w, pm, region, depth, eps, folds, pathFolds, child);
    Built b;
    b.faces = this->SubtreeStoredFaces(index);
    b.nodes.assign(this->Tree.nodes.begin() + index, this->Tree.nodes.end());
    b.done = this->DoneFaces;
    b.keptSecond = this->KeptSecondOrder;
    this->Tree.nodes.resize(index);
    this->Tree.nodes.push_back(fresh);
    this->DoneFaces = done;
    this->KeptSecondOrder = keptSecond;
    return b;
  };
  Built first = buildAside(turned, turn), other, cut, folded;
  for (const RotationPlan* p : { &second, &cutSecond })
    if (p->order > 0)
    {
      const SymmetricChild turnOther = [&](int at, WorkMesh region, int atDepth)
      { this->Rotate(at, std::move(region), *p, atDepth, eps, folds); };
      (p == &second ? other : cut) = buildAside(std::vector<char>(nf, 1), turnOther);
    }
  if (meaningful)
    folded = buildAside(S, fold);
  --this->BuildingAlternatives;
  Built* kept = &folded;
  for (Built* b : { &cut, &other, &first }) // on a tie the fold, then the first pass's orders
    if (b->faces <= kept->faces && (b->faces < kept->faces || kept != &folded))
      kept = b;
  if (O.trace)
    O.trace(FormatTrace("[rotation] node %d: order %d's subtree stores %d faces, order %d's %d, "
                        "the other pass's order %d's %d, the fold's %d: %s kept",
      index,
      rotation.order,
      first.faces,
      second.order,
      other.faces,
      cutSecond.order,
      cut.faces,
      folded.faces,
      kept == &folded    ? "the fold's"
        : kept == &first ? "the first"
                         : "another"));
  this->KeptSecondOrder = kept->keptSecond || kept == &other || kept == &cut;
  this->Tree.nodes.resize(index);
  this->Tree.nodes.insert(this->Tree.nodes.end(), kept->nodes.begin(), kept->nodes.end());
  this->DoneFaces = kept->done;
  return index;
}

void Builder::Segment(int index,
  WorkMesh w,
  const PreparedMesh& pm,
  const std::vector<char>& S,
  int depth,
  double eps,
  int folds,
  uint64_t pathFolds,
  const SymmetricChild& symmetric)
{
  const int nf = w.NumberOfFaces();
  std::vector<char> rest(nf, 0);
  for (int f = 0; f < nf; ++f)
    rest[f] = !S[f];
  std::vector<int> labels;
  const int n = LabelConnectedRegions(pm, rest, labels);
  if (n == 0)
  {
    symmetric(index, std::move(w), depth);
    return;
  }

  this->Tree.nodes[index].kind = FoldingNodeKind::Segmentation;
  MarkTears(w, S, labels, depth);
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
  // fold(S) (or its rotation): a folding (rotation) node one level down, then the remaining
  // components.
  {
    const int child = this->NewNode(index, depth + 1, eps, folds, ws);
    this->Tree.nodes[child].symmetricAreaFraction = 1.0;
    symmetric(child, std::move(ws), depth + 1);
  }
  for (int r = 0; r < n; ++r)
    this->Build(std::move(regions[r]), index, depth + 1, eps, folds, pathFolds);
}
}

using treebuilder::Builder;
using treebuilder::TriangleArea;
using treebuilder::WorkMesh;

namespace
{
/// Why BuildFoldingTree cannot build from these (empty: it can).
std::string CheckBuildInput(const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals,
  const FoldingTreeOptions& options)
{
  if (!(options.epsilon > 0.0) || !std::isfinite(options.epsilon))
    return "the root epsilon must be a positive, finite length";
  if (!(options.minimumAreaFraction >= 0.0 && options.minimumAreaFraction <= 1.0))
    return "minimumAreaFraction must be within [0, 1]";
  if (!(options.planeSnapFraction >= 0.0 && options.planeSnapFraction < 1.0))
    return "planeSnapFraction must be within [0, 1)";
  if ((options.rotationNodes || options.rotationNodesWhenAxial) &&
    (options.maximumRotationOrder < 2 || options.maximumRotationOrder > MaximumRotationNodeOrder))
    return "maximumRotationOrder must be within [2, 360]";
  if (input.points.empty() || input.triangles.empty())
    return "the input mesh is empty";
  const int np = static_cast<int>(input.points.size());
  if (!inputNormals.empty() && static_cast<int>(inputNormals.size()) != np)
    return "inputNormals must be empty or have one normal per input point";
  for (const Vec3& p : input.points)
    if (!p.allFinite())
      return "the input has non-finite point coordinates";
  for (const Triangle& t : input.triangles)
    for (int v : t)
      if (v < 0 || v >= np)
        return "a triangle refers to a point index out of range";
  return std::string();
}
}

bool BuildFoldingTree(const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals,
  const FoldingTreeOptions& options,
  FoldingTree& tree,
  std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  tree = FoldingTree();
  error = CheckBuildInput(input, inputNormals, options);
  if (!error.empty())
    return false;
  if (options.rotationNodesWhenAxial && !options.rotationNodes)
    return BuildFoldingTree(
      input, inputNormals, treebuilder::RotationNodesDecided(input, options), tree, error);
  const int np = static_cast<int>(input.points.size());

  // Distances to the input (the core's face tree), for every build and the verification.
  const SurfaceDistanceQuery toInput(input);
  // One build with the faces `pinned` kept out of every symmetric region.
  bool secondOrders = true, keptSecondOrder = false; // rotation nodes' second orders
  treebuilder::DetectionCache detections; // what the builds detected, for the later ones to reuse
  auto build = [&](const FoldingTreeOptions& o, const std::vector<char>& pinned) -> bool
  {
    tree = FoldingTree();
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
    root.budget.assign(np, o.epsilon);

    tree.numberOfOriginalFaces = static_cast<int>(input.triangles.size());
    tree.numberOfOriginalPoints = np;
    tree.rootEpsilon = o.epsilon;
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
      return false;
    Builder builder(o, inputNormals, tree, pinned, toInput);
    builder.SecondOrders = secondOrders;
    const bool reuse = options.reuseDetections && treebuilder::SameDetectionOptions(o, options);
    builder.Detections = reuse && options.verifyBound ? &detections : nullptr;
    builder.Run(std::move(root));
    tree.aborted = builder.Aborted;
    keptSecondOrder = builder.KeptSecondOrder;
    return true;
  };
  if (!build(options, {}))
  {
    error = "the input mesh has zero area";
    tree = FoldingTree();
    return false;
  }
  // The bound, proved; where it is not, the faces there are pinned and the tree built again.
  // A closed input that comes back with holes gets the faces there pinned too, for at most
  // MaximumClosingRounds builds, each kept only while it stores at most MaximumClosingShare of
  // the input's faces (or MaximumClosingFaces) more than the tree before it; a hole never
  // costs the bound: when a tree built to close holes is not proved within epsilon, the last
  // proved tree stands, holes and all.
  if (options.verifyBound && !tree.aborted)
  {
    FoldingTreeOptions again = options;
    again.progress = nullptr; // the progress bar already reached the end once
    std::vector<char> pinned(input.triangles.size(), 0);
    int boundRounds = 0, closingRounds = 0;
    std::unique_ptr<FoldingTree> proved; // the last tree proved within epsilon, with holes
    // A near miss of the first tree: it is rebuilt at a smaller epsilon, no pins; should that
    // tree miss too, the rounds go on at epsilon with the first tree's pins (firstPins).
    bool nearMissTree = false;
    std::vector<int> firstPins;
    int firstRound = 0;
    double provedArea = 0.0; // `proved`'s area ratio where it was rebuilt for that, else 0
    for (int round = 0;; ++round)
    {
      const UnfoldedBoundCheck check =
        VerifyUnfoldedBound(input, tree, options.verificationQueries, &toInput);
      if (options.trace)
        options.trace(FormatTrace(
          "[verify] round %d: proved bound %.6g of epsilon %.6g, %s; %d open edges where the "
          "input has none",
          round,
          check.upper,
          tree.rootEpsilon,
          check.within ? "within" : "not within",
          check.openEdges));
      if (check.within)
      {
        tree.verifiedBound = check.upper;
        nearMissTree = false;
      }
      const bool laidTwice = check.within && round == firstRound && again.rotationNodes &&
        tree.NumberOfRotations() > 0 && check.areaRatio > RotationAreaRatioLimit;
      // (A rebuild with holes lays no less: its missing faces lower its area.)
      const bool noLess =
        provedArea > 0.0 && (check.areaRatio >= provedArea || !check.pinOpen.empty());
      if (check.within && noLess && !laidTwice)
      {
        tree = std::move(*proved); // the planes lay no less surface twice
        tree.verificationRounds = round;
        break;
      }
      if (check.within && !laidTwice &&
        (check.pinOpen.empty() || closingRounds == MaximumClosingRounds))
        break;
      if (!check.within && proved)
      {
        tree = std::move(*proved);
        break;
      }
      // A first tree with rotation nodes that misses (the bound, or holes where the input is
      // closed): without the second orders it kept, if any, then the planes alone, at epsilon,
      // no pins (their seams are the ones the unfolder closes best); should that tree miss
      // too, the rounds below go on from it. One whose area is above RotationAreaRatioLimit:
      // the planes alone at once, kept only where they lay less surface twice.
      if (round == firstRound && again.rotationNodes && tree.NumberOfRotations() > 0)
      {
        const bool withoutSecond = keptSecondOrder && secondOrders && !laidTwice;
        if (withoutSecond)
          secondOrders = false;
        else
          again.rotationNodes = false;
        firstRound = round + 1; // the rebuilt tree is the first of the rounds below
        if (check.within && !(laidTwice && noLess))
        {
          proved.reset(new FoldingTree(tree)); // should the rebuilt tree miss the bound
          provedArea = laidTwice && check.pinOpen.empty() ? check.areaRatio : 0.0;
        }
        if (options.trace)
          options.trace(FormatTrace("[verify] the tree with rotation nodes missed%s: rebuilt %s",
            laidTwice ? FormatTrace(" (area %.3f of the input's)", check.areaRatio).c_str() : "",
            withoutSecond ? "without second orders" : "with planes alone"));
        build(again, pinned);
        tree.verificationRounds = round + 1;
        if (check.within &&
          tree.StoredFaces() - proved->StoredFaces() >
            std::max(MaximumClosingFaces,
              static_cast<int>(MaximumClosingShare * static_cast<double>(input.triangles.size()))))
        {
          tree = std::move(*proved); // the planes close its holes at too much storage
          break;
        }
        continue;
      }
      if (check.within)
      {
        int added = 0;
        for (int f : check.pinOpen)
          added += !pinned[f];
        if (added == 0)
          break; // pinned there already: the same tree again
        proved.reset(new FoldingTree(tree));
        provedArea = 0.0;
        ++closingRounds;
        for (int f : check.pinOpen)
          pinned[f] = 1;
      }
      else if (round == firstRound && check.upper > again.epsilon &&
        check.upper <= NearMissBoundRatio * again.epsilon)
      {
        again.epsilon *= NearMissEpsilonMargin * again.epsilon / check.upper; // no pins
        nearMissTree = true;
        if (options.trace)
          options.trace(
            FormatTrace("[verify] a near miss: rebuilt at epsilon %.6g", again.epsilon));
        firstPins = check.pin;
        --boundRounds; // not a round of pins
      }
      else if (nearMissTree)
      {
        again.epsilon = options.epsilon; // the near-miss rebuild missed too
        nearMissTree = false;
        if (options.trace)
          options.trace(FormatTrace("[verify] the near-miss rebuild missed too: epsilon %.6g with "
                                    "the first tree's pins",
            again.epsilon));
        for (int f : firstPins)
          pinned[f] = 1;
      }
      else if (boundRounds == MaximumVerificationRounds)
        std::fill(pinned.begin(), pinned.end(), 1); // a single leaf: the input itself
      else
        for (int f : check.pin)
          pinned[f] = 1;
      if (!check.within)
        ++boundRounds;
      build(again, pinned);
      tree.verificationRounds = round + 1;
      tree.pinnedFaces = static_cast<int>(std::count(pinned.begin(), pinned.end(), 1));
      if (check.within &&
        tree.StoredFaces() - proved->StoredFaces() >
          std::max(MaximumClosingFaces,
            static_cast<int>(MaximumClosingShare * static_cast<double>(input.triangles.size()))))
      {
        tree = std::move(*proved); // closing the holes would cost too much storage
        break;
      }
      if (boundRounds > MaximumVerificationRounds + 1)
        break; // not expected: every face pinned is the input itself
    }
  }
  tree.rotationNodesTried = options.rotationNodes;
  tree.buildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}
}
