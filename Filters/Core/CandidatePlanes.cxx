#include "CandidatePlanes.h"

#include <Eigen/Eigenvalues>

#include "ParallelTasks.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace foldingmeshes
{
namespace
{
/// The three planes through m perpendicular to the eigenvectors of the covariance c.
void PlanesOfCovariance(const Vec3& m, const Eigen::Matrix3d& c, std::array<Plane, 3>& planes)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(c);
  for (int k = 0; k < 3; ++k)
  {
    Plane p;
    p.origin = m;
    p.normal = solver.eigenvectors().col(k).normalized();
    planes[k] = CanonicalPlane(p, m);
  }
}
}

bool PrincipalPlanes(const PreparedMesh& mesh,
  const std::vector<double>& weights,
  std::array<Plane, 3>& planes)
{
  double s = 0.0;
  Vec3 m = Vec3::Zero();
  for (int i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    s += weights[i];
    m += weights[i] * mesh.points[i];
  }
  if (!(s > 0.0))
    return false;
  m /= s;
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  for (int i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    if (weights[i] > 0.0)
    {
      const Vec3 r = mesh.points[i] - m;
      c += weights[i] * r * r.transpose();
    }
  }
  c /= s;
  PlanesOfCovariance(m, c, planes);
  return true;
}

bool RefinePlaneFromCorrespondences(const std::vector<Vec3>& points,
  const std::vector<Vec3>& partners,
  const std::vector<Vec3>& partnerNormals,
  const std::vector<double>& weights,
  const Plane& current,
  Plane& plane)
{
  const Vec3 n = current.normal;
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);
  Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
  Vec3 jte = Vec3::Zero();
  double s = 0.0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    if (!(weights[i] > 0.0))
      continue;
    const Vec3 p = points[i] - current.origin;
    const Vec3& m = partnerNormals[i];
    const double h = n.dot(p);
    const Vec3 r = p - 2.0 * h * n;
    const double e = (r - (partners[i] - current.origin)).dot(m);
    const double nm = n.dot(m);
    const Vec3 j(
      -2.0 * (u.dot(p) * nm + h * u.dot(m)), -2.0 * (v.dot(p) * nm + h * v.dot(m)), 2.0 * nm);
    jtj += weights[i] * j * j.transpose();
    jte += weights[i] * e * j;
    s += weights[i];
  }
  if (!(s > 0.0) || !(jtj.trace() > 0.0))
    return false;
  // Light damping keeps directions the data does not constrain (e.g. a sphere) still.
  const Eigen::Matrix3d damped = jtj + 1e-9 * jtj.trace() * Eigen::Matrix3d::Identity();
  Vec3 x = damped.ldlt().solve(-jte);
  if (!x.allFinite())
    return false;
  const double tilt = std::hypot(x[0], x[1]);
  const double maxTilt = 10.0 * 3.14159265358979323846 / 180.0;
  if (tilt > maxTilt)
  {
    x[0] *= maxTilt / tilt;
    x[1] *= maxTilt / tilt;
  }
  plane.normal = (n + x[0] * u + x[1] * v).normalized();
  plane.origin = current.origin + x[2] * n;
  return true;
}

bool SurfacePrincipalPlanes(const PreparedMesh& mesh, std::array<Plane, 3>& planes)
{
  return SurfacePrincipalPlanes(mesh, std::vector<char>(mesh.NumberOfFaces(), 1), planes);
}

namespace
{
/// The area-weighted mean (about `center`) and covariance of the surface of the triangles
/// `use` accepts, each of area `areaOf(f)`, by exact triangle integrals about `center` (about
/// the world origin, far-away meshes would lose the covariance to cancellation). False
/// without area.
template <class Use, class AreaOf>
bool SurfaceCovariance(const std::vector<Vec3>& points,
  const std::vector<Triangle>& triangles,
  const Vec3& center,
  Use use,
  AreaOf areaOf,
  Vec3& mean,
  Eigen::Matrix3d& covariance)
{
  double area = 0.0;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (size_t f = 0; f < triangles.size(); ++f)
  {
    if (!use(f))
      continue;
    const double a = areaOf(f);
    if (!(a > 0.0))
      continue;
    const Triangle& t = triangles[f];
    const Vec3 p = points[t[0]] - center, q = points[t[1]] - center, r = points[t[2]] - center;
    const Vec3 s = p + q + r;
    area += a;
    first += a * s / 3.0;
    // Integral of x x^T over the triangle: A/12 (p p^T + q q^T + r r^T + s s^T).
    second +=
      a / 12.0 * (p * p.transpose() + q * q.transpose() + r * r.transpose() + s * s.transpose());
  }
  if (!(area > 0.0))
    return false;
  mean = first / area;
  covariance = second / area - mean * mean.transpose();
  return true;
}
}

bool SurfacePrincipalPlanes(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  std::array<Plane, 3>& planes)
{
  const Vec3 center = 0.5 * (mesh.boundsMin + mesh.boundsMax);
  Vec3 mc;
  Eigen::Matrix3d c;
  if (!SurfaceCovariance(
        mesh.points,
        mesh.triangles,
        center,
        [&](size_t f) { return faceMask[f] != 0; },
        [&](size_t f) { return mesh.faceAreas[f]; },
        mc,
        c))
    return false;
  PlanesOfCovariance(mc + center, c, planes);
  return true;
}

bool AxiallySymmetricSecondMoments(const TriangleMesh& mesh, double relativeGap)
{
  if (mesh.points.empty())
    return false;
  Vec3 lo = mesh.points[0], hi = mesh.points[0];
  for (const Vec3& p : mesh.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Vec3 mean;
  Eigen::Matrix3d c;
  const auto area = [&](size_t f)
  {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.points[t[0]];
    return 0.5 * (mesh.points[t[1]] - a).cross(mesh.points[t[2]] - a).norm();
  };
  if (!SurfaceCovariance(
        mesh.points, mesh.triangles, 0.5 * (lo + hi), [](size_t) { return true; }, area, mean, c))
    return false;
  const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c).eigenvalues();
  if (!(e[2] > 0.0))
    return false;
  // Each pair against the larger of the two (against the largest of all, the two small
  // eigenvalues of any long, thin shape would agree).
  return (e[1] > 0.0 && e[1] - e[0] <= relativeGap * e[1]) || e[2] - e[1] <= relativeGap * e[2];
}

namespace
{
/// Votes wanted, and pairs drawn at most to get them.
constexpr int WantedVotes = 4000, VoteAttempts = 400000;
/// A pair votes when its normals mirror into each other within this angle (degrees).
constexpr double PairAngle = 25.0;
/// Votes within this angle (degrees) and epsilon of each other support each other.
constexpr double ClusterAngle = 4.0;
/// A chosen plane uses up the votes within this angle (degrees) and 3 epsilon.
constexpr double SeparationAngle = 10.0;
/// A cluster must have at least this weight of votes to give a plane.
constexpr double MinimumClusterWeight = 3.0;

double Cosine(double degrees)
{
  return std::cos(degrees * 3.14159265358979323846 / 180.0);
}

/// A pair's plane (unit normal, offset from the bounding-box centre) and its weight.
struct Vote
{
  Vec3 normal;
  double offset;
  double weight;
};

bool NearVote(const Vote& u, const Vote& v, double cosLimit, double offsetLimit)
{
  const double c = u.normal.dot(v.normal);
  if (std::abs(c) < cosLimit)
    return false;
  const double vo = c < 0 ? -v.offset : v.offset;
  return std::abs(u.offset - vo) <= offsetLimit;
}

/// A discrete mean normal curvature per vertex (in parallel: each vertex alone).
std::vector<double> VertexCurvatures(const PreparedMesh& mesh)
{
  const int nv = mesh.NumberOfPoints();
  std::vector<double> curvature(nv, 0.0);
  ForRanges(nv,
    1024,
    [&](vtkIdType first, vtkIdType last)
    {
      for (int v = static_cast<int>(first); v < static_cast<int>(last); ++v)
      {
        double sum = 0.0;
        int n = 0;
        for (int k = mesh.vertexFaceOffsets[v]; k < mesh.vertexFaceOffsets[v + 1]; ++k)
          for (int w : mesh.triangles[mesh.vertexFaces[k]])
          {
            const Vec3 e = mesh.points[v] - mesh.points[w];
            const double len2 = e.squaredNorm();
            if (w == v || !(len2 > 0.0))
              continue;
            sum += (mesh.vertexNormals[v] - mesh.vertexNormals[w]).dot(e) / len2;
            ++n;
          }
        curvature[v] = n > 0 ? sum / n : 0.0;
      }
    });
  return curvature;
}

/**
 * The votes of vertex pairs (p, q) whose normals mirror into each other: p sampled by area,
 * q mostly among vertices of similar curvature (mirror images have the same: within a
 * window of p's curvature rank), one vote in four with a q sampled by area.
 */
std::vector<Vote> CastVotes(const PreparedMesh& mesh, double epsilon, unsigned seed)
{
  const int nv = mesh.NumberOfPoints();
  // Area-weighted vertex sampling.
  std::vector<double> cumulative(nv);
  double total = 0.0;
  for (int i = 0; i < nv; ++i)
    cumulative[i] = (total += mesh.vertexAreas[i]);
  std::mt19937 random(seed);
  auto sample = [&]()
  {
    const double u = (static_cast<double>(random()) + 0.5) / 4294967296.0 * total;
    return static_cast<int>(std::min<std::ptrdiff_t>(
      std::lower_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin(), nv - 1));
  };
  const std::vector<double> curvature = VertexCurvatures(mesh);
  std::vector<int> byCurvature(nv), rank(nv);
  for (int v = 0; v < nv; ++v)
    byCurvature[v] = v;
  std::sort(byCurvature.begin(),
    byCurvature.end(),
    [&](int a, int b)
    { return curvature[a] != curvature[b] ? curvature[a] < curvature[b] : a < b; });
  for (int r = 0; r < nv; ++r)
    rank[byCurvature[r]] = r;
  const int window = std::max(8, nv / 100);
  auto similar = [&](int a)
  {
    const int lo = std::max(0, rank[a] - window), hi = std::min(nv - 1, rank[a] + window);
    return byCurvature[lo + static_cast<int>(random() % static_cast<unsigned>(hi - lo + 1))];
  };

  std::vector<Vote> votes;
  const double pairCos = Cosine(PairAngle);
  const Vec3 center = 0.5 * (mesh.boundsMin + mesh.boundsMax);
  for (int k = 0; k < VoteAttempts && static_cast<int>(votes.size()) < WantedVotes; ++k)
  {
    const int a = sample();
    const int b = (k % 4 == 3) ? sample() : similar(a);
    const Vec3 ab = mesh.points[a] - mesh.points[b];
    const double len = ab.norm();
    if (len < epsilon)
      continue;
    Plane p;
    p.normal = ab / len;
    p.origin = 0.5 * (mesh.points[a] + mesh.points[b]);
    if (p.ReflectDirection(mesh.vertexNormals[a]).dot(mesh.vertexNormals[b]) < pairCos)
      continue;
    p = CanonicalPlane(p, center);
    votes.push_back({ p.normal, p.normal.dot(p.origin - center), 1.0 });
  }
  return votes;
}

/**
 * Per vote, the weight of the votes near it (itself included; NearVote within ClusterAngle
 * and epsilon). NearVote needs the offsets within epsilon (or opposite within epsilon, for
 * opposite normals): only the votes in two offset windows of the votes sorted by offset are
 * tested. In parallel: each vote alone.
 */
std::vector<double> ClusterStrengths(const std::vector<Vote>& votes, double epsilon)
{
  const double clusterCos = Cosine(ClusterAngle);
  const int nvotes = static_cast<int>(votes.size());
  std::vector<int> byOffset(nvotes);
  for (int i = 0; i < nvotes; ++i)
    byOffset[i] = i;
  std::sort(byOffset.begin(),
    byOffset.end(),
    [&](int a, int b)
    { return votes[a].offset != votes[b].offset ? votes[a].offset < votes[b].offset : a < b; });
  std::vector<double> sortedOffsets(nvotes);
  for (int k = 0; k < nvotes; ++k)
    sortedOffsets[k] = votes[byOffset[k]].offset;
  auto offsetWindow = [&](double center)
  {
    const auto lo = std::lower_bound(sortedOffsets.begin(), sortedOffsets.end(), center - epsilon);
    const auto hi = std::upper_bound(sortedOffsets.begin(), sortedOffsets.end(), center + epsilon);
    return std::make_pair(
      static_cast<int>(lo - sortedOffsets.begin()), static_cast<int>(hi - sortedOffsets.begin()));
  };
  std::vector<double> strength(nvotes, 0.0);
  ForRanges(nvotes,
    64,
    [&](vtkIdType first, vtkIdType last)
    {
      for (int i = static_cast<int>(first); i < static_cast<int>(last); ++i)
      {
        const auto same = offsetWindow(votes[i].offset);
        const auto opposite = offsetWindow(-votes[i].offset);
        for (int k = same.first; k < same.second; ++k)
          if (NearVote(votes[i], votes[byOffset[k]], clusterCos, epsilon))
            strength[i] += votes[byOffset[k]].weight;
        for (int k = opposite.first; k < opposite.second; ++k)
          if ((k < same.first || k >= same.second) &&
            NearVote(votes[i], votes[byOffset[k]], clusterCos, epsilon))
            strength[i] += votes[byOffset[k]].weight;
      }
    });
  return strength;
}
}

std::vector<Plane> VotedPlanes(const PreparedMesh& mesh, int count, double epsilon, unsigned seed)
{
  std::vector<Plane> result;
  if (count <= 0 || mesh.NumberOfPoints() < 2)
    return result;
  // The per-vertex and per-vote loops run in parallel (ForRanges): each element is computed
  // alone, in a fixed order, so the result does not depend on the thread count.
  const std::vector<Vote> votes = CastVotes(mesh, epsilon, seed);
  const std::vector<double> strength = ClusterStrengths(votes, epsilon);
  // The strongest cluster not used up yet, one plane at a time: the mean of its votes.
  const int nvotes = static_cast<int>(votes.size());
  const double clusterCos = Cosine(ClusterAngle), separationCos = Cosine(SeparationAngle);
  const Vec3 center = 0.5 * (mesh.boundsMin + mesh.boundsMax);
  std::vector<char> used(nvotes, 0);
  while (static_cast<int>(result.size()) < count)
  {
    int best = -1;
    for (int i = 0; i < nvotes; ++i)
      if (!used[i] && (best < 0 || strength[i] > strength[best]))
        best = i;
    if (best < 0 || strength[best] < MinimumClusterWeight)
      break;
    Vec3 n = Vec3::Zero();
    double offset = 0.0, weight = 0.0;
    for (int j = 0; j < nvotes; ++j)
    {
      if (NearVote(votes[best], votes[j], clusterCos, epsilon))
      {
        const double sgn = votes[best].normal.dot(votes[j].normal) < 0 ? -1.0 : 1.0;
        n += sgn * votes[j].normal;
        offset += sgn * votes[j].offset;
        weight += 1.0;
      }
    }
    for (int j = 0; j < nvotes; ++j)
      if (!used[j] && NearVote(votes[best], votes[j], separationCos, 3.0 * epsilon))
        used[j] = 1;
    used[best] = 1;
    Plane p;
    p.normal = n.normalized();
    p.origin = center + (offset / weight) * p.normal;
    result.push_back(CanonicalPlane(p, center));
  }
  return result;
}
}
