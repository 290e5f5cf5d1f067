#include "MirroredFaceCache.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace foldingmeshes
{
MirroredFaceCache::MirroredFaceCache(const PreparedMesh& mesh,
  std::function<const ClosestFaceQuery&()> queries,
  const Plane& plane,
  int depth)
  : Mesh(mesh)
  , Queries(std::move(queries))
  , Mirror(plane)
  , Depth(depth)
{
}

bool MirroredFaceCache::Holds(const Entry& e,
  const std::array<Vec3, 3>& corners,
  const std::array<double, 3>& cornerDistance,
  double limit)
{
  // Bit for bit (== would take -0 for 0 and never a NaN for itself: a new test then).
  return e.tested && std::memcmp(e.corners.data(), corners.data(), sizeof(corners)) == 0 &&
    std::memcmp(e.cornerDistance.data(), cornerDistance.data(), sizeof(cornerDistance)) == 0 &&
    std::memcmp(&e.limit, &limit, sizeof(limit)) == 0;
}

std::vector<char> MirroredFaceCache::Within(const std::vector<int>& keys,
  const std::vector<Triangle>& faces,
  const std::vector<Vec3>& points,
  const std::vector<double>& cornerDistance,
  const std::vector<double>& limit)
{
  std::vector<char> within(faces.size(), 0);
  std::vector<int> untested; // indices into faces
  int largestKey = -1;
  for (int key : keys)
    largestKey = std::max(largestKey, key);
  if (largestKey >= static_cast<int>(this->Entries.size()))
    this->Entries.resize(largestKey + 1); // once per growth, not once per new key
  for (size_t k = 0; k < faces.size(); ++k)
  {
    Entry& e = this->Entries[keys[k]];
    const Triangle& t = faces[k];
    const std::array<Vec3, 3> corners = { points[t[0]], points[t[1]], points[t[2]] };
    const std::array<double, 3> distances = {
      cornerDistance[t[0]], cornerDistance[t[1]], cornerDistance[t[2]]
    };
    if (Holds(e, corners, distances, limit[k]))
    {
      within[k] = e.within;
      continue;
    }
    e.tested = false;
    e.corners = corners;
    e.cornerDistance = distances;
    e.limit = limit[k];
    untested.push_back(static_cast<int>(k));
  }
  if (untested.empty())
    return within;
  std::vector<Triangle> testFaces;
  std::vector<double> testLimit;
  for (int k : untested)
  {
    testFaces.push_back(faces[k]);
    testLimit.push_back(limit[k]);
  }
  const std::vector<char> tested = MirroredFacesWithin(this->Mesh,
    this->Queries,
    this->Mirror,
    testFaces,
    points,
    cornerDistance,
    testLimit,
    this->Depth);
  for (size_t j = 0; j < untested.size(); ++j)
  {
    Entry& e = this->Entries[keys[untested[j]]];
    e.tested = true;
    e.within = tested[j];
    within[untested[j]] = tested[j];
  }
  return within;
}
}
