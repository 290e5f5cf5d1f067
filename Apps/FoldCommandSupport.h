// Shared parts of the fold / unfold / roundtrip commands (FoldCommands.cxx,
// RoundtripCommand.cxx).
#ifndef foldingmeshes_FoldCommandSupport_h
#define foldingmeshes_FoldCommandSupport_h

#include "CommandLine.h"
#include "MeshComparison.h"
#include "vtkFoldingTreeBuilder.h"

#include <vtkAlgorithm.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <optional>
#include <string>

namespace foldingmeshes
{
namespace cli
{
/// The command line's settings. Builder parameters the user did not give stay unset, so the
/// filter's own defaults apply (they are stated once, in vtkFoldingTreeBuilder.h).
struct FoldSettings
{
  std::string meshPath, outdir = ".";
  bool json = false, quiet = false;
  std::optional<double> tolerance;         // relative to the diagonal
  std::optional<double> absoluteTolerance; // a length; overrides `tolerance`
  std::optional<int> keep;
  std::optional<double> minAreaFraction;
  std::optional<int> maxFolds;
  std::optional<int> minFaces;
  std::optional<int> method;
  std::optional<int> randomSeed;
  std::optional<int> sampledSearchAboveFaces;
  bool tightSymmetry = false;                     // --tight-symmetry: RequireTightSymmetry on
  bool noVerifyBound = false;                     // --no-verify-bound: VerifyBound off
  bool separateParts = false;                     // --separate-parts: ConnectNearbyParts off
  bool rotationNodes = false;                     // --rotation: RotationNodes on
  bool rotationWhenAxial = false;                 // --rotation-when-axial: ... WHEN_AXIAL
  bool noRotation = false;                        // --no-rotation: ... OFF (compress's rule off)
  std::optional<int> maxRotationOrder;            // --max-rotation-order
  int upAxis = -1;                                // the picture's up axis (--up; -1: auto)
  bool keepProjectedPoints = false;               // roundtrip's unfolder: RemoveProjectedPoints off
  bool keepCopyDensity = false;                   // roundtrip's unfolder: MatchDiscardedDensity off
  bool noStitch = false;                          // roundtrip's unfolder: Stitch off
  bool noCloseHoles = false;                      // roundtrip's unfolder: CloseHoles off
  std::optional<DistanceLocator> distanceLocator; // --distance-locator (roundtrip only)
};

/// The arguments of fold / unfold / roundtrip; throws std::runtime_error on a bad one.
FoldSettings ParseFoldArguments(int argc, char* argv[]);

/// Runs `algorithm` with error capture and optional progress; false with the message.
bool RunFilter(vtkAlgorithm* algorithm, const char* label, bool quiet, std::string& error);

/// The builder's parameters from the settings.
void ConfigureBuilder(vtkFoldingTreeBuilder* builder, const FoldSettings& f);

/// A number of the tree's "Tree" information block (block 1), or `fallback`.
double TreeValue(vtkMultiBlockDataSet* tree, const char* name, double fallback = 0.0);

/// A number of the mesh's field data, or `fallback`.
double FieldValue(vtkPolyData* mesh, const char* name, double fallback = 0.0);

bool WriteTree(vtkMultiBlockDataSet* tree, const std::string& path, std::string& error);
vtkSmartPointer<vtkMultiBlockDataSet> ReadTree(const std::string& path, std::string& error);

/// Writes a picture of `mesh` coloured by the cell array `arrayName`, up along `upAxis`
/// (MakeCategoryScene); skipped without a display (the returned path is then empty). False (with
/// error) when it cannot be written.
bool WriteCategoryPicture(vtkPolyData* mesh,
  const char* arrayName,
  int upAxis,
  std::string& picture,
  std::string& error);

/// The file stem of a tree path without its "_tree" suffix.
std::string TreeStem(const std::string& path);

bool MakeOutdir(const std::string& outdir, std::string& error);
}
}

#endif
