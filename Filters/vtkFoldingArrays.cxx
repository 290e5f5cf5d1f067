#include "vtkFoldingArrays.h"

#include <vtkAbstractArray.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <functional>

namespace foldingmeshes
{
namespace
{
bool Contains(const std::vector<std::string>& names, const std::string& name)
{
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// Whether the tuples of `a` are pairwise different.
bool AllDistinct(vtkAbstractArray* a)
{
  const vtkIdType n = a->GetNumberOfTuples();
  const int nc = a->GetNumberOfComponents();
  std::vector<std::string> keys(n);
  vtkDataArray* data = vtkDataArray::SafeDownCast(a);
  if (data && nc == 1)
  {
    std::vector<double> values(n);
    for (vtkIdType i = 0; i < n; ++i)
      values[i] = data->GetTuple1(i);
    std::sort(values.begin(), values.end());
    return std::adjacent_find(values.begin(), values.end()) == values.end();
  }
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < nc; ++c)
      keys[i] += a->GetVariantValue(i * nc + c).ToString() + '\x1f';
  std::sort(keys.begin(), keys.end());
  return std::adjacent_find(keys.begin(), keys.end()) == keys.end();
}

/// A copy of `array` named `name` sharing its values where the class allows.
vtkSmartPointer<vtkAbstractArray> Renamed(vtkAbstractArray* array, const std::string& name)
{
  vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(array->NewInstance());
  vtkDataArray* data = vtkDataArray::SafeDownCast(copy);
  if (data)
    data->ShallowCopy(vtkDataArray::SafeDownCast(array));
  else
    copy->DeepCopy(array);
  copy->SetName(name.c_str());
  return copy;
}

/**
 * Rebuilds the arrays of `fd` in order, each replaced by `replace(array)` (null: removed;
 * the array itself: kept). Active attributes of a vtkDataSetAttributes follow the arrays.
 */
void Rebuild(vtkFieldData* fd,
  const std::function<vtkSmartPointer<vtkAbstractArray>(vtkAbstractArray*)>& replace)
{
  vtkDataSetAttributes* dsa = vtkDataSetAttributes::SafeDownCast(fd);
  const int n = fd->GetNumberOfArrays();
  std::vector<vtkSmartPointer<vtkAbstractArray>> before(n), after(n);
  std::vector<int> activeOf(vtkDataSetAttributes::NUM_ATTRIBUTES, -1);
  bool changed = false;
  for (int a = 0; a < n; ++a)
  {
    before[a] = fd->GetAbstractArray(a);
    after[a] = before[a] ? replace(before[a]) : nullptr;
    changed = changed || after[a] != before[a];
  }
  if (!changed)
    return;
  if (dsa)
    for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
      if (vtkAbstractArray* active = dsa->GetAbstractAttribute(attribute))
        for (int a = 0; a < n; ++a)
          if (before[a] == active)
            activeOf[attribute] = a;
  while (fd->GetNumberOfArrays() > 0)
    fd->RemoveArray(0);
  std::vector<int> indexOf(n, -1);
  for (int a = 0; a < n; ++a)
    if (after[a])
      indexOf[a] = fd->AddArray(after[a]);
  if (dsa)
    for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
      if (activeOf[attribute] >= 0 && indexOf[activeOf[attribute]] >= 0)
        dsa->SetActiveAttribute(indexOf[activeOf[attribute]], attribute);
}
}

//------------------------------------------------------------------------------
const std::vector<std::string>& LeafPointArrayNames()
{
  static const std::vector<std::string> names = { "OriginalPointId",
    "TearMask",
    "PlaneMask",
    "Projected",
    "ErrorBudget",
    "InputBoundary",
    "InputBorderNeighbors" };
  return names;
}

const std::vector<std::string>& LeafCellArrayNames()
{
  static const std::vector<std::string> names = { "OriginalCellId", "FoldingLeafId" };
  return names;
}

const std::vector<std::string>& UnfoldedPointArrayNames()
{
  static const std::vector<std::string> names = { "OriginalPointId", "DistanceToOriginal" };
  return names;
}

const std::vector<std::string>& UnfoldedCellArrayNames()
{
  static const std::vector<std::string> names = { "OriginalCellId",
    "FoldingLeafId",
    "FoldingCopy",
    "FoldingMirrored",
    "FoldingMirrorMask",
    "FoldingFilled" };
  return names;
}

//------------------------------------------------------------------------------
std::string FreeInputName(vtkFieldData* fd,
  const std::string& name,
  const std::vector<std::string>& avoid)
{
  const std::string base = name + RenamedInputSuffix;
  std::string candidate = base;
  for (int k = 2; (fd && fd->GetAbstractArray(candidate.c_str())) || Contains(avoid, candidate);
       ++k)
    candidate = base + std::to_string(k);
  return candidate;
}

void RenameReservedArrays(vtkFieldData* fd,
  const std::vector<std::string>& reserved,
  std::vector<std::string>& notes)
{
  std::vector<std::string> taken; // new names given in this pass
  Rebuild(fd,
    [&](vtkAbstractArray* a) -> vtkSmartPointer<vtkAbstractArray>
    {
      if (!a->GetName() || !Contains(reserved, a->GetName()))
        return a;
      std::vector<std::string> avoid = reserved;
      avoid.insert(avoid.end(), taken.begin(), taken.end());
      const std::string name = FreeInputName(fd, a->GetName(), avoid);
      taken.push_back(name);
      notes.push_back(std::string(a->GetName()) + " -> " + name);
      return Renamed(a, name);
    });
}

void NameUnnamedArrays(vtkFieldData* fd, const char* prefix, std::vector<std::string>& notes)
{
  int k = 0;
  std::vector<std::string> taken;
  Rebuild(fd,
    [&](vtkAbstractArray* a) -> vtkSmartPointer<vtkAbstractArray>
    {
      if (a->GetName() && a->GetName()[0])
        return a;
      std::string name;
      do
        name = prefix + std::to_string(k++);
      while (fd->GetAbstractArray(name.c_str()) || Contains(taken, name));
      taken.push_back(name);
      notes.push_back(name);
      return Renamed(a, name);
    });
}

bool IsXMLWritable(vtkAbstractArray* array)
{
  return vtkDataArray::SafeDownCast(array) || vtkStringArray::SafeDownCast(array);
}

void RemoveUnwritableArrays(vtkFieldData* fd, std::vector<std::string>& notes)
{
  Rebuild(fd,
    [&](vtkAbstractArray* a) -> vtkSmartPointer<vtkAbstractArray>
    {
      if (IsXMLWritable(a))
        return a;
      notes.push_back(
        std::string(a->GetName() ? a->GetName() : "(unnamed)") + " (" + a->GetClassName() + ")");
      return nullptr;
    });
}

//------------------------------------------------------------------------------
void CopyTuplesById(vtkDataSetAttributes* src,
  vtkDataSetAttributes* dst,
  const vtkIdType* ids,
  vtkIdType n)
{
  vtkIdType largest = -1;
  for (vtkIdType i = 0; i < n; ++i)
    largest = std::max(largest, ids[i]);
  std::vector<int> indexOf(src->GetNumberOfArrays(), -1);
  for (int a = 0; a < src->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* in = src->GetAbstractArray(a);
    if (!in || in->GetNumberOfTuples() <= largest)
      continue;
    vtkSmartPointer<vtkAbstractArray> out = vtk::TakeSmartPointer(in->NewInstance());
    out->SetName(in->GetName());
    out->SetNumberOfComponents(in->GetNumberOfComponents());
    for (int c = 0; c < in->GetNumberOfComponents(); ++c)
      if (in->GetComponentName(c))
        out->SetComponentName(c, in->GetComponentName(c));
    out->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      out->SetTuple(i, ids[i], in);
    indexOf[a] = dst->AddArray(out);
  }
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
    if (vtkAbstractArray* active = src->GetAbstractAttribute(attribute))
      for (int a = 0; a < src->GetNumberOfArrays(); ++a)
        if (src->GetAbstractArray(a) == active && indexOf[a] >= 0)
          dst->SetActiveAttribute(indexOf[a], attribute);
}

std::vector<std::string> ActiveAttributeNames(vtkDataSetAttributes* dsa)
{
  std::vector<std::string> names(vtkDataSetAttributes::NUM_ATTRIBUTES);
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
    if (vtkAbstractArray* active = dsa->GetAbstractAttribute(attribute))
      if (active->GetName())
        names[attribute] = active->GetName();
  return names;
}
//------------------------------------------------------------------------------
vtkSmartPointer<vtkStringArray> AttributeRecord(vtkDataSetAttributes* dsa, const char* name)
{
  auto record = vtkSmartPointer<vtkStringArray>::New();
  record->SetName(name);
  // "k:name" per attribute k ("k:" for none: XML files may lose empty strings).
  const std::vector<std::string> active = ActiveAttributeNames(dsa);
  for (size_t k = 0; k < active.size(); ++k)
    record->InsertNextValue(std::to_string(k) + ":" + active[k]);
  return record;
}

void ApplyActiveAttributes(vtkDataSetAttributes* out, const std::vector<std::string>& names)
{
  for (size_t attribute = 0; attribute < names.size() &&
       attribute < static_cast<size_t>(vtkDataSetAttributes::NUM_ATTRIBUTES);
       ++attribute)
  {
    vtkAbstractArray* array =
      names[attribute].empty() ? nullptr : out->GetAbstractArray(names[attribute].c_str());
    if (!array)
      continue;
    if ((attribute == vtkDataSetAttributes::GLOBALIDS ||
          attribute == vtkDataSetAttributes::PEDIGREEIDS) &&
      !AllDistinct(array))
      continue;
    out->SetActiveAttribute(names[attribute].c_str(), static_cast<int>(attribute));
  }
}

std::vector<std::string> RecordedAttributes(vtkFieldData* info,
  const char* name,
  const std::vector<vtkPolyData*>& leaves,
  bool points)
{
  if (vtkStringArray* recorded = vtkStringArray::SafeDownCast(info->GetAbstractArray(name)))
  {
    // Entries "k:name" (AttributeRecord).
    std::vector<std::string> names(vtkDataSetAttributes::NUM_ATTRIBUTES);
    for (vtkIdType k = 0; k < recorded->GetNumberOfValues(); ++k)
    {
      const std::string entry = recorded->GetValue(k);
      const size_t colon = entry.find(':');
      if (colon == std::string::npos || colon == 0 || colon > 3 ||
        entry.find_first_not_of("0123456789") != colon)
        continue;
      const int attribute = std::stoi(entry.substr(0, colon));
      if (attribute < vtkDataSetAttributes::NUM_ATTRIBUTES)
        names[attribute] = entry.substr(colon + 1);
    }
    return names;
  }
  for (vtkPolyData* leaf : leaves)
    if (leaf)
    {
      std::vector<std::string> names = ActiveAttributeNames(points
          ? static_cast<vtkDataSetAttributes*>(leaf->GetPointData())
          : static_cast<vtkDataSetAttributes*>(leaf->GetCellData()));
      for (std::string& n : names)
        if (Contains(points ? LeafPointArrayNames() : LeafCellArrayNames(), n))
          n.clear();
      return names;
    }
  return {};
}
namespace
{
/// The builder's arrays in the leaves (read by the unfolder, not carried to the output).
bool IsTreeArray(const char* name, bool points)
{
  const std::vector<std::string>& names =
    points ? LeafPointArrayNames() : LeafCellArrayNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

}

/// Names of the arrays present in every leaf with the same type, components and size;
/// `unnamed` counts the first leaf's unnamed arrays (not carried: nothing matches them).
std::vector<std::string> CommonLeafArrays(const std::vector<vtkPolyData*>& leaves,
  bool points,
  int& unnamed)
{
  std::vector<std::string> names;
  unnamed = 0;
  vtkPolyData* first = nullptr;
  for (vtkPolyData* leaf : leaves)
    if (leaf && !first)
      first = leaf;
  if (!first)
    return names;
  auto attributes = [points](vtkPolyData* pd) -> vtkDataSetAttributes*
  {
    return points ? static_cast<vtkDataSetAttributes*>(pd->GetPointData())
                  : static_cast<vtkDataSetAttributes*>(pd->GetCellData());
  };
  vtkDataSetAttributes* reference = attributes(first);
  for (int a = 0; a < reference->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* ref = reference->GetAbstractArray(a);
    if (ref && (!ref->GetName() || !ref->GetName()[0]))
      ++unnamed;
    if (!ref || !ref->GetName() || !ref->GetName()[0] || IsTreeArray(ref->GetName(), points))
      continue;
    bool everywhere = true;
    for (vtkPolyData* leaf : leaves)
    {
      if (!leaf)
        continue;
      vtkAbstractArray* other = attributes(leaf)->GetAbstractArray(ref->GetName());
      const vtkIdType n = points ? leaf->GetNumberOfPoints() : leaf->GetNumberOfCells();
      if (!other || other->GetDataType() != ref->GetDataType() ||
        other->GetNumberOfComponents() != ref->GetNumberOfComponents() ||
        other->GetNumberOfTuples() != n)
      {
        everywhere = false;
        break;
      }
    }
    if (everywhere)
      names.emplace_back(ref->GetName());
  }
  return names;
}

}
