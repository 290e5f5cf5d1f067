// The boundary loops of the final repair (UnfoldOptions::closeHoles): open edges traced
// into simple loops (FoldingTreeUnfolderHoles.cxx classifies and fills them).
#include "FoldingTreeUnfolderRepairInternal.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace foldingmeshes
{
namespace unfolder_detail
{
using namespace repair;

/// Splits a walk at repeated vertices into simple loops (of at least 3 vertices), appended to
/// `loops`; the rest counts as a loop too when `closed`.
static void SplitWalk(const std::vector<int>& walk,
  bool closed,
  std::vector<std::vector<int>>& loops)
{
  std::vector<int> stack;
  std::map<int, size_t> at;
  for (int v : walk)
  {
    auto it = at.find(v);
    if (it != at.end())
    {
      std::vector<int> loop(stack.begin() + it->second, stack.end());
      for (size_t i = it->second; i < stack.size(); ++i)
        at.erase(stack[i]);
      stack.resize(it->second);
      if (loop.size() >= 3)
        loops.push_back(loop);
    }
    at[v] = stack.size();
    stack.push_back(v);
  }
  if (closed && stack.size() >= 3)
    loops.push_back(stack);
}

namespace
{
/// The open edges of a piece and its face half-edges.
struct OpenEdges
{
  FlatEdgeMap<int> halfEdges; ///< directed face half-edge -> face (the last face of two)
  EdgeSet open;               ///< edges of one face (keys)
  std::map<int, std::vector<int>> holeNext; ///< hole half-edge a -> b, by a

  explicit OpenEdges(const Piece& piece)
  {
    for (const auto& e : EdgeFaces(piece))
      if (e.second.size() == 1)
      {
        this->open.insert(e.first);
        const Triangle& t = piece.triangles[e.second[0]];
        const int a = e.first.first, b = e.first.second;
        if (Direction(t, a, b) == 1)
          this->holeNext[b].push_back(a); // face a -> b: hole b -> a
        else
          this->holeNext[a].push_back(b);
      }
    if (this->open.empty())
      return; // a closed piece: no loop to trace, no half-edges needed
    this->halfEdges.reserve(3 * piece.triangles.size());
    for (int f = 0; f < piece.NumberOfFaces(); ++f)
      for (int k = 0; k < 3; ++k)
        this->halfEdges[{ piece.triangles[f][k], piece.triangles[f][(k + 1) % 3] }] = f;
  }

  /// Arrived at b by the hole edge a -> b (face half-edge b -> a): the next hole edge found
  /// by turning around b through its faces, so that at a pinch vertex (several openings)
  /// each opening is traced as its own loop; -1 if the fan is not consistently oriented.
  int Turn(const Piece& piece, int a, int b) const
  {
    const int* it = this->halfEdges.find({ b, a });
    for (int guard = 0; it && guard < 256; ++guard)
    {
      const Triangle& t = piece.triangles[*it];
      int k = 0;
      while (k < 3 && t[(k + 1) % 3] != b)
        ++k;
      if (k == 3)
        return -1;
      const int y = t[k]; // half-edge y -> b in this face
      if (this->open.count(Key(y, b)))
        return y;
      it = this->halfEdges.find({ b, y });
    }
    return -1;
  }
};

/// The loops along the hole half-edges, split at pinch vertices.
std::vector<std::vector<int>> DirectedLoops(const Piece& piece, const OpenEdges& edges)
{
  std::vector<std::vector<int>> loops;
  std::set<Edge> visited;
  for (const auto& start : edges.holeNext)
    for (int firstNext : start.second)
    {
      if (visited.count({ start.first, firstNext }))
        continue;
      // Walk unused hole half-edges until none leaves the current vertex.
      std::vector<int> walk;
      int a = start.first, b = firstNext;
      bool closed = false;
      while (true)
      {
        visited.insert({ a, b });
        walk.push_back(a);
        auto it = edges.holeNext.find(b);
        if (it == edges.holeNext.end())
          break; // a dead end: inconsistent orientation around b
        int next = edges.Turn(piece, a, b);
        if (next >= 0 && visited.count({ b, next }))
          next = -1;
        for (size_t i = 0; i < it->second.size() && next < 0; ++i)
          if (!visited.count({ b, it->second[i] }))
            next = it->second[i];
        if (next < 0)
        {
          closed = b == start.first; // back where the walk began
          break;
        }
        a = b;
        b = next;
      }
      SplitWalk(walk, closed, loops);
    }
  return loops;
}

/// The inner vertices of a shortest path from `from` to `to` along the edges of
/// `nonManifold` (by end point), at most three edges, avoiding `walk`'s vertices (`to`
/// excepted); false: none.
bool NonManifoldPath(const std::map<int, std::vector<int>>& nonManifold,
  int from,
  int to,
  const std::vector<int>& walk,
  std::vector<int>& path)
{
  std::map<int, int> previous{ { from, from } };
  std::vector<int> layer{ from };
  for (int depth = 0; depth < 3 && !layer.empty(); ++depth)
  {
    std::vector<int> nextLayer;
    for (int v : layer)
    {
      auto it = nonManifold.find(v);
      if (it == nonManifold.end())
        continue;
      for (int w : it->second)
      {
        if (previous.count(w) || (w != to && std::find(walk.begin(), walk.end(), w) != walk.end()))
          continue;
        previous[w] = v;
        if (w == to)
        {
          path.clear();
          for (int x = v; x != from; x = previous[x])
            path.push_back(x);
          std::reverse(path.begin(), path.end());
          return true;
        }
        nextLayer.push_back(w);
      }
    }
    layer = std::move(nextLayer);
  }
  return false;
}

/// The open edges in no loop, traced undirected and appended to `loops`: first chains
/// (between branch points or ends) closed by non-manifold edges, then cycles, then what is
/// left chain by chain from `reportOnly` on (see Unfolder::BoundaryLoops).
void UndirectedLoops(const Piece& piece,
  const OpenEdges& edges,
  std::vector<std::vector<int>>& loops,
  size_t& reportOnly)
{
  std::map<int, std::vector<int>> nonManifold; // edges of more than two faces, by end point
  for (const auto& e : EdgeFaces(piece))
    if (e.second.size() > 2)
    {
      nonManifold[e.first.first].push_back(e.first.second);
      nonManifold[e.first.second].push_back(e.first.first);
    }
  for (int stage = 0; stage < 3; ++stage)
  {
    if (stage == 2)
      reportOnly = loops.size();
    EdgeSet inLoop;
    for (const auto& loop : loops)
      for (size_t i = 0; i < loop.size(); ++i)
        inLoop.insert(Key(loop[i], loop[(i + 1) % loop.size()]));
    std::map<int, std::vector<int>> around; // open edges left, by end point (sorted)
    std::vector<Edge> open = edges.open.Keys();
    std::sort(open.begin(), open.end());
    for (const Edge& e : open)
      if (!inLoop.count(e))
      {
        around[e.first].push_back(e.second);
        around[e.second].push_back(e.first);
      }
    const bool chains = stage != 1;
    std::set<Edge> used;
    for (int pass = 0; pass < (stage == 2 ? 2 : 1); ++pass)
      for (const auto& start : around)
        for (int firstNext : start.second)
        {
          // Chains start at branch points and ends (then, left at last, anywhere).
          if (used.count(Key(start.first, firstNext)) ||
            (chains && pass == 0 && start.second.size() == 2))
            continue;
          std::vector<int> walk;
          int a = start.first, b = firstNext;
          bool closed = false;
          while (true)
          {
            used.insert(Key(a, b));
            walk.push_back(a);
            int next = -1;
            if (!chains || around[b].size() == 2)
              for (int c : around[b])
                if (!used.count(Key(b, c)))
                {
                  next = c;
                  break;
                }
            if (next < 0)
            {
              closed = b == start.first;
              if (chains && !closed)
              {
                walk.push_back(b);
                std::vector<int> back;
                closed = NonManifoldPath(nonManifold, b, start.first, walk, back) || stage == 2;
                walk.insert(walk.end(), back.begin(), back.end());
              }
              break;
            }
            a = b;
            b = next;
          }
          if (stage == 2)
            loops.push_back(walk); // (reported, never filled)
          else
            SplitWalk(walk, closed, loops);
        }
  }
}

/// Loops from `first` on run the way most of their edges' hole half-edges do.
void OrientAlongHoleEdges(const OpenEdges& edges,
  std::vector<std::vector<int>>& loops,
  size_t first)
{
  for (size_t l = first; l < loops.size(); ++l)
  {
    std::vector<int>& loop = loops[l];
    int along = 0; // edges a -> b whose open face runs b -> a (a hole half-edge)
    for (size_t i = 0; i < loop.size(); ++i)
    {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      along += edges.halfEdges.count({ b, a }) ? 1 : -1;
    }
    if (along < 0)
      std::reverse(loop.begin(), loop.end());
  }
}
} // namespace

/**
 * Boundary loops of the mesh, traced along hole half-edges (the reverses of the open face
 * half-edges) and split at pinch vertices into simple loops. With `undirectedRest` (the
 * tree lists input non-manifold edges, which the repair keeps: around them the hole
 * half-edges need not form cycles - at a fan of faces on one edge they all run from one end
 * of it to the other), the open edges left in no loop are traced again as undirected edges:
 * first chains between branch points or ends whose ends at most three non-manifold edges
 * join (closed by them), then cycles; such a loop runs the way most of its edges' hole
 * half-edges do. What is still left is appended chain by chain from index `reportOnly` on
 * (not closed: reported, never filled; max() when there is none).
 */
std::vector<std::vector<int>> Unfolder::BoundaryLoops(const Piece& piece,
  bool undirectedRest,
  size_t& reportOnly)
{
  reportOnly = std::numeric_limits<size_t>::max();
  const OpenEdges edges(piece);
  if (edges.open.empty())
    return {}; // a closed piece: no loop, directed or not
  std::vector<std::vector<int>> loops = DirectedLoops(piece, edges);
  if (!undirectedRest)
    return loops;
  const size_t directed = loops.size();
  UndirectedLoops(piece, edges, loops, reportOnly);
  OrientAlongHoleEdges(edges, loops, directed);
  return loops;
}
} // namespace unfolder_detail
} // namespace foldingmeshes
