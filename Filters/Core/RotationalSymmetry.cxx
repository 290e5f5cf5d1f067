#include "RotationalSymmetry.h"

#include "CandidatePlanes.h"
#include "ParallelTasks.h"
#include "RobustCost.h"
#include "RotationOrderScan.h"
#include "SymmetryDetection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace foldingmeshes
{
using namespace rotation_detail;
namespace
{
/// Vertices of the scan's sample (at most), spread over the vertex ids.
constexpr int ScanSampleSize = 600;
/// Vertices the axis fit uses (at most).
constexpr int FitSampleSize = 1000;
/// A phase of the axis fit (sigma 3 epsilon, then epsilon) stops when a step tilts the axis
/// less than this (radians) and shifts it less than this many diagonals, or after half the
/// iterations.
constexpr double ConvergedStep[2] = { 1e-4, 1e-6 };
/// Two candidate axes closer than this (degrees, and epsilon at the centroid) are one.
constexpr double SameAxisDegrees = 1.0;
/// Mirror planes closer in angle than this (degrees) do not make a candidate axis.
constexpr double PlanePairMinimumDegrees = 2.0;
/// Gauss-Newton limits per step: tilt of the axis (radians) and shift (diagonals).
constexpr double MaximumTiltStep = 10.0 * Pi / 180.0;
constexpr double MaximumShiftStep = 0.05;
/// Candidate axes refined before giving up, and fits in all.
constexpr int RefinedCandidates = 3;
constexpr int MaximumFits = 3;
/// Parts (largest first) whose own principal axes are candidates.
constexpr int MaximumPartsWithAxes = 4;

/// Candidate axes: the surface's principal axes through its area centroid, and the lines
/// where two mirror planes meet; duplicates dropped.
std::vector<RotationAxis> CandidateAxes(const PreparedMesh& mesh, const RotationOptions& options)
{
  std::vector<RotationAxis> axes;
  Vec3 centroid = 0.5 * (mesh.boundsMin + mesh.boundsMax);
  std::array<Plane, 3> principal;
  if (SurfacePrincipalPlanes(mesh, principal))
  {
    centroid = principal[0].origin;
    // Largest eigenvalue last: the long axis of a chess piece or a bolt is tried first.
    for (int k = 2; k >= 0; --k)
      axes.push_back({ principal[k].origin, principal[k].normal });
  }
  // Each large part's own axes: an attached separate part (a handle, a box) tilts and moves
  // the whole surface's axes, not those of the symmetric part.
  std::vector<double> partArea(mesh.numberOfParts, 0.0);
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    partArea[mesh.facePart[f]] += mesh.faceAreas[f];
  std::vector<int> parts(mesh.numberOfParts);
  std::iota(parts.begin(), parts.end(), 0);
  std::stable_sort(
    parts.begin(), parts.end(), [&](int a, int b) { return partArea[a] > partArea[b]; });
  for (size_t i = 0; i < parts.size() && i < static_cast<size_t>(MaximumPartsWithAxes); ++i)
  {
    if (mesh.numberOfParts < 2 ||
      partArea[parts[i]] < options.minimumSymmetricAreaFraction * mesh.totalArea)
      break;
    std::vector<char> mask(mesh.NumberOfFaces(), 0);
    for (int f = 0; f < mesh.NumberOfFaces(); ++f)
      mask[f] = mesh.facePart[f] == parts[i];
    if (SurfacePrincipalPlanes(mesh, mask, principal))
      for (int k = 2; k >= 0; --k)
        axes.push_back({ principal[k].origin, principal[k].normal });
  }
  const auto& planes = options.mirrorPlanes;
  for (size_t a = 0; a < planes.size(); ++a)
    for (size_t b = a + 1; b < planes.size(); ++b)
    {
      if (PlaneAngleDegrees(planes[a], planes[b]) < PlanePairMinimumDegrees)
        continue;
      const Vec3 direction = planes[a].normal.cross(planes[b].normal).normalized();
      // The point of both planes nearest to the centroid: minimise |x - c| subject to the
      // two plane equations and x . direction = c . direction.
      Eigen::Matrix3d m;
      m.row(0) = planes[a].normal.transpose();
      m.row(1) = planes[b].normal.transpose();
      m.row(2) = direction.transpose();
      const Vec3 rhs(planes[a].normal.dot(planes[a].origin),
        planes[b].normal.dot(planes[b].origin),
        direction.dot(centroid));
      const Vec3 origin = m.colPivHouseholderQr().solve(rhs);
      if (origin.allFinite() && direction.allFinite())
        axes.push_back({ origin, direction });
    }
  std::vector<RotationAxis> distinct;
  for (const RotationAxis& axis : axes)
  {
    bool seen = false;
    for (const RotationAxis& d : distinct)
      seen = seen ||
        (AxisAngleDegrees(axis, d) < SameAxisDegrees &&
          AxisOffsetAt(d, axis, centroid) < options.epsilon);
    if (!seen)
      distinct.push_back(axis);
  }
  return distinct;
}

/// The axis moved by the Gauss-Newton parameters x: tilt (x0, x1) along the axis' basis
/// (e1, e2), shift (x2, x3) of the origin along the same.
RotationAxis MovedAxis(const RotationAxis& axis,
  const Vec3& e1,
  const Vec3& e2,
  const Eigen::Vector4d& x)
{
  RotationAxis moved;
  moved.direction = (axis.direction + x[0] * e1 + x[1] * e2).normalized();
  moved.origin = axis.origin + x[2] * e1 + x[3] * e2;
  return moved;
}

/**
 * Gauss-Newton on the axis for the turns of `order`: every sampled vertex, turned, should lie
 * on the tangent plane of its closest compatible point (numeric derivatives of the turned
 * point with respect to the four axis parameters), on the vertices `sample`. Geman-McClure
 * weights times vertex area,
 * sigma = 3 epsilon for the first half of the steps, then epsilon. Returns the steps taken.
 */
int RefineAxis(const PreparedMesh& mesh,
  const FaceTree& faces,
  const RotationOptions& options,
  const std::vector<int>& sample,
  int order,
  RotationAxis& axis)
{
  const std::vector<Turn> turns = TurnsOfOrder(order);
  const double cosLimit = std::cos(options.compatibilityAngle * Pi / 180.0);
  const double diagonal = mesh.diagonal;
  const int rows = static_cast<int>(sample.size() * turns.size());
  std::vector<FaceTree::Hit> hits(rows);
  int steps = 0;
  const int phaseSteps = std::max(1, options.maximumIterations / 2);
  for (int phase = 0; phase < 2; ++phase)
    for (int it = 0; it < phaseSteps; ++it)
    {
      const double sigma = (phase == 0 ? 3.0 : 1.0) * options.epsilon;
      const Vec3 e1 = axis.direction.unitOrthogonal();
      const Vec3 e2 = axis.direction.cross(e1);
      const double h[4] = { 1e-6, 1e-6, 1e-6 * diagonal, 1e-6 * diagonal };
      // Per turn: the turn about the axis, then about the axis moved by +h and -h in each
      // parameter (the numeric derivatives), each matrix computed once per step.
      std::vector<std::array<AxisTurn, 9>> turned;
      for (const Turn& t : turns)
      {
        const double angle = t.Angle();
        auto moved = [&](int p, double sign)
        {
          Eigen::Vector4d dx = Eigen::Vector4d::Zero();
          dx[p] = sign * h[p];
          return AxisTurn(MovedAxis(axis, e1, e2, dx), angle);
        };
        turned.push_back({ AxisTurn(axis, angle),
          moved(0, 1),
          moved(0, -1),
          moved(1, 1),
          moved(1, -1),
          moved(2, 1),
          moved(2, -1),
          moved(3, 1),
          moved(3, -1) });
      }
      ForRanges(rows,
        64,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType r = begin; r < end; ++r)
            hits[r] = TurnedHit(mesh,
              faces,
              turned[r % turns.size()][0],
              sample[r / turns.size()],
              cosLimit,
              2.0 * sigma,
              hits[r].face); // the last step's face: a hint, the same answer sooner
        });
      Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
      Eigen::Vector4d jte = Eigen::Vector4d::Zero();
      for (int r = 0; r < rows; ++r)
      {
        const FaceTree::Hit& hit = hits[r];
        if (hit.face < 0)
          continue;
        const int v = sample[r / turns.size()];
        const std::array<AxisTurn, 9>& turn = turned[r % turns.size()];
        const double w = GemanMcClureWeight(hit.distance, sigma) * mesh.vertexAreas[v];
        const Vec3& m = mesh.faceNormals[hit.face];
        const double e = m.dot(turn[0].Point(mesh.points[v]) - hit.point);
        Eigen::Vector4d j;
        for (int p = 0; p < 4; ++p)
        {
          const Vec3 plus = turn[1 + 2 * p].Point(mesh.points[v]);
          const Vec3 minus = turn[2 + 2 * p].Point(mesh.points[v]);
          j[p] = m.dot(plus - minus) / (2.0 * h[p]);
        }
        jtj += w * j * j.transpose();
        jte += w * e * j;
      }
      if (!(jtj.trace() > 0.0))
        break;
      // Scale the shifts to diagonals so that one damping fits all four parameters.
      const Eigen::Vector4d scale(1.0, 1.0, diagonal, diagonal);
      const Eigen::Matrix4d s = scale.asDiagonal();
      const Eigen::Matrix4d a = s * jtj * s;
      Eigen::Vector4d y =
        (a + 1e-9 * a.trace() * Eigen::Matrix4d::Identity()).ldlt().solve(-(s * jte));
      if (!y.allFinite())
        break;
      const double tilt = std::hypot(y[0], y[1]);
      if (tilt > MaximumTiltStep)
        y.head<2>() *= MaximumTiltStep / tilt;
      const double shift = std::hypot(y[2], y[3]);
      if (shift > MaximumShiftStep)
        y.tail<2>() *= MaximumShiftStep / shift;
      const Eigen::Vector4d x = s * y;
      axis = MovedAxis(axis, e1, e2, x);
      ++steps;
      if (tilt < ConvergedStep[phase] && shift < ConvergedStep[phase])
        break;
    }
  return steps;
}

/// The whole mesh's distances under the turns of `order`, the region and the found rule.
void EvaluateOnMesh(const PreparedMesh& mesh,
  const FaceTree& faces,
  const RotationOptions& options,
  int order,
  RotationResult& result)
{
  const std::vector<Turn> turns = TurnsOfOrder(order);
  const double cosLimit = std::cos(options.compatibilityAngle * Pi / 180.0);
  std::vector<AxisTurn> turned;
  for (const Turn& t : turns)
    turned.emplace_back(result.axis, t.Angle());
  const int n = mesh.NumberOfPoints();
  result.distance.assign(n, std::numeric_limits<double>::infinity());
  ForRanges(n,
    256,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType v = begin; v < end; ++v)
      {
        if (!(mesh.vertexAreas[v] > 0.0))
          continue;
        // The largest over the turns: a turn without a partner (infinite) settles it.
        double d = 0.0;
        for (size_t t = 0; t < turned.size() && std::isfinite(d); ++t)
          d = std::max(d,
            TurnedHit(mesh, faces, turned[t], static_cast<int>(v), cosLimit, 3.0 * options.epsilon)
              .distance);
        result.distance[v] = d;
      }
    });
  result.faceLabel.assign(mesh.NumberOfFaces(), 0);
  double area = 0.0, squares = 0.0, weights = 0.0;
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
  {
    if (mesh.faceDegenerate[f])
      continue;
    const Triangle& t = mesh.triangles[f];
    bool inside = true;
    for (int p : t)
      inside = inside && result.distance[p] <= options.epsilon;
    if (!inside)
      continue;
    result.faceLabel[f] = 1;
    area += mesh.faceAreas[f];
    for (int p : t)
    {
      squares += mesh.faceAreas[f] * result.distance[p] * result.distance[p];
      weights += mesh.faceAreas[f];
    }
  }
  result.symmetricAreaFraction = mesh.totalArea > 0.0 ? area / mesh.totalArea : 0.0;
  result.rmsResidual = weights > 0.0 ? std::sqrt(squares / weights) : 0.0;
  result.found = area > 0.0 &&
    result.symmetricAreaFraction >= options.minimumSymmetricAreaFraction &&
    result.rmsResidual <= FoundResidualRatio * options.epsilon;
}
}

RotationResult DetectRotationalSymmetry(const PreparedMesh& mesh,
  const RotationOptions& options,
  const FaceTree* meshFaces)
{
  RotationResult result;
  result.distance.assign(mesh.NumberOfPoints(), std::numeric_limits<double>::infinity());
  result.faceLabel.assign(mesh.NumberOfFaces(), 0);
  if (!(options.epsilon > 0.0) || options.maximumOrder < 2 || mesh.NumberOfFaces() == 0)
    return result;
  std::unique_ptr<FaceTree> ownTree;
  if (!meshFaces)
  {
    ownTree = std::make_unique<FaceTree>(mesh);
    meshFaces = ownTree.get();
  }
  RotationOptions clamped = options;
  clamped.maximumOrder = std::min(options.maximumOrder, 360);

  const std::vector<RotationAxis> axes = CandidateAxes(mesh, clamped);
  result.candidateAxes = static_cast<int>(axes.size());
  const std::vector<int> sample = SampleVertices(mesh, ScanSampleSize);
  std::vector<ScanEntry> scanned;
  auto report = [&](double p) { return !options.progress || options.progress(p); };
  // The scan takes about two thirds of the time, the fits the rest.
  std::vector<ScanEntry> perAxis(axes.size());
  const size_t batch = 2; // axes scanned in parallel between progress reports
  for (size_t first = 0; first < axes.size(); first += batch)
  {
    const size_t count = std::min(batch, axes.size() - first);
    RunTasksInParallel(count,
      [&](size_t i)
      {
        const size_t a = first + i;
        perAxis[a] = ScanAxis(mesh, *meshFaces, clamped, sample, static_cast<int>(a), axes[a]);
      });
    if (!report(0.65 * static_cast<double>(first + count) / axes.size()))
    {
      result.aborted = true;
      return result;
    }
  }
  for (const ScanEntry& entry : perAxis)
    if (entry.order >= 2)
      scanned.push_back(entry);
  // Most faces saved (or, rankByArea, the largest area) first; ties (within 2% of the area)
  // to the higher order, then the earlier candidate.
  const bool byArea = options.rankByArea;
  std::stable_sort(scanned.begin(),
    scanned.end(),
    [byArea](const ScanEntry& x, const ScanEntry& y)
    {
      const double a = byArea ? x.area : x.Saved(), b = byArea ? y.area : y.Saved();
      if (std::abs(a - b) > 0.02)
        return a > b;
      return x.order > y.order;
    });
  if (scanned.empty())
    return result;

  const std::vector<int> fitSample = SampleVertices(mesh, FitSampleSize);
  RotationResult best;
  bool first = true;
  int fits = 0;
  for (size_t c = 0; c < scanned.size() && c < static_cast<size_t>(RefinedCandidates); ++c)
    for (size_t o = 0; o < scanned[c].orders.size() && !best.found && fits < MaximumFits;
         ++o, ++fits)
    {
      RotationResult trial;
      trial.candidateAxes = result.candidateAxes;
      trial.order = scanned[c].orders[o];
      trial.continuous = o == 0 && scanned[c].continuous;
      trial.axis = axes[scanned[c].axis];
      trial.iterations = RefineAxis(mesh, *meshFaces, clamped, fitSample, trial.order, trial.axis);
      EvaluateOnMesh(mesh, *meshFaces, clamped, trial.order, trial);
      if (first || trial.found)
        best = std::move(trial);
      first = false;
      if (!report(0.65 + 0.35 * (fits + 1) / MaximumFits))
      {
        result.aborted = true;
        return result;
      }
    }
  // A canonical direction: largest component positive; the origin nearest the centroid.
  int k = 0;
  best.axis.direction.cwiseAbs().maxCoeff(&k);
  if (best.axis.direction[k] < 0)
    best.axis.direction = -best.axis.direction;
  const Vec3 c = 0.5 * (mesh.boundsMin + mesh.boundsMax);
  best.axis.origin += (c - best.axis.origin).dot(best.axis.direction) * best.axis.direction;
  return best;
}
}
