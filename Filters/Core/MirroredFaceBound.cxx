#include "MirroredFaceBound.h"

#include "PointTriangleDistance.h"

#include "ParallelTasks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

namespace foldingmeshes
{
namespace
{
struct Corner
{
  Vec3 x;
  ClosestFaceHit hit; ///< closest triangle of the mesh (within the search radius)
};

double TriangleDistance(const PreparedMesh& mesh, const Vec3& p, int face)
{
  const Triangle& t = mesh.triangles[face];
  return std::sqrt(ClosestPointTriangle(p, mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]])
                     .squaredDistance);
}

/// True when the sub-triangle with these corners is proved within `limit` (see the header).
bool Within(const PreparedMesh& mesh,
  const ClosestFaceQuery& queries,
  const std::array<Corner, 3>& c,
  double limit,
  double radius,
  int levels)
{
  for (const Corner& k : c)
    if (!(k.hit.face >= 0 && k.hit.distance < limit))
      return false;
  // Candidates T: the triangles closest to the centroid (inside a face this piece may lie
  // on: the one tie-free choice for a copy that coincides with a face) and to the corners.
  const Vec3 centroid = (c[0].x + c[1].x + c[2].x) / 3.0;
  const ClosestFaceHit centre = queries.ClosestWithin(centroid, radius);
  if (!(centre.face >= 0 && centre.distance < limit))
    return false;
  // The distance is 1-Lipschitz: at most dist(centroid) + the corners' distance to it (this
  // settles pieces over several coplanar faces, where no single face bounds them).
  const double spread = std::sqrt(std::max({ (c[0].x - centroid).squaredNorm(),
    (c[1].x - centroid).squaredNorm(),
    (c[2].x - centroid).squaredNorm() }));
  if (centre.distance + spread < limit)
    return true;
  const int candidates[4] = { centre.face, c[0].hit.face, c[1].hit.face, c[2].hit.face };
  for (int j = 0; j < 4; ++j)
  {
    const int face = candidates[j];
    if (j > 0 &&
      (face == candidates[0] || (j > 1 && face == candidates[1]) ||
        (j > 2 && face == candidates[2])))
      continue; // tried already
    // dist(x, T) <= max over the corners (convexity).
    double bound = 0.0;
    for (int i = 0; i < 3 && bound < limit; ++i)
      bound = std::max(
        bound, c[i].hit.face == face ? c[i].hit.distance : TriangleDistance(mesh, c[i].x, face));
    if (bound < limit)
      return true;
  }
  if (levels <= 0)
    return false;
  auto corner = [&](const Vec3& x) { return Corner{ x, queries.ClosestWithin(x, radius) }; };
  const Corner m01 = corner(0.5 * (c[0].x + c[1].x)), m12 = corner(0.5 * (c[1].x + c[2].x)),
               m20 = corner(0.5 * (c[2].x + c[0].x));
  for (const std::array<Corner, 3>& child : { std::array<Corner, 3>{ c[0], m01, m20 },
         std::array<Corner, 3>{ m01, c[1], m12 },
         std::array<Corner, 3>{ m20, m12, c[2] },
         std::array<Corner, 3>{ m12, m20, m01 } })
    if (!Within(mesh, queries, child, limit, radius, levels - 1))
      return false;
  return true;
}
}

std::vector<char> MirroredFacesWithin(const PreparedMesh& mesh,
  const std::function<const ClosestFaceQuery&()>& queries,
  const Plane& plane,
  const std::vector<Triangle>& faces,
  const std::vector<Vec3>& points,
  const std::vector<double>& cornerDistance,
  const std::vector<double>& limit,
  int depth)
{
  // The quick proof: every point of a triangle is within (longest edge) / sqrt(3) of a corner.
  std::vector<char> ok(faces.size(), 0);
  ForRanges(static_cast<vtkIdType>(faces.size()),
    0,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const Triangle& t = faces[k];
        const double longest = std::sqrt(std::max({ (points[t[1]] - points[t[0]]).squaredNorm(),
          (points[t[2]] - points[t[1]]).squaredNorm(),
          (points[t[0]] - points[t[2]]).squaredNorm() }));
        ok[k] = limit[k] > 0.0 &&
          std::max({ cornerDistance[t[0]], cornerDistance[t[1]], cornerDistance[t[2]] }) +
              longest / std::sqrt(3.0) <
            limit[k];
      }
    });
  // The others: the closest triangles of their mirrored corners (once per point), then the
  // subdivision proof per face. Closest triangles beyond twice the limit are never needed.
  // The radius, the largest of those over all open faces, leaves each face's answer its own:
  // Within uses a hit (corner, midpoint, centroid) only once it found it closer than the
  // face's limit, and fails where it is not. With any radius >= the limit, ClosestFace gives
  // the same hit when the closest face is closer than the limit (the lowest (distance, id)
  // among the faces within the radius), and otherwise a hit at least the limit away or none:
  // a failure either way.
  std::vector<int> open;
  double radius = 0.0;
  std::vector<int> cornerIndex(points.size(), -1);
  std::vector<int> corners;
  for (size_t k = 0; k < faces.size(); ++k)
    if (!ok[k] && limit[k] > 0.0)
    {
      open.push_back(static_cast<int>(k));
      radius = std::max(radius, 2.0 * limit[k]);
      for (int v : faces[k])
        if (cornerIndex[v] < 0)
        {
          cornerIndex[v] = static_cast<int>(corners.size());
          corners.push_back(v);
        }
    }
  if (open.empty())
    return ok;
  const ClosestFaceQuery& closest = queries();
  std::vector<Corner> mirrored(corners.size());
  ForRanges(static_cast<vtkIdType>(corners.size()),
    0,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        mirrored[i].x = plane.Reflect(points[corners[i]]);
        mirrored[i].hit = closest.ClosestWithin(mirrored[i].x, radius);
      }
    });
  ForRanges(static_cast<vtkIdType>(open.size()),
    0,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType j = begin; j < end; ++j)
      {
        const int k = open[j];
        const std::array<Corner, 3> c = { mirrored[cornerIndex[faces[k][0]]],
          mirrored[cornerIndex[faces[k][1]]],
          mirrored[cornerIndex[faces[k][2]]] };
        ok[k] = Within(mesh, closest, c, limit[k], radius, depth);
      }
    });
  return ok;
}
}
