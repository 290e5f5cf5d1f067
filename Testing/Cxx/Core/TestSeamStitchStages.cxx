// The stages of the unfolder's seam stitch (FoldingTreeUnfolderStitching.cxx), one at a time
// on hand-made points:
// - ProposeStitches pairs each candidate with its nearest candidate of another child within
//   tol (a tie goes to the lower id), never with one farther than tol; two candidates of one
//   child only within sameChildDistance; the proposals come sorted by (distance, a, b);
// - ClusterStitches never puts two vertices of one child in a cluster through proposals of
//   different children, chains children A-B-C into one cluster, and merges same-child pairs,
//   but never chains them (a run of one child's short open edges stays pairs, issue 21);
// - PlaceClusters moves a cluster to its mean when every member's budget allows it, to a
//   member's position when only that fits, and dissolves it when nothing fits;
// - ConstrainedLaplacianSmoothing (the paper's section 4.3) moves only rough vertices, each
//   at most min(rough, budget) from where it started, towards its neighbours' mean, spends
//   the budgets and does nothing with 0 iterations.
#include "CoreTestUtilities.h"
#include "FoldingTreeUnfolderInternal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace foldingmeshes;
using namespace foldingmeshes::unfolder_detail;

namespace
{
/// A piece of loose points (no faces) with the given budgets.
Piece LoosePoints(const std::vector<Vec3>& points, double budget)
{
  Piece p;
  p.points = points;
  const int n = static_cast<int>(points.size());
  p.pointOrig.resize(n);
  for (int i = 0; i < n; ++i)
    p.pointOrig[i] = i;
  p.pointCopy.assign(n, 0);
  p.tear.assign(n, TearList{});
  p.onPlane.assign(n, 0);
  p.budget.assign(n, budget);
  p.border.assign(n, 0);
  p.projected.assign(n, 0);
  return p;
}

void TestProposals()
{
  // 0 and 1 of child 0; 2, 3 of child 1 at equal distance from 0; 4 of child 1 beyond tol.
  const std::vector<Vec3> x{
    Vec3(0, 0, 0), Vec3(0.001, 0, 0), Vec3(0.1, 0, 0), Vec3(-0.1, 0, 0), Vec3(5, 0, 0)
  };
  const std::vector<int> child{ 0, 0, 1, 1, 1 };
  const std::vector<int> all{ 0, 1, 2, 3, 4 };
  const auto p = ProposeStitches(x, all, child, 0.2, 0.0);
  bool zeroToTwo = false, four = false, same = false;
  for (const auto& s : p)
  {
    zeroToTwo = zeroToTwo || (s.a == 0 && s.b == 2);
    four = four || s.a == 4 || s.b == 4;
    same = same || s.sameChild;
  }
  EXPECT(zeroToTwo, "0's nearest of child 1 at a tie is the lower id 2");
  EXPECT(!four, "4, farther than tol from every other child, is proposed");
  EXPECT(!same, "a same-child pair is proposed with sameChildDistance 0");
  for (size_t i = 1; i < p.size(); ++i)
    EXPECT(p[i - 1].distance <= p[i].distance, "proposals not sorted by distance");
  const auto q = ProposeStitches(x, all, child, 0.2, 0.01);
  int sameCount = 0;
  for (const auto& s : q)
    sameCount += s.sameChild && s.a == 0 && s.b == 1;
  EXPECT(sameCount == 1, "0-1 (one child, 0.001 apart) proposed " << sameCount << " times");
}

void TestClusters()
{
  // A chain over three children: 0 (child 0) - 1 (child 1) - 2 (child 2); and 3 (child 0)
  // next to 1: it cannot join the cluster that already holds child 0.
  const std::vector<int> child{ 0, 1, 2, 0 };
  std::vector<StitchProposal> p{ { 0.1, 0, 1, false }, { 0.2, 1, 2, false }, { 0.3, 1, 3, false } };
  StitchClusters c = ClusterStitches(p, child, 4);
  EXPECT(c.rep[0] == c.rep[1] && c.rep[1] == c.rep[2], "children 0-1-2 not chained");
  EXPECT(c.rep[3] == 3, "a second vertex of child 0 joined the cluster");
  EXPECT(c.count[c.rep[0]] == 3, "cluster of " << c.count[c.rep[0]] << " members, not 3");
  // The same two vertices of one child, proposed as a same-child pair, merge.
  p.push_back({ 0.4, 0, 3, true });
  c = ClusterStitches(p, child, 4);
  EXPECT(c.rep[3] == c.rep[0], "a same-child pair did not merge");
  // Same-child pairs do not chain: a run 0-1-2-3-4 of one child (a finely tessellated open
  // rim) becomes pairs, never one point.
  const std::vector<int> one(5, 0);
  std::vector<StitchProposal> run;
  for (int i = 0; i < 4; ++i)
    run.push_back({ 0.001, i, i + 1, true });
  c = ClusterStitches(run, one, 5);
  int largest = 0;
  for (int v = 0; v < 5; ++v)
    largest = std::max(largest, c.count[c.rep[v]]);
  EXPECT(largest == 2, "a run of same-child pairs chained into a cluster of " << largest);
}

void TestPlacement()
{
  const std::vector<int> child{ 0, 1 };
  const std::vector<StitchProposal> p{ { 0.1, 0, 1, false } };
  for (const double budget : { 1.0, 0.01 })
  {
    Piece piece = LoosePoints({ Vec3(0, 0, 0), Vec3(0.1, 0, 0) }, budget);
    StitchClusters c = ClusterStitches(p, child, 2);
    SeamReport seam;
    seam.tearVertices = 2;
    PlaceClusters(piece, c, seam);
    if (budget == 1.0)
    {
      EXPECT((piece.points[0] - Vec3(0.05, 0, 0)).norm() < 1e-15,
        "a cluster with room was not placed at its mean");
      EXPECT(std::abs(piece.budget[0] - (1.0 - 0.05)) < 1e-15, "the move was not charged");
      EXPECT(seam.stitchedVertices == 2 && seam.budgetRejectedClusters == 0,
        "stitched " << seam.stitchedVertices);
    }
    else
    {
      EXPECT(c.rep[1] == 1 && seam.budgetRejectedClusters == 1 && seam.stitchedVertices == 0,
        "a cluster with no room (budgets 0.01, 0.1 apart) was merged");
      EXPECT(piece.points[0] == Vec3(0, 0, 0) && piece.points[1] == Vec3(0.1, 0, 0),
        "a dissolved cluster moved its points");
    }
  }
  // Only one member's position fits: member 0 may not move, member 1 may move 1.
  Piece piece = LoosePoints({ Vec3(0, 0, 0), Vec3(0.1, 0, 0) }, 1.0);
  piece.budget[0] = 0.0;
  StitchClusters c = ClusterStitches(p, child, 2);
  SeamReport seam;
  PlaceClusters(piece, c, seam);
  EXPECT(piece.points[0] == Vec3(0, 0, 0) && seam.budgetRejectedClusters == 0,
    "the cluster did not go to the member that may not move");
}

void TestSmoothing()
{
  // A fan: centre 0 lifted by 0.3 above a flat hexagon of fixed vertices 1..6.
  std::vector<Vec3> x{ Vec3(0, 0, 0.3) };
  for (int k = 0; k < 6; ++k)
    x.push_back(Vec3(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.0));
  Piece piece = LoosePoints(x, 1.0);
  for (int k = 0; k < 6; ++k)
    piece.triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 6 });
  std::vector<double> rough(7, 0.0);
  rough[0] = 0.1;
  Piece unchanged = piece;
  EXPECT(ConstrainedLaplacianSmoothing(unchanged, rough, 0, 0.5) == 1 &&
      unchanged.points == piece.points,
    "0 iterations moved points");
  const int smoothed = ConstrainedLaplacianSmoothing(piece, rough, 10, 0.5);
  EXPECT(smoothed == 1, "smoothed " << smoothed << " vertices, not 1");
  EXPECT(std::abs(piece.points[0].z() - 0.2) < 1e-12 && piece.points[0].head<2>().norm() < 1e-12,
    "the rough vertex went to " << piece.points[0].transpose() << ", not 0.1 down to z 0.2");
  for (int v = 1; v < 7; ++v)
    EXPECT(piece.points[v] == x[v], "fixed vertex " << v << " moved");
  EXPECT(std::abs(piece.budget[0] - 0.9) < 1e-12, "budget " << piece.budget[0] << ", not 0.9");
  // A budget below rough bounds the move.
  Piece tight = LoosePoints(x, 1.0);
  tight.triangles = piece.triangles;
  tight.budget[0] = 0.05;
  ConstrainedLaplacianSmoothing(tight, rough, 10, 0.5);
  EXPECT(std::abs(tight.points[0].z() - 0.25) < 1e-12 && tight.budget[0] < 1e-12,
    "with budget 0.05 the vertex went to z " << tight.points[0].z());
}
}

int main()
{
  TestProposals();
  TestClusters();
  TestPlacement();
  TestSmoothing();
  return coretest::Finish("TestSeamStitchStages");
}
