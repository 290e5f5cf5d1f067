// Shared by the TestFoldingTreeFilters sources: failure counter, EXPECT, tree checks, declarations.
#ifndef foldingmeshes_testing_TestFoldingTreeChecks_h
#define foldingmeshes_testing_TestFoldingTreeChecks_h

#include "ProceduralMeshes.h"
#include "TestExpect.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkFieldData;
class vtkMultiBlockDataSet;
class vtkObject;
class vtkPolyData;

namespace foldingtreetest
{
namespace pm = foldingmeshes::testing;
using Vec3 = Eigen::Vector3d;
extern int failures;

#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(failures, cond, msg)

struct EventLog
{
  std::vector<std::string> errors;
  static void Callback(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    static_cast<EventLog*>(clientData)
      ->errors.push_back(callData ? static_cast<const char*>(callData) : "");
  }
};

/// Updates `alg`, capturing (and silencing) its error events; returns the executive's status.
int UpdateCapturing(vtkAlgorithm* alg, EventLog& log);

double FieldValue(vtkFieldData* fd, const char* name, int component = 0);

const char* BlockName(vtkMultiBlockDataSet* mb, unsigned int b);

/// Unit normal of triangle c (zero when degenerate).
Vec3 FaceNormal(vtkPolyData* pd, vtkIdType c);

/// Input with the test arrays: "Temperature" (point, double), "Label" (cell, int) and
/// "Position" (point vector, double = the point itself).
vtkSmartPointer<vtkPolyData> WithArrays(vtkPolyData* mesh);

struct NodeInfo
{
  std::string name;
  int kind = -1;
  int index = -1;
  int depth = -1;
  double epsilon = 0.0;
  vtkPolyData* leaf = nullptr;
  std::vector<int> children; // positions in the list
};

/// Walks a tree node block, checking names, kinds, depths and epsilons; appends to `nodes`.
int Walk(vtkDataObject* object,
  const std::string& name,
  int depth,
  double parentEpsilon,
  int parentKind,
  std::vector<NodeInfo>& nodes,
  const std::string& label);

/// Leaves carry the input arrays with the values of their original ids.
void CheckLeafArrays(const std::vector<NodeInfo>& nodes,
  vtkPolyData* input,
  const std::string& label);

/// Every polydata block of `b` equals the one of `a` at the same place (points, cells,
/// point, cell and field arrays, names).
void CompareTrees(vtkMultiBlockDataSet* a, vtkMultiBlockDataSet* b, const std::string& label);

/// Largest distance of the vertices of `from` to the surface `to`.
double MaximumVertexDistance(vtkPolyData* from, vtkPolyData* to);

/// Boundary and non-manifold edges.
void CountEdges(vtkPolyData* mesh, int& open, int& nonManifold);

void ExpectIdentical(vtkPolyData* a, vtkPolyData* b, const std::string& label);

/// Malformed trees and bad builder input fail with an ErrorEvent (TestFoldingTreeMalformed.cxx).
void TestMalformed(vtkMultiBlockDataSet* good);
} // namespace foldingtreetest

#endif
