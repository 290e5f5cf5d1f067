// EdgeFaces (the core's edge table, a counting sort by the smaller point since 2026-12-05)
// against a std::map built face by face: the same edges in the same (sorted) order, each with
// the same faces in increasing order - on random triangle lists with repeated points
// (degenerate triangles), duplicate and opposite faces, non-manifold edges, unused point ids;
// on a single triangle and on no triangle. OpenEdges against the map's edges of one use.
#include "CoreTestUtilities.h"
#include "EdgeTable.h"

#include <map>
#include <random>
#include <string>
#include <vector>

namespace
{
using foldingmeshes::Edge;
using foldingmeshes::Triangle;

std::map<Edge, std::vector<int>> ByMap(const std::vector<Triangle>& triangles)
{
  std::map<Edge, std::vector<int>> edges;
  for (size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      edges[foldingmeshes::EdgeKey(triangles[f][k], triangles[f][(k + 1) % 3])].push_back(
        static_cast<int>(f));
  return edges;
}

void Compare(const std::vector<Triangle>& triangles, const std::string& name)
{
  const std::map<Edge, std::vector<int>> expected = ByMap(triangles);
  const foldingmeshes::EdgeTable table = foldingmeshes::EdgeFaces(triangles);
  auto e = expected.begin();
  size_t count = 0;
  for (const auto& entry : table)
  {
    ++count;
    if (e == expected.end())
    {
      EXPECT(false, name << ": more edges than the map's " << expected.size());
      return;
    }
    EXPECT(entry.first == e->first,
      name << ": edge " << count << " is (" << entry.first.first << ", " << entry.first.second
           << "), the map's (" << e->first.first << ", " << e->first.second << ")");
    EXPECT(std::vector<int>(entry.second.begin(), entry.second.end()) == e->second,
      name << ": the faces of edge (" << e->first.first << ", " << e->first.second << ") differ");
    ++e;
  }
  EXPECT(count == expected.size(), name << ": " << count << " edges, the map " << expected.size());
  std::vector<Edge> open;
  for (const auto& x : expected)
    if (x.second.size() == 1)
      open.push_back(x.first);
  EXPECT(foldingmeshes::OpenEdges(triangles) == open, name << ": open edges differ");
}
}

int main()
{
  Compare({}, "no triangle");
  Compare({ { 2, 0, 1 } }, "one triangle");
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial)
  {
    const int points = 3 + static_cast<int>(rng() % 40);
    const int faces = static_cast<int>(rng() % 300);
    std::vector<Triangle> triangles;
    for (int f = 0; f < faces; ++f)
    {
      Triangle t{ static_cast<int>(rng() % points),
        static_cast<int>(rng() % points),
        static_cast<int>(rng() % points) };
      if (rng() % 4 == 0 && !triangles.empty()) // a duplicate or an opposite face
      {
        t = triangles[rng() % triangles.size()];
        if (rng() % 2)
          std::swap(t[1], t[2]);
      }
      triangles.push_back(t);
    }
    Compare(triangles, "random list " + std::to_string(trial));
  }
  return coretest::Finish("TestEdgeTable");
}
