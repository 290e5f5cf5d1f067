// RegionGrowing on hand-made strips of triangles (integer coordinates: exact areas):
// - FacesWithVerticesWithin: inclusive vs strict at values equal to the threshold, infinite d;
// - LabelConnectedRegions: two separate strips -> 2 regions numbered by lowest face id; a gap
//   splits a strip; faces sharing only a vertex are not connected; proximity links join parts
//   (only where the linked vertices touch selected faces);
// - LargestConnectedRegion: by area, not by face count; ties go to the lowest face id; empty
//   mask -> empty region; RegionArea.
// - LargestRegionAndWholeParts: the largest region plus the regions that are whole parts (not
//   pieces of a part); on one part exactly LargestConnectedRegion; HasSeveralParts.
#include "CoreTestUtilities.h"
#include "RegionGrowing.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

using foldingmeshes::FacesWithVerticesWithin;
using foldingmeshes::HasSeveralParts;
using foldingmeshes::LabelConnectedRegions;
using foldingmeshes::LargestConnectedRegion;
using foldingmeshes::LargestRegionAndWholeParts;
using foldingmeshes::PreparedMesh;
using foldingmeshes::RegionArea;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;

namespace
{
/// A strip of 2n triangles over [x0, x0 + n*w] x [y0, y0 + h] in the plane z = 0.
void AddStrip(TriangleMesh& m, double x0, double y0, int n, double w, double h)
{
  const int base = static_cast<int>(m.points.size());
  for (int i = 0; i <= n; ++i)
  {
    m.points.push_back(Vec3(x0 + i * w, y0, 0));
    m.points.push_back(Vec3(x0 + i * w, y0 + h, 0));
  }
  for (int i = 0; i < n; ++i)
  {
    const int a = base + 2 * i, b = a + 1, c = a + 2, d = a + 3;
    m.triangles.push_back({ a, c, d });
    m.triangles.push_back({ a, d, b });
  }
}

std::vector<char> All(const PreparedMesh& m)
{
  return std::vector<char>(m.NumberOfFaces(), 1);
}

/// Three separate strips of a, b and c squares (2a, 2b and 2c faces, in that order).
PreparedMesh ThreeStrips(int a, int b, int c)
{
  TriangleMesh soup;
  AddStrip(soup, 0, 0, a, 1, 1);
  AddStrip(soup, 0, 10, b, 1, 1);
  AddStrip(soup, 0, 20, c, 1, 1);
  return coretest::Prepare(soup);
}

/// Counts the faces where region[f] differs from expected(f) (each reported).
template <typename Expected>
int Mismatches(const std::vector<char>& region, Expected expected, const char* what)
{
  int wrong = 0;
  for (size_t f = 0; f < region.size(); ++f)
    if (bool(region[f]) != expected(static_cast<int>(f)))
    {
      std::cerr << what << ": face " << f << " " << int(region[f]) << "\n";
      ++wrong;
    }
  return wrong;
}
}

int main()
{
  const double inf = std::numeric_limits<double>::infinity();

  // ---- FacesWithVerticesWithin ----
  {
    TriangleMesh soup;
    AddStrip(soup, 0, 0, 6, 1, 1);
    const PreparedMesh m = coretest::Prepare(soup);
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial)
    {
      // Values on a coarse grid so that many equal the threshold exactly.
      std::vector<double> d(m.NumberOfPoints());
      for (double& v : d)
        v = rng() % 7 == 0 ? inf : 0.25 * (rng() % 8);
      const double threshold = 0.25 * (rng() % 8);
      const auto inclusive = FacesWithVerticesWithin(m, d, threshold, false);
      const auto strict = FacesWithVerticesWithin(m, d, threshold, true);
      for (int f = 0; f < m.NumberOfFaces(); ++f)
      {
        double maxD = 0.0;
        for (int v : m.triangles[f])
          maxD = std::max(maxD, d[v]);
        EXPECT(bool(inclusive[f]) == (maxD <= threshold),
          "inclusive: face " << f << " max d " << maxD << " threshold " << threshold);
        EXPECT(bool(strict[f]) == (maxD < threshold),
          "strict: face " << f << " max d " << maxD << " threshold " << threshold);
      }
    }
    std::vector<double> d(m.NumberOfPoints(), 1.0);
    EXPECT(RegionArea(m, FacesWithVerticesWithin(m, d, 1.0, false)) == 6.0 &&
        RegionArea(m, FacesWithVerticesWithin(m, d, 1.0, true)) == 0.0,
      "d == threshold everywhere: inclusive must select all, strict none");
  }

  // ---- Two separate strips, gaps, vertex-only contact ----
  {
    TriangleMesh soup;
    AddStrip(soup, 0, 0, 5, 1, 1);  // faces 0..9
    AddStrip(soup, 0, 10, 4, 1, 1); // faces 10..17
    const PreparedMesh m = coretest::Prepare(soup);
    REQUIRE(m.numberOfParts == 2, "two strips: " << m.numberOfParts << " parts");
    std::vector<int> labels;
    int n = LabelConnectedRegions(m, All(m), labels);
    EXPECT(n == 2, "two strips: " << n << " regions");
    for (int f = 0; f < m.NumberOfFaces(); ++f)
      EXPECT(labels[f] == (f < 10 ? 0 : 1), "two strips: face " << f << " label " << labels[f]);
    // Remove faces 4 and 5 (one square in the middle of the first strip): 3 regions, and the
    // numbering follows the lowest face id: {0..3} = 0, {6..9} = 1, {10..17} = 2.
    std::vector<char> mask = All(m);
    mask[4] = mask[5] = 0;
    n = LabelConnectedRegions(m, mask, labels);
    EXPECT(n == 3, "strip with a gap: " << n << " regions, expected 3");
    for (int f = 0; f < m.NumberOfFaces(); ++f)
    {
      const int expected = (f == 4 || f == 5) ? -1 : (f < 4 ? 0 : (f < 10 ? 1 : 2));
      EXPECT(labels[f] == expected,
        "strip with a gap: face " << f << " label " << labels[f] << " expected " << expected);
    }
    // The dual graph of a strip is a path (1-0-3-2-5-4-7-6-9-8): removing the single
    // triangle 5 splits the first strip into {0..3} and {4, 6..9}.
    mask = All(m);
    mask[5] = 0;
    n = LabelConnectedRegions(m, mask, labels);
    EXPECT(n == 3 && labels[0] == 0 && labels[3] == 0 && labels[4] == 1 && labels[6] == 1 &&
        labels[9] == 1 && labels[10] == 2,
      "removing triangle 5: " << n << " regions, labels of 3/4: " << labels[3] << "/" << labels[4]);

    // Faces sharing only a vertex are not connected.
    TriangleMesh bow;
    bow.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0) };
    bow.triangles = { { 0, 1, 2 }, { 0, 3, 4 } };
    const PreparedMesh b = coretest::Prepare(bow);
    EXPECT(
      LabelConnectedRegions(b, All(b), labels) == 2, "faces sharing a vertex only were connected");
  }

  // ---- LargestConnectedRegion: by area, not by count ----
  {
    TriangleMesh soup;
    AddStrip(soup, 0, 0, 10, 1, 1); // 20 faces, area 10
    AddStrip(soup, 0, 10, 2, 4, 4); // 4 faces, area 32
    const PreparedMesh m = coretest::Prepare(soup);
    const auto region = LargestConnectedRegion(m, All(m));
    int count = 0;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
    {
      EXPECT(bool(region[f]) == (f >= 20), "largest by area: face " << f << " " << int(region[f]));
      count += region[f];
    }
    EXPECT(count == 4 && RegionArea(m, region) == 32.0,
      "largest region: " << count << " faces, area " << RegionArea(m, region)
                         << ", expected 4 and 32");
    EXPECT(RegionArea(m, All(m)) == 42.0, "RegionArea of all faces " << RegionArea(m, All(m)));

    // Masking most of the big strip makes the small one the largest.
    std::vector<char> mask = All(m);
    for (int f = 20; f < 23; ++f)
      mask[f] = 0;
    const auto r2 = LargestConnectedRegion(m, mask);
    EXPECT(RegionArea(m, r2) == 10.0 && r2[0] && !r2[23],
      "largest after masking: area " << RegionArea(m, r2));

    // Empty mask: empty region.
    const auto none = LargestConnectedRegion(m, std::vector<char>(m.NumberOfFaces(), 0));
    EXPECT(RegionArea(m, none) == 0.0 && std::count(none.begin(), none.end(), 1) == 0,
      "empty mask gave a non-empty region");
  }

  // ---- Ties: equal areas -> the region with the lowest face id ----
  {
    TriangleMesh soup;
    AddStrip(soup, 0, 0, 3, 1, 1);  // faces 0..5, area 3
    AddStrip(soup, 0, 10, 3, 1, 1); // faces 6..11, area 3 (a translated copy: exact)
    const PreparedMesh m = coretest::Prepare(soup);
    const auto region = LargestConnectedRegion(m, All(m));
    EXPECT(region[0] && !region[6], "tie: the region of face 0 should win");
    std::vector<char> mask = All(m);
    mask[0] = 0; // now 2.5 vs 3: the second strip wins
    const auto r2 = LargestConnectedRegion(m, mask);
    EXPECT(r2[6] && !r2[1], "after removing face 0 the second strip should win");
  }

  // ---- Proximity links join parts ----
  {
    TriangleMesh soup;
    AddStrip(soup, 0, 0, 4, 1, 1);     // faces 0..7, points 0..9
    AddStrip(soup, 4.001, 0, 3, 1, 1); // faces 8..13, starts 0.001 after the first ends
    PreparedMesh m = coretest::Prepare(soup);
    REQUIRE(m.numberOfParts == 2, "linked strips: " << m.numberOfParts << " parts");
    std::vector<int> labels;
    EXPECT(LabelConnectedRegions(m, All(m), labels) == 2, "unlinked strips must be 2 regions");
    foldingmeshes::LinkNearbyParts(m, 0.01);
    EXPECT(!m.proximityLinks.empty(), "no proximity links between strips 0.001 apart");
    EXPECT(LabelConnectedRegions(m, All(m), labels) == 1, "linked strips must be 1 region");
    const auto region = LargestConnectedRegion(m, All(m));
    EXPECT(std::abs(RegionArea(m, region) - 7.0) < 1e-12,
      "linked largest region area " << RegionArea(m, region));
    // Deselect the faces touching the linked vertices on one side: no more connection.
    std::vector<char> mask = All(m);
    for (const auto& link : m.proximityLinks)
      for (int k = m.vertexFaceOffsets[link.second]; k < m.vertexFaceOffsets[link.second + 1]; ++k)
        mask[m.vertexFaces[k]] = 0;
    EXPECT(LabelConnectedRegions(m, mask, labels) == 2, "links without selected faces still join");
    // Far strips: no links.
    TriangleMesh far;
    AddStrip(far, 0, 0, 4, 1, 1);
    AddStrip(far, 4.5, 0, 3, 1, 1);
    PreparedMesh mf = coretest::Prepare(far);
    foldingmeshes::LinkNearbyParts(mf, 0.01);
    EXPECT(mf.proximityLinks.empty() && LabelConnectedRegions(mf, All(mf), labels) == 2,
      "strips 0.5 apart were linked");
  }

  // ---- Whole parts join the largest region; pieces of parts do not ----
  {
    // Parts A: faces 0..9 (area 5), B: 10..13 (2), C: 14..17 (2).
    const PreparedMesh m = ThreeStrips(5, 2, 2);
    EXPECT(HasSeveralParts(m), "three strips: HasSeveralParts false");
    std::vector<char> mask = All(m);
    mask[9] = 0;  // A: faces 0..7 the largest region, face 8 cut off (the strip's dual is a path)
    mask[17] = 0; // C: a piece of its part
    EXPECT(Mismatches(
             LargestRegionAndWholeParts(m, mask),
             [](int f) { return f < 8 || (f >= 10 && f < 14); },
             "largest + whole parts") == 0,
      "largest region + whole parts: wrong faces");
    // One part: exactly the largest connected region, the other pieces left out.
    TriangleMesh strip;
    AddStrip(strip, 0, 0, 8, 1, 1);
    const PreparedMesh one = coretest::Prepare(strip);
    EXPECT(!HasSeveralParts(one), "one strip: HasSeveralParts true");
    std::vector<char> gap = All(one);
    gap[6] = gap[7] = 0;
    EXPECT(LargestRegionAndWholeParts(one, gap) == LargestConnectedRegion(one, gap),
      "one part: not the largest connected region");
    // A whole part larger than the largest region that is not one does not take its place.
    // Parts A: faces 0..5 (area 3), B: 6..15 (5), C: 16..19 (2).
    const PreparedMesh t = ThreeStrips(3, 5, 2);
    std::vector<char> partly = All(t);
    partly[5] = 0;  // A: faces 0..3 (a piece of A), area 2; face 4 cut off
    partly[19] = 0; // C: pieces {16, 17} and {18}
    EXPECT(Mismatches(
             LargestRegionAndWholeParts(t, partly),
             [](int f) { return f < 4 || (f >= 6 && f < 16); },
             "whole part larger than the region") == 0,
      "a whole part larger than the connected region took its place");
    // Every region a whole part: all of them.
    EXPECT(LargestRegionAndWholeParts(m, All(m)) == All(m), "all whole parts: not all faces");
    EXPECT(RegionArea(m, LargestRegionAndWholeParts(m, std::vector<char>(18, 0))) == 0.0,
      "empty mask gave a non-empty region");
  }
  return coretest::Finish("TestRegionGrowing");
}
