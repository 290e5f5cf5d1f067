// How the filters carry the user's point, cell and field arrays next to their own (internal
// header): the names they reserve, the renaming of user arrays that clash with them, names for
// unnamed arrays, the arrays VTK's XML files cannot hold, copying tuples by id, and the record
// of the input's active attributes.
#ifndef vtkFoldingArrays_h
#define vtkFoldingArrays_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <string>
#include <vector>

class vtkAbstractArray;
class vtkDataSetAttributes;
class vtkFieldData;
class vtkPolyData;
class vtkStringArray;

namespace foldingmeshes
{
/// Suffix of a user array renamed because a filter writes an array of the same name.
constexpr const char* RenamedInputSuffix = "_input";

/// Point / cell arrays the builder writes into every leaf; the unfolder reads them and does not
/// carry them to its output.
const std::vector<std::string>& LeafPointArrayNames();
const std::vector<std::string>& LeafCellArrayNames();
/// Point / cell arrays the unfolder writes into its output.
const std::vector<std::string>& UnfoldedPointArrayNames();
const std::vector<std::string>& UnfoldedCellArrayNames();

/// `name` + "_input", or with a number appended ("_input2", ...) when that is taken in `fd`
/// or listed in `avoid`.
std::string FreeInputName(vtkFieldData* fd,
  const std::string& name,
  const std::vector<std::string>& avoid = {});

/**
 * Renames every array of `fd` named in `reserved` to FreeInputName (the array object is
 * replaced by a shallow copy, so arrays shared with the caller's input keep their names; an
 * active attribute stays active under its new name). Appends "old -> new" to `notes`.
 */
void RenameReservedArrays(vtkFieldData* fd,
  const std::vector<std::string>& reserved,
  std::vector<std::string>& notes);

/// Prefix of the input's field arrays on a folding tree's "Tree" block.
constexpr const char* InputFieldPrefix = "InputField:";

/// Gives every unnamed array of `fd` the name `prefix` + k (k counting the unnamed arrays,
/// skipping names in use), as a renamed shallow copy; appends the new names to `notes`.
void NameUnnamedArrays(vtkFieldData* fd, const char* prefix, std::vector<std::string>& notes);

/// True for arrays VTK's XML writers store: data arrays and string arrays (not, e.g.,
/// vtkVariantArray, which makes the written file unreadable).
bool IsXMLWritable(vtkAbstractArray* array);

/// Removes the arrays of `fd` IsXMLWritable rejects; appends their names to `notes`.
void RemoveUnwritableArrays(vtkFieldData* fd, std::vector<std::string>& notes);

/**
 * Fills `dst` with every array of `src` (named or not, any array class) holding tuple ids[i]
 * as tuple i; arrays too short for the largest id are skipped. Active attributes follow.
 */
void CopyTuplesById(vtkDataSetAttributes* src,
  vtkDataSetAttributes* dst,
  const vtkIdType* ids,
  vtkIdType n);

/// The attribute names of `dsa` (vtkDataSetAttributes::NUM_ATTRIBUTES entries, "" for none).
std::vector<std::string> ActiveAttributeNames(vtkDataSetAttributes* dsa);

/// The active attribute names of `dsa` as the string array `name` the builder stores on the
/// tree's "Tree" block: "k:name" per attribute k ("k:" for none).
vtkSmartPointer<vtkStringArray> AttributeRecord(vtkDataSetAttributes* dsa, const char* name);

/// The names AttributeRecord stored as `name` in `info`; without such a record (older trees)
/// those of the first leaf, less the builder's own leaf arrays.
std::vector<std::string> RecordedAttributes(vtkFieldData* info,
  const char* name,
  const std::vector<vtkPolyData*>& leaves,
  bool points);

/// Makes the arrays `names[attribute]` of `out` its active attributes where they exist, except
/// global or pedigree ids whose values repeat (mirrored copies repeat their leaf's ids: the
/// array stays, unflagged).
/**
 * Names of the user arrays (not the tree's own, named, present in every leaf with the same type,
 * components and one tuple per point / cell) of the leaves (null entries skipped); `unnamed`
 * counts the first leaf's unnamed arrays (never carried).
 */
std::vector<std::string> CommonLeafArrays(const std::vector<vtkPolyData*>& leaves,
  bool points,
  int& unnamed);

void ApplyActiveAttributes(vtkDataSetAttributes* out, const std::vector<std::string>& names);
}

#endif
