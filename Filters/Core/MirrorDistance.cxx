#include "MirrorDistance.h"

#include "ParallelTasks.h"

#include <algorithm>
#include <cmath>

namespace foldingmeshes
{
MirrorDistance::MirrorDistance(const PreparedMesh& mesh, double compatibilityAngleDegrees)
  : MirrorDistance(mesh, mesh, compatibilityAngleDegrees)
{
}

MirrorDistance::MirrorDistance(const PreparedMesh& query,
  const PreparedMesh& target,
  double compatibilityAngleDegrees)
  : Mesh(query)
  , OwnedFaces(std::make_unique<FaceTree>(target))
  , Faces(*OwnedFaces)
  , Target(target)
  , CosLimit(std::cos(compatibilityAngleDegrees * 3.14159265358979323846 / 180.0))
{
  this->MarkUsedVertices();
}

MirrorDistance::MirrorDistance(const PreparedMesh& query,
  const FaceTree& targetFaces,
  double compatibilityAngleDegrees)
  : Mesh(query)
  , Faces(targetFaces)
  , Target(targetFaces.Surface())
  , CosLimit(std::cos(compatibilityAngleDegrees * 3.14159265358979323846 / 180.0))
{
  this->MarkUsedVertices();
}

void MirrorDistance::MarkUsedVertices()
{
  this->VertexUsed.assign(this->Mesh.NumberOfPoints(), 0);
  for (int f = 0; f < this->Mesh.NumberOfFaces(); ++f)
    if (!this->Mesh.faceDegenerate[f])
      for (int v : this->Mesh.triangles[f])
        this->VertexUsed[v] = 1;
  this->LastFace.assign(this->Mesh.NumberOfPoints(), -1);
}

void MirrorDistance::Compute(const Plane& plane,
  DistanceMetric metric,
  double maxDistance,
  std::vector<double>& d,
  std::vector<Vec3>* closest,
  std::vector<Vec3>* closestNormals,
  std::vector<int>* closestFaces,
  std::vector<int>* hints) const
{
  const int nv = Mesh.NumberOfPoints();
  if (hints && static_cast<int>(hints->size()) != nv)
    hints->assign(nv, -1);
  std::vector<int>& lastFace = hints ? *hints : this->LastFace;
  // Every entry is (re)set in the parallel loop: vectors reused across calls are not
  // cleared serially first.
  d.resize(nv);
  if (closest)
    closest->resize(nv);
  if (closestNormals)
    closestNormals->resize(nv);
  if (closestFaces)
    closestFaces->resize(nv);
  ForRanges(nv,
    256,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        d[i] = std::numeric_limits<double>::infinity();
        if (closest)
          (*closest)[i] = Vec3::Zero();
        if (closestNormals)
          (*closestNormals)[i] = Vec3::Zero();
        if (closestFaces)
          (*closestFaces)[i] = -1;
        if (!VertexUsed[i])
          continue;
        const Vec3 r = plane.Reflect(Mesh.points[i]);
        const Vec3 rn = plane.ReflectDirection(Mesh.vertexNormals[i]);
        if (metric == DistanceMetric::Fine)
        {
          // The previous answer for this vertex (a nearby plane, usually the same face)
          // speeds the search up without changing its result.
          // With the fast path, a compatible closest face (of any normal) bounds the search:
          // the tree then only confirms it among the faces as close, so that ties and
          // rounding are decided as without it (bit for bit the same answers).
          FaceTree::Hit plain;
          const bool bounded = this->FastPath &&
            Faces.CompatibleFaceHit(r,
              rn,
              CosLimit,
              maxDistance,
              this->FastPath->ClosestWithin(r, maxDistance).face,
              plain);
          const FaceTree::Hit hit = bounded
            ? Faces.ClosestCompatibleFace(
                r, rn, CosLimit, std::min(maxDistance, plain.distance * (1.0 + 1e-12)), plain.face)
            : Faces.ClosestCompatibleFace(r, rn, CosLimit, maxDistance, lastFace[i]);
          if (hit.face >= 0)
            lastFace[i] = hit.face;
          d[i] = hit.distance;
          if (closest)
            (*closest)[i] = hit.point;
          if (closestNormals && hit.face >= 0)
            (*closestNormals)[i] = Target.faceNormals[hit.face];
          if (closestFaces)
            (*closestFaces)[i] = hit.face;
        }
        else
        {
          const int f = Faces.NearestCentroidFace(r);
          if (f >= 0 && Target.faceNormals[f].dot(rn) > 0.0)
          {
            const double h = Target.faceNormals[f].dot(r - Target.faceCentroids[f]);
            d[i] = std::abs(h);
            if (closest)
              (*closest)[i] = r - h * Target.faceNormals[f];
            if (closestNormals)
              (*closestNormals)[i] = Target.faceNormals[f];
            if (closestFaces)
              (*closestFaces)[i] = f;
          }
        }
      }
    });
}

void MirrorDistance::Recompute(const Plane& plane,
  double maxDistance,
  const std::vector<int>& vertices,
  const std::vector<char>& excludedFaces,
  std::vector<double>& d,
  std::vector<int>& closestFaces) const
{
  ForRanges(static_cast<vtkIdType>(vertices.size()),
    64,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const int i = vertices[k];
        const Vec3 r = plane.Reflect(Mesh.points[i]);
        const Vec3 rn = plane.ReflectDirection(Mesh.vertexNormals[i]);
        const FaceTree::Hit hit =
          Faces.ClosestCompatibleFace(r, rn, CosLimit, maxDistance, LastFace[i], &excludedFaces);
        if (hit.face >= 0)
          LastFace[i] = hit.face;
        d[i] = hit.distance;
        closestFaces[i] = hit.face;
      }
    });
}
}
