#include "ShrinkingMirrorBudget.h"

#include "ParallelTasks.h"

#include <algorithm>

namespace foldingmeshes
{
ShrinkingMirrorBudget::ShrinkingMirrorBudget(const std::vector<Vec3>& points,
  const std::vector<double>& budget,
  const Plane& plane,
  double eps)
  : Points(points)
  , Budget(budget)
  , Mirror(plane)
  , Eps(eps)
{
}

std::vector<double> ShrinkingMirrorBudget::Limits(const std::vector<int>& ids)
{
  if (this->Region.empty() || !this->Shrinks(ids))
    this->Start(ids);
  else
    this->Shrink(ids);
  double least = this->Eps;
  for (int v : ids)
    least = std::min(least, this->Budget[v]);
  std::vector<double> limit(ids.size());
  for (size_t k = 0; k < ids.size(); ++k)
  {
    const int v = ids[k], p = this->Partner[v];
    limit[k] = std::min({ this->Eps, this->Budget[v], p >= 0 ? this->Budget[p] : least });
  }
  return limit;
}

void ShrinkingMirrorBudget::Start(const std::vector<int>& ids)
{
  this->Search = std::make_unique<PointKdTree>(this->Points, ids);
  this->Region = ids;
  this->InRegion.assign(this->Points.size(), 0);
  for (int v : ids)
    this->InRegion[v] = 1;
  this->Partner.assign(this->Points.size(), -1);
  // Every point alone (a read-only tree): the same partners for any thread count.
  ForRanges(static_cast<vtkIdType>(ids.size()),
    256,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType k = first; k < last; ++k)
      {
        const int v = ids[k];
        this->Partner[v] =
          this->Search->NearestWithin(this->Mirror.Reflect(this->Points[v]), this->Eps);
      }
    });
}

bool ShrinkingMirrorBudget::Shrinks(const std::vector<int>& ids) const
{
  return std::all_of(ids.begin(), ids.end(), [&](int v) { return this->InRegion[v] != 0; });
}

void ShrinkingMirrorBudget::Shrink(const std::vector<int>& ids)
{
  for (int v : this->Region)
    this->InRegion[v] = 0;
  for (int v : ids)
    this->InRegion[v] = 1;
  this->Region = ids;
  std::vector<int> lost;
  for (int v : ids)
    if (this->Partner[v] >= 0 && !this->InRegion[this->Partner[v]])
      lost.push_back(v);
  ForRanges(static_cast<vtkIdType>(lost.size()),
    64,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType k = first; k < last; ++k)
        this->Partner[lost[k]] = this->PartnerInRegion(lost[k]);
    });
}

int ShrinkingMirrorBudget::PartnerInRegion(int v) const
{
  return this->Search->NearestWithinWhere(this->Mirror.Reflect(this->Points[v]),
    this->Eps,
    [this](int p) { return this->InRegion[p] != 0; });
}
}
