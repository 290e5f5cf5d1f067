// WorkMesh helpers: area, extraction, welding (see FoldingWorkMesh.h).
#include "FoldingWorkMesh.h"

#include "MeshPreparation.h"

#include <algorithm>
#include <numeric>

namespace foldingmeshes
{
namespace treebuilder
{
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
      out.AppendPoint(w, v);
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

WorkMesh ExtractFaces(const WorkMesh& w, const std::vector<int>& faces)
{
  std::vector<int> points;
  for (int f : faces)
    points.insert(points.end(), w.triangles[f].begin(), w.triangles[f].end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  WorkMesh out;
  for (int v : points)
    out.AppendPoint(w, v);
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

std::vector<int> WeldAndDropCollapsed(WorkMesh& w)
{
  const int n = w.NumberOfPoints();
  const std::vector<int> rep = CoincidentPointRepresentatives(w.points);
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

void MarkTears(WorkMesh& w, const std::vector<char>& S, const std::vector<int>& labels, int depth)
{
  std::vector<int> firstChild(w.points.size(), -1);
  std::vector<char> tear(w.points.size(), 0);
  for (int f = 0; f < w.NumberOfFaces(); ++f)
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
}
}
