// foldingmeshes detect: the symmetry plane and symmetric region of a mesh.
#include "CommandLine.h"
#include "MeshIO.h"
#include "MeshPicture.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace foldingmeshes
{
namespace cli
{
namespace
{
/// What detect was asked (the detector's options go straight to the filter).
struct DetectArguments
{
  std::string meshPath, output, planeOutput, axisOutput, picture, outdir = ".";
  int upAxis = -1;
  bool json = false, quiet = false, noFiles = false;
};

DetectArguments ParseDetectArguments(int argc, char* argv[], vtkSymmetryPlaneDetector* detector)
{
  DetectArguments args;
  bool absoluteGiven = false;
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](const char* what) -> std::string
    {
      if (i + 1 >= argc)
        throw std::runtime_error(std::string("missing value after ") + what);
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      std::exit(0);
    }
    else if (arg == "--tolerance")
    {
      const double tolerance = ParseNumber(arg, value("--tolerance"), 1e-12, 1.0, true);
      if (!absoluteGiven) // --absolute-tolerance overrides it, in any order
      {
        detector->SetTolerance(tolerance);
        detector->SetToleranceMode(vtkSymmetryPlaneDetector::RELATIVE_TO_DIAGONAL);
      }
    }
    else if (arg == "--absolute-tolerance")
    {
      detector->SetTolerance(ParseNumber(arg, value("--absolute-tolerance"), 1e-12, 1e30, true));
      detector->SetToleranceMode(vtkSymmetryPlaneDetector::ABSOLUTE);
      absoluteGiven = true;
    }
    else if (arg == "--method")
    {
      const std::string m = value("--method");
      if (m != "robust" && m != "paper")
        throw std::runtime_error("--method must be robust or paper, got '" + m + "'");
      detector->SetMethod(
        m == "paper" ? vtkSymmetryPlaneDetector::PAPER : vtkSymmetryPlaneDetector::ROBUST);
    }
    else if (arg == "--initial-plane")
    {
      std::vector<double> v;
      if (!ParseNumbers(value("--initial-plane"), v) || v.size() != 6)
        throw std::runtime_error("--initial-plane needs six comma-separated numbers");
      detector->UseInitialPlaneOn();
      detector->SetInitialPlaneOrigin(v[0], v[1], v[2]);
      detector->SetInitialPlaneNormal(v[3], v[4], v[5]);
    }
    else if (arg == "--candidates")
      detector->SetNumberOfCandidates(ParseInteger(arg, value("--candidates"), 0, 64));
    else if (arg == "--sampled-search-above")
      detector->SetSampledSearchAboveFaces(
        ParseInteger(arg, value("--sampled-search-above"), 0, 1000000000));
    else if (arg == "--seed")
      detector->SetRandomSeed(ParseInteger(arg, value("--seed"), -2147483647, 2147483647));
    else if (arg == "--separate-parts")
      detector->ConnectNearbyPartsOff();
    else if (arg == "--rotation")
      detector->DetectRotationOn();
    else if (arg == "--max-rotation-order")
      detector->SetMaximumRotationOrder(ParseInteger(arg, value("--max-rotation-order"), 2, 360));
    else if (arg == "--axis-output")
      args.axisOutput = value("--axis-output");
    else if (arg == "--output")
      args.output = value("--output");
    else if (arg == "--plane-output")
      args.planeOutput = value("--plane-output");
    else if (arg == "--picture")
      args.picture = value("--picture");
    else if (arg == "--up")
      args.upAxis = ParseUpAxis(value("--up"));
    else if (arg == "--outdir")
      args.outdir = value("--outdir");
    else if (arg == "--no-files")
      args.noFiles = true;
    else if (arg == "--json")
      args.json = true;
    else if (arg == "--quiet")
      args.quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw std::runtime_error("unknown option '" + arg + "'");
    else if (args.meshPath.empty())
      args.meshPath = arg;
    else
      throw std::runtime_error("more than one mesh given ('" + arg + "')");
  }
  if (args.meshPath.empty())
    throw std::runtime_error("no mesh given");
  return args;
}

/// Runs the detector with error and progress observers; false with the errors printed.
bool RunDetector(vtkSymmetryPlaneDetector* detector, const DetectArguments& args, double& seconds)
{
  ErrorCollector errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&ErrorCollector::OnError);
  onError->SetClientData(&errors);
  detector->AddObserver(vtkCommand::ErrorEvent, onError);
  ProgressPrinter progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetCallback(&ProgressPrinter::OnProgress);
  onProgress->SetClientData(&progress);
  if (!args.quiet)
    detector->AddObserver(vtkCommand::ProgressEvent, onProgress);

  const auto start = std::chrono::steady_clock::now();
  const int ok = detector->GetExecutive()->Update();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet)
    std::fprintf(stderr, "\n");
  if (!ok || !errors.messages.empty())
  {
    std::cerr << "foldingmeshes: " << args.meshPath << ": "
              << (errors.messages.empty() ? "symmetry detection failed" : errors.messages);
    if (errors.messages.empty() || errors.messages.back() != '\n')
      std::cerr << "\n";
    return false;
  }
  return true;
}

/// Writes the region, the plane glyph and the picture (default names in the outdir); false
/// with the error printed.
bool WriteDetectOutputs(vtkSymmetryPlaneDetector* detector, DetectArguments& args)
{
  const std::string stem = std::filesystem::path(args.meshPath).stem().string();
  const std::filesystem::path dir(args.outdir);
  std::string error;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (args.output.empty())
    args.output = (dir / (stem + "_symmetry.vtp")).string();
  if (args.planeOutput.empty())
    args.planeOutput = (dir / (stem + "_plane.vtp")).string();
  if (args.picture.empty())
    args.picture = (dir / (stem + "_symmetry.png")).string();
  if (!detector->GetDetectRotation())
    args.axisOutput.clear();
  else if (args.axisOutput.empty())
    args.axisOutput = (dir / (stem + "_axis.vtp")).string();
  if (!foldingmeshes::WriteMesh(detector->GetOutput(0), args.output, error) ||
    !foldingmeshes::WriteMesh(detector->GetOutput(1), args.planeOutput, error) ||
    (!args.axisOutput.empty() &&
      !foldingmeshes::WriteMesh(detector->GetOutput(2), args.axisOutput, error)))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return false;
  }
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "foldingmeshes: no display, picture skipped (run under xvfb-run -a)\n";
    args.picture.clear();
    return true;
  }
  auto window = foldingmeshes::MakeSymmetryScene(detector->GetOutput(0),
    detector->GetOutput(1),
    800,
    600,
    args.upAxis,
    detector->GetDetectRotation() ? detector->GetOutput(2) : nullptr);
  if (!foldingmeshes::WritePicture(window, args.picture, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return false;
  }
  return true;
}

void PrintDetectJson(vtkSymmetryPlaneDetector* detector,
  const DetectArguments& args,
  double seconds)
{
  const double* o = detector->GetPlaneOrigin();
  const double* n = detector->GetPlaneNormal();
  const vtkIdType faces = detector->GetOutput(0)->GetNumberOfCells();
  std::printf("{\n  \"mesh\": %s,\n  \"faces\": %lld,\n  \"tolerance\": %.9g,\n"
              "  \"plane\": {\"origin\": [%.9g, %.9g, %.9g], \"normal\": [%.9g, %.9g, %.9g]},\n"
              "  \"symmetricAreaFraction\": %.6f,\n  \"symmetryFound\": %s,\n"
              "  \"iterations\": {\"coarse\": %d, \"fine\": %d},\n  \"seconds\": %.3f",
    JsonString(args.meshPath).c_str(),
    static_cast<long long>(faces),
    detector->GetToleranceLength(),
    o[0],
    o[1],
    o[2],
    n[0],
    n[1],
    n[2],
    detector->GetSymmetricAreaFraction(),
    detector->GetSymmetryFound() ? "true" : "false",
    detector->GetCoarseIterations(),
    detector->GetFineIterations(),
    seconds);
  if (detector->GetDetectRotation())
  {
    const double* ao = detector->GetRotationAxisOrigin();
    const double* ad = detector->GetRotationAxisDirection();
    std::printf(",\n  \"rotation\": {\"origin\": [%.9g, %.9g, %.9g], "
                "\"direction\": [%.9g, %.9g, %.9g], \"order\": %d, \"found\": %s, "
                "\"continuous\": %s, \"areaFraction\": %.6f}",
      ao[0],
      ao[1],
      ao[2],
      ad[0],
      ad[1],
      ad[2],
      detector->GetRotationOrder(),
      detector->GetRotationFound() ? "true" : "false",
      detector->GetRotationContinuous() ? "true" : "false",
      detector->GetRotationalAreaFraction());
  }
  if (!args.noFiles)
    std::printf(",\n  \"outputs\": {\"mesh\": %s, \"plane\": %s, \"axis\": %s, "
                "\"picture\": %s}",
      JsonString(args.output).c_str(),
      JsonString(args.planeOutput).c_str(),
      args.axisOutput.empty() ? "null" : JsonString(args.axisOutput).c_str(),
      args.picture.empty() ? "null" : JsonString(args.picture).c_str());
  std::printf("\n}\n");
}

void PrintDetectText(vtkSymmetryPlaneDetector* detector,
  const DetectArguments& args,
  double seconds)
{
  const double* o = detector->GetPlaneOrigin();
  const double* n = detector->GetPlaneNormal();
  const vtkIdType faces = detector->GetOutput(0)->GetNumberOfCells();
  std::printf("mesh:                    %s (%lld faces)\n",
    args.meshPath.c_str(),
    static_cast<long long>(faces));
  std::printf("tolerance (epsilon):     %.6g\n", detector->GetToleranceLength());
  std::printf("plane origin:            %.6g %.6g %.6g\n", o[0], o[1], o[2]);
  std::printf("plane normal:            %.6f %.6f %.6f\n", n[0], n[1], n[2]);
  std::printf("symmetric area fraction: %.1f%%\n", 100.0 * detector->GetSymmetricAreaFraction());
  std::printf("symmetry found:          %s\n", detector->GetSymmetryFound() ? "yes" : "no");
  std::printf("iterations:              %d coarse, %d fine\n",
    detector->GetCoarseIterations(),
    detector->GetFineIterations());
  if (detector->GetDetectRotation())
  {
    const double* ao = detector->GetRotationAxisOrigin();
    const double* ad = detector->GetRotationAxisDirection();
    std::printf("rotation axis origin:    %.6g %.6g %.6g\n", ao[0], ao[1], ao[2]);
    std::printf("rotation axis direction: %.6f %.6f %.6f\n", ad[0], ad[1], ad[2]);
    std::printf("rotation order:          %d%s\n",
      detector->GetRotationOrder(),
      detector->GetRotationContinuous() ? " (every order up to the cap: a surface of revolution)"
                                        : "");
    std::printf("rotational area:         %.1f%%\n", 100.0 * detector->GetRotationalAreaFraction());
    std::printf("rotation found:          %s\n", detector->GetRotationFound() ? "yes" : "no");
  }
  std::printf("time:                    %.3f s\n", seconds);
  if (!args.noFiles)
  {
    std::printf("wrote:                   %s\n                         %s\n",
      args.output.c_str(),
      args.planeOutput.c_str());
    if (!args.axisOutput.empty())
      std::printf("                         %s\n", args.axisOutput.c_str());
    if (!args.picture.empty())
      std::printf("                         %s\n", args.picture.c_str());
  }
}
}

int Detect(int argc, char* argv[])
{
  vtkNew<vtkSymmetryPlaneDetector> detector;
  DetectArguments args = ParseDetectArguments(argc, argv, detector);
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(args.meshPath, error);
  if (!mesh)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }
  detector->SetInputData(mesh);
  double seconds = 0.0;
  if (!RunDetector(detector, args, seconds))
    return 2;
  if (!args.noFiles && !WriteDetectOutputs(detector, args))
    return 3;
  if (args.json)
    PrintDetectJson(detector, args, seconds);
  else
    PrintDetectText(detector, args, seconds);
  return 0;
}
}
}
