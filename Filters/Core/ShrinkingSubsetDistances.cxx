#include "ShrinkingSubsetDistances.h"

#include "SubsetPreparation.h"

#include <cstring>
#include <limits>

namespace foldingmeshes
{
namespace
{
/// Equal bit for bit (== would take -0 for 0).
bool SameBits(const Vec3& a, const Vec3& b)
{
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

/// The elements of two vectors equal bit for bit.
template <typename T>
bool SameElements(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() &&
    (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// What MirrorDistance reads of a mesh, equal bit for bit in `a` and `b`.
bool SameQueryInput(const PreparedMesh& a, const PreparedMesh& b)
{
  return SameElements(a.points, b.points) && SameElements(a.triangles, b.triangles) &&
    SameElements(a.faceDegenerate, b.faceDegenerate) &&
    SameElements(a.vertexNormals, b.vertexNormals) && SameElements(a.faceNormals, b.faceNormals) &&
    SameElements(a.faceCentroids, b.faceCentroids);
}
}

ShrinkingSubsetDistances::ShrinkingSubsetDistances(const PreparedMesh& mesh,
  const Plane& plane,
  double compatibilityAngleDegrees,
  double maxDistance,
  const FaceEdgeUses* edgeUses)
  : Mesh(mesh)
  , Mirror(plane)
  , CompatibilityAngle(compatibilityAngleDegrees)
  , MaxDistance(maxDistance)
  , EdgeUses(edgeUses)
{
}

ShrinkingSubsetDistances::~ShrinkingSubsetDistances() = default;

bool ShrinkingSubsetDistances::Update(const std::vector<char>& S)
{
  if (!this->EdgeUses)
  {
    this->OwnEdgeUses.reset(new FaceEdgeUses(ComputeFaceEdgeUses(this->Mesh)));
    this->EdgeUses = this->OwnEdgeUses.get();
  }
  if (!PrepareFaceSubset(this->Mesh, S, this->Current, *this->EdgeUses))
    return false;
  // The mesh ids of the subset's faces and points, both in increasing order (as
  // PrepareFaceSubset numbers them).
  this->CurrentFaces.clear();
  std::vector<char> pointInS(this->Mesh.NumberOfPoints(), 0);
  for (int f = 0; f < this->Mesh.NumberOfFaces(); ++f)
    if (S[f])
    {
      this->CurrentFaces.push_back(f);
      for (int v : this->Mesh.triangles[f])
        pointInS[v] = 1;
    }
  this->CurrentPoints.clear();
  for (int v = 0; v < this->Mesh.NumberOfPoints(); ++v)
    if (pointInS[v])
      this->CurrentPoints.push_back(v);
  if (this->Base && this->MatchesBase())
    this->ComputeChanged();
  else
    this->ComputeAll();
  return true;
}

bool ShrinkingSubsetDistances::NumberedAsMesh() const
{
  if (this->Current.NumberOfPoints() != static_cast<int>(this->CurrentPoints.size()) ||
    this->Current.NumberOfFaces() != static_cast<int>(this->CurrentFaces.size()))
    return false;
  for (int k = 0; k < this->Current.NumberOfPoints(); ++k)
    if (!SameBits(this->Current.points[k], this->Mesh.points[this->CurrentPoints[k]]))
      return false;
  return true;
}

bool ShrinkingSubsetDistances::MatchesBase() const
{
  const PreparedMesh& base = *this->Base;
  if (!this->NumberedAsMesh())
    return false;
  for (int k = 0; k < this->Current.NumberOfPoints(); ++k)
  {
    const int b = this->BasePointOf[this->CurrentPoints[k]];
    if (b < 0 || !SameBits(this->Current.vertexNormals[k], base.vertexNormals[b]))
      return false;
  }
  for (int i = 0; i < this->Current.NumberOfFaces(); ++i)
  {
    const int b = this->BaseFaceOf[this->CurrentFaces[i]];
    if (b < 0 || !this->BaseFaceInS[b] || this->Current.faceDegenerate[i] != base.faceDegenerate[b])
      return false;
    for (int c = 0; c < 3; ++c)
      if (this->BasePointOf[this->CurrentPoints[this->Current.triangles[i][c]]] !=
        base.triangles[b][c])
        return false;
  }
  return true;
}

void ShrinkingSubsetDistances::ComputeAll()
{
  ++this->NumberOfFullUpdates;
  this->BaseQueries.reset(); // it refers to the old base
  PreparedSubsetQueries adopted = std::move(this->Adopted);
  if (adopted.subset && adopted.queries && SameQueryInput(*adopted.subset, this->Current))
  {
    // The same face tree as a new one would be (it is built from these alone).
    this->Base = std::move(adopted.subset);
    this->BaseQueries = std::move(adopted.queries);
    this->BaseQueries->ResetHints(); // as a new one starts
    ++this->NumberOfAdoptedUpdates;
  }
  else
  {
    adopted.queries.reset(); // it refers to adopted.subset
    this->Base = std::make_unique<PreparedMesh>(this->Current);
    this->BaseQueries = std::make_unique<MirrorDistance>(*this->Base, this->CompatibilityAngle);
  }
  this->BaseQueries->Compute(this->Mirror,
    DistanceMetric::Fine,
    this->MaxDistance,
    this->BaseDistance,
    nullptr,
    nullptr,
    &this->BaseClosest);
  this->CurrentDistance = this->BaseDistance;
  // No mesh point or face in a base numbered otherwise: no later S can match it.
  this->BasePointOf.assign(this->Mesh.NumberOfPoints(), -1);
  this->BaseFaceOf.assign(this->Mesh.NumberOfFaces(), -1);
  this->BaseFaceInS.assign(this->Current.NumberOfFaces(), 1);
  if (!this->NumberedAsMesh())
    return;
  for (size_t k = 0; k < this->CurrentPoints.size(); ++k)
    this->BasePointOf[this->CurrentPoints[k]] = static_cast<int>(k);
  for (size_t i = 0; i < this->CurrentFaces.size(); ++i)
    this->BaseFaceOf[this->CurrentFaces[i]] = static_cast<int>(i);
}

void ShrinkingSubsetDistances::ComputeChanged()
{
  const PreparedMesh& base = *this->Base;
  std::vector<char> left(base.NumberOfFaces(), 1); // not in S: excluded from the queries
  for (int f : this->CurrentFaces)
    left[this->BaseFaceOf[f]] = 0;
  this->BaseFaceInS.assign(base.NumberOfFaces(), 0);
  for (int b = 0; b < base.NumberOfFaces(); ++b)
    this->BaseFaceInS[b] = !left[b];
  // Only the vertices of non-degenerate faces are queried (MirrorDistance): the others are
  // infinitely far, whatever their closest face was.
  std::vector<char> used(this->Current.NumberOfPoints(), 0);
  for (int i = 0; i < this->Current.NumberOfFaces(); ++i)
    if (!this->Current.faceDegenerate[i])
      for (int k : this->Current.triangles[i])
        used[k] = 1;
  std::vector<int> again;
  for (int k = 0; k < this->Current.NumberOfPoints(); ++k)
  {
    const int b = this->BasePointOf[this->CurrentPoints[k]];
    if (!used[k])
    {
      this->BaseDistance[b] = std::numeric_limits<double>::infinity();
      this->BaseClosest[b] = -1;
    }
    else if (this->BaseClosest[b] >= 0 && left[this->BaseClosest[b]])
      again.push_back(b);
  }
  this->BaseQueries->Recompute(
    this->Mirror, this->MaxDistance, again, left, this->BaseDistance, this->BaseClosest);
  this->CurrentDistance.resize(this->CurrentPoints.size());
  for (size_t k = 0; k < this->CurrentPoints.size(); ++k)
    this->CurrentDistance[k] = this->BaseDistance[this->BasePointOf[this->CurrentPoints[k]]];
}
}
