// MirroredFacesWithin over calls that mostly repeat faces (Builder::Trim's loop).
#ifndef foldingmeshes_MirroredFaceCache_h
#define foldingmeshes_MirroredFaceCache_h

#include "MirroredFaceBound.h"

#include <array>
#include <functional>
#include <vector>

namespace foldingmeshes
{
/**
 * MirroredFacesWithin with one mesh, query, plane and depth for faces that keep an identity
 * (a key, e.g. their id in the node's region) from call to call - Builder::Trim's iterations
 * over a shrinking region, where most faces keep their corners, corner distances and limit.
 *
 * A face's answer depends on nothing else (see MirroredFacesWithin: not on the other faces
 * tested with it), so a face whose corners (in order), corner distances and limit are bit for
 * bit those of its key's last test gets that answer again without a test.
 */
class MirroredFaceCache
{
public:
  MirroredFaceCache(const PreparedMesh& mesh,
    std::function<const ClosestFaceQuery&()> queries,
    const Plane& plane,
    int depth);

  /// MirroredFacesWithin(mesh, queries, plane, faces, points, cornerDistance, limit, depth), with
  /// keys[k] (>= 0) the identity of faces[k].
  std::vector<char> Within(const std::vector<int>& keys,
    const std::vector<Triangle>& faces,
    const std::vector<Vec3>& points,
    const std::vector<double>& cornerDistance,
    const std::vector<double>& limit);

private:
  /// The inputs of a face's last test and its answer.
  struct Entry
  {
    bool tested = false;
    char within = 0;
    std::array<Vec3, 3> corners;
    std::array<double, 3> cornerDistance;
    double limit = 0.0;
  };
  /// Entry e holds the answer for these inputs.
  static bool Holds(const Entry& e,
    const std::array<Vec3, 3>& corners,
    const std::array<double, 3>& cornerDistance,
    double limit);

  const PreparedMesh& Mesh;
  const std::function<const ClosestFaceQuery&()> Queries;
  const Plane Mirror;
  const int Depth;
  std::vector<Entry> Entries; ///< per key
};
}

#endif
