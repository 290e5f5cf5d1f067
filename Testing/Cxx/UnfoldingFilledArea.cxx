// FilledAreaRatio against a hole of known area (see UnfoldingFilledArea.h).
#include "UnfoldingFilledArea.h"

#include "Core/CoreTestUtilities.h"
#include "FoldingTree.h"
#include "TestExpect.h"
#include "vtkFoldingTreeIO.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace foldingmeshes
{
namespace testing
{
int CheckFilledArea()
{
  int failures = 0;
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(16);
  source->SetPhiResolution(12);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  const TriangleMesh full = coretest::ToTriangleMesh(source->GetOutput());
  // The north pole (largest z) and the ring of its neighbours, all at one height.
  int pole = 0;
  for (int v = 1; v < static_cast<int>(full.points.size()); ++v)
    if (full.points[v].z() > full.points[pole].z())
      pole = v;
  TriangleMesh holed;
  holed.points = full.points;
  double fullArea = 0.0, ringArea = 0.0;
  for (const Triangle& t : full.triangles)
  {
    const Vec3 a = full.points[t[0]], b = full.points[t[1]], c = full.points[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    fullArea += area;
    if (std::find(t.begin(), t.end(), pole) == t.end())
      holed.triangles.push_back(t);
    else
    {
      // The removed face's edge opposite the pole, projected on the ring's plane, is a side
      // of the ring polygon: its triangle with the axis is the polygon's share.
      std::array<int, 2> side{};
      int k = 0;
      for (int v : t)
        if (v != pole)
          side[k++] = v;
      const Vec3 p = full.points[side[0]], q = full.points[side[1]];
      ringArea += 0.5 * std::abs(p.x() * q.y() - p.y() * q.x());
    }
  }
  // One leaf, no flags: the ring is not on the input's border (a hole to fill).
  FoldingTree tree = coretest::LeafTree(holed, 0.2, coretest::Diagonal(full));
  tree.originalArea = fullArea;
  vtkNew<vtkMultiBlockDataSet> blocks;
  std::string error;
  FOLDINGMESHES_EXPECT(
    failures, FoldingTreeToMultiBlock(tree, nullptr, blocks, error), "holed sphere: " << error);
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(blocks);
  unfolder->Update();
  vtkFieldData* fd = unfolder->GetOutput()->GetFieldData();
  auto field = [&](const char* name)
  {
    vtkDataArray* a = fd->GetArray(name);
    return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : -1.0;
  };
  const double filled = field("FilledAreaRatio") * fullArea;
  std::printf("holed sphere: %g loops filled, fill area %.9f, ring polygon %.9f, open edges %g\n",
    field("FilledLoops"),
    filled,
    ringArea,
    field("OpenEdges"));
  FOLDINGMESHES_EXPECT(failures,
    field("FilledLoops") == 1 && field("OpenEdges") == 0,
    "holed sphere: " << field("FilledLoops") << " loops filled, " << field("OpenEdges")
                     << " open edges");
  FOLDINGMESHES_EXPECT(failures,
    std::abs(filled - ringArea) <= 1e-9 * ringArea,
    "holed sphere: FilledAreaRatio x area " << filled << ", the ring's polygon " << ringArea);
  return failures;
}
}
}
