// Meshes and measures of TestUnfoldingAccuracy (see the header).
#include "UnfoldingAccuracyMeshes.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkTriangle.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace foldingmeshes
{
namespace testing
{
namespace
{
/// Summed area of the triangles of pd whose entry of `only` (a cell array; null: every
/// triangle) is nonzero; polygons in cell order after any vertices and lines.
double TriangleArea(vtkPolyData* pd, vtkDataArray* only)
{
  double area = 0.0, p[3][3];
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = pd->GetPolys();
  vtkIdType cell = pd->GetNumberOfVerts() + pd->GetNumberOfLines();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids); ++cell)
    if (n == 3 && (!only || only->GetTuple1(cell) != 0.0))
    {
      for (int k = 0; k < 3; ++k)
        pd->GetPoint(ids[k], p[k]);
      area += vtkTriangle::TriangleArea(p[0], p[1], p[2]);
    }
  return area;
}
}

double TotalArea(vtkPolyData* pd)
{
  return TriangleArea(pd, nullptr);
}

double FilledArea(vtkPolyData* pd)
{
  vtkDataArray* filled = pd->GetCellData()->GetArray("FoldingFilled");
  return filled ? TriangleArea(pd, filled) : 0.0;
}

vtkSmartPointer<vtkPolyData> Cube(int n, double h)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  std::map<std::array<long long, 3>, vtkIdType> ids;
  auto at = [&](double x, double y, double z)
  {
    const std::array<long long, 3> key{
      std::llround(x * 1e9), std::llround(y * 1e9), std::llround(z * 1e9)
    };
    auto it = ids.find(key);
    if (it != ids.end())
      return it->second;
    const vtkIdType id = points->InsertNextPoint(x, y, z);
    ids[key] = id;
    return id;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (double side : { -1.0, 1.0 })
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      auto point = [&](double a, double b)
      {
        double p[3];
        p[axis] = side * h;
        p[u] = a;
        p[v] = b;
        return at(p[0], p[1], p[2]);
      };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
          const double a0 = -h + 2 * h * i / n, a1 = -h + 2 * h * (i + 1) / n;
          const double b0 = -h + 2 * h * j / n, b1 = -h + 2 * h * (j + 1) / n;
          vtkIdType q[4] = { point(a0, b0), point(a1, b0), point(a1, b1), point(a0, b1) };
          const vtkIdType c = point(0.5 * (a0 + a1), 0.5 * (b0 + b1));
          for (int k = 0; k < 4; ++k)
          {
            // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
            vtkIdType t[3] = { q[k], q[(k + 1) % 4], c };
            if (side < 0)
              std::swap(t[0], t[1]);
            polys->InsertNextCell(3, t);
          }
        }
    }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

vtkSmartPointer<vtkPolyData> Scaled(vtkPolyData* in, double s)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(in);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    out->GetPoints()->SetPoint(i, s * p[0], s * p[1], s * p[2]);
  }
  return out;
}

EdgeCounts CountEdges(vtkPolyData* pd)
{
  std::map<std::pair<vtkIdType, vtkIdType>, std::array<int, 2>> uses; // (forward, backward)
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = pts[k], b = pts[(k + 1) % n];
      auto& u = uses[{ std::min(a, b), std::max(a, b) }];
      if (!u[0] && !u[1])
        u = { 0, 0 };
      ++u[a < b ? 0 : 1];
    }
  EdgeCounts c;
  for (const auto& e : uses)
  {
    const int total = e.second[0] + e.second[1];
    ++c.edges;
    c.open += total == 1;
    c.nonManifold += total > 2;
    c.misoriented += total == 2 && (e.second[0] == 2 || e.second[1] == 2);
  }
  return c;
}

Border InputBorder(vtkPolyData* pd)
{
  std::map<std::array<double, 3>, vtkIdType> unique;
  std::vector<vtkIdType> id(pd->GetNumberOfPoints());
  for (vtkIdType p = 0; p < pd->GetNumberOfPoints(); ++p)
  {
    std::array<double, 3> x;
    pd->GetPoint(p, x.data());
    id[p] = unique.emplace(x, static_cast<vtkIdType>(unique.size())).first->second;
  }
  std::map<std::pair<vtkIdType, vtkIdType>, std::pair<int, std::pair<vtkIdType, vtkIdType>>> uses;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = id[pts[k]], b = id[pts[(k + 1) % n]];
      if (a == b)
        continue;
      auto& u = uses[{ std::min(a, b), std::max(a, b) }];
      ++u.first;
      u.second = { pts[k], pts[(k + 1) % n] };
    }
  std::vector<vtkIdType> parent(unique.size());
  for (size_t i = 0; i < parent.size(); ++i)
    parent[i] = static_cast<vtkIdType>(i);
  auto find = [&](vtkIdType a)
  {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  Border border;
  std::set<vtkIdType> onBorder;
  for (const auto& e : uses)
    if (e.second.first == 1)
    {
      double x[3], y[3];
      pd->GetPoint(e.second.second.first, x);
      pd->GetPoint(e.second.second.second, y);
      border.length += std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
      parent[find(e.first.first)] = find(e.first.second);
      onBorder.insert(e.first.first);
      onBorder.insert(e.first.second);
    }
  std::set<vtkIdType> roots;
  for (vtkIdType v : onBorder)
    roots.insert(find(v));
  border.loops = static_cast<long long>(roots.size());
  return border;
}

long long WeldedPointCount(vtkPolyData* pd)
{
  std::set<std::array<double, 3>> unique;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 0; k < n; ++k)
    {
      std::array<double, 3> x;
      pd->GetPoint(pts[k], x.data());
      unique.insert(x);
    }
  return static_cast<long long>(unique.size());
}

long long TriangleCount(vtkPolyData* pd)
{
  long long count = 0;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    count += std::max<vtkIdType>(0, n - 2);
  return count;
}

vtkSmartPointer<vtkPolyData> BumpBox(int n, double bump, bool doublePoints)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<vtkIdType, 3>> triangles;
  auto grid = [n](int layer, int i, int j) -> vtkIdType
  { return layer * (n + 1) * (n + 1) + j * (n + 1) + i; };
  for (int layer = 0; layer < 2; ++layer) // 0: top, 1: bottom
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        const bool centre = layer == 0 && 2 * i == n && 2 * j == n;
        points.push_back(
          { double(i) / n, double(j) / n, layer == 0 ? 1.0 + (centre ? bump : 0.0) : 0.0 });
      }
  for (int layer = 0; layer < 2; ++layer)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType a = grid(layer, i, j), b = grid(layer, i + 1, j),
                        c = grid(layer, i + 1, j + 1), d = grid(layer, i, j + 1);
        if (layer == 0)
          triangles.insert(triangles.end(), { { a, b, c }, { a, c, d } });
        else
          triangles.insert(triangles.end(), { { a, c, b }, { a, d, c } });
      }
  // The sides: the grid's boundary ring, counter-clockwise seen from above.
  std::vector<std::array<int, 2>> ring;
  for (int i = 0; i < n; ++i)
    ring.push_back({ i, 0 });
  for (int j = 0; j < n; ++j)
    ring.push_back({ n, j });
  for (int i = n; i > 0; --i)
    ring.push_back({ i, n });
  for (int j = n; j > 0; --j)
    ring.push_back({ 0, j });
  for (size_t k = 0; k < ring.size(); ++k)
  {
    const auto& p = ring[k];
    const auto& q = ring[(k + 1) % ring.size()];
    const vtkIdType b0 = grid(1, p[0], p[1]), b1 = grid(1, q[0], q[1]);
    const vtkIdType t0 = grid(0, p[0], p[1]), t1 = grid(0, q[0], q[1]);
    triangles.insert(triangles.end(), { { b0, b1, t1 }, { b0, t1, t0 } });
  }
  vtkSmartPointer<vtkPolyData> box = Triangles(points, triangles);
  if (doublePoints)
    return box;
  vtkNew<vtkPoints> single;
  single->SetDataTypeToFloat();
  for (const auto& p : points)
    single->InsertNextPoint(p.data());
  box->SetPoints(single);
  return box;
}

vtkSmartPointer<vtkPolyData> Triangles(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
    pts->InsertNextPoint(p.data());
  vtkNew<vtkCellArray> polys;
  for (const auto& t : triangles)
    polys->InsertNextCell(3, t.data());
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(pts);
  pd->SetPolys(polys);
  return pd;
}
}
}
