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
int Detect(int argc, char* argv[])
{
  std::string meshPath, output, planeOutput, picture, outdir = ".";
  int upAxis = -1;
  bool json = false, quiet = false, noFiles = false, absoluteGiven = false;
  vtkNew<vtkSymmetryPlaneDetector> detector;
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
      detector->SetTolerance(
        ParseNumber(arg, value("--absolute-tolerance"), 1e-12, 1e30, true));
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
    else if (arg == "--seed")
      detector->SetRandomSeed(ParseInteger(arg, value("--seed"), -2147483647, 2147483647));
    else if (arg == "--separate-parts")
      detector->ConnectNearbyPartsOff();
    else if (arg == "--output")
      output = value("--output");
    else if (arg == "--plane-output")
      planeOutput = value("--plane-output");
    else if (arg == "--picture")
      picture = value("--picture");
    else if (arg == "--up")
      upAxis = ParseUpAxis(value("--up"));
    else if (arg == "--outdir")
      outdir = value("--outdir");
    else if (arg == "--no-files")
      noFiles = true;
    else if (arg == "--json")
      json = true;
    else if (arg == "--quiet")
      quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw std::runtime_error("unknown option '" + arg + "'");
    else if (meshPath.empty())
      meshPath = arg;
    else
      throw std::runtime_error("more than one mesh given ('" + arg + "')");
  }
  if (meshPath.empty())
    throw std::runtime_error("no mesh given");

  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(meshPath, error);
  if (!mesh)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }

  ErrorCollector errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&ErrorCollector::OnError);
  onError->SetClientData(&errors);
  detector->AddObserver(vtkCommand::ErrorEvent, onError);
  ProgressPrinter progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetCallback(&ProgressPrinter::OnProgress);
  onProgress->SetClientData(&progress);
  if (!quiet)
    detector->AddObserver(vtkCommand::ProgressEvent, onProgress);

  detector->SetInputData(mesh);
  const auto start = std::chrono::steady_clock::now();
  const int ok = detector->GetExecutive()->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!quiet)
    std::fprintf(stderr, "\n");
  if (!ok || !errors.messages.empty())
  {
    std::cerr << "foldingmeshes: " << meshPath << ": "
              << (errors.messages.empty() ? "symmetry detection failed" : errors.messages);
    if (errors.messages.empty() || errors.messages.back() != '\n')
      std::cerr << "\n";
    return 2;
  }

  const std::string stem = std::filesystem::path(meshPath).stem().string();
  const std::filesystem::path dir(outdir);
  if (!noFiles)
  {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (output.empty())
      output = (dir / (stem + "_symmetry.vtp")).string();
    if (planeOutput.empty())
      planeOutput = (dir / (stem + "_plane.vtp")).string();
    if (picture.empty())
      picture = (dir / (stem + "_symmetry.png")).string();
    if (!foldingmeshes::WriteMesh(detector->GetOutput(0), output, error) ||
      !foldingmeshes::WriteMesh(detector->GetOutput(1), planeOutput, error))
    {
      std::cerr << "foldingmeshes: " << error << "\n";
      return 3;
    }
    if (!std::getenv("DISPLAY"))
    {
      std::cerr << "foldingmeshes: no display, picture skipped (run under xvfb-run -a)\n";
      picture.clear();
    }
    else
    {
      auto window =
        foldingmeshes::MakeSymmetryScene(detector->GetOutput(0), detector->GetOutput(1), 800, 600, upAxis);
      if (!foldingmeshes::WritePicture(window, picture, error))
      {
        std::cerr << "foldingmeshes: " << error << "\n";
        return 3;
      }
    }
  }

  const double* o = detector->GetPlaneOrigin();
  const double* n = detector->GetPlaneNormal();
  const vtkIdType faces = detector->GetOutput(0)->GetNumberOfCells();
  if (json)
  {
    std::printf("{\n  \"mesh\": %s,\n  \"faces\": %lld,\n  \"tolerance\": %.9g,\n"
                "  \"plane\": {\"origin\": [%.9g, %.9g, %.9g], \"normal\": [%.9g, %.9g, %.9g]},\n"
                "  \"symmetricAreaFraction\": %.6f,\n  \"symmetryFound\": %s,\n"
                "  \"iterations\": {\"coarse\": %d, \"fine\": %d},\n  \"seconds\": %.3f",
      JsonString(meshPath).c_str(),
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
    if (!noFiles)
      std::printf(",\n  \"outputs\": {\"mesh\": %s, \"plane\": %s, \"picture\": %s}",
        JsonString(output).c_str(),
        JsonString(planeOutput).c_str(),
        picture.empty() ? "null" : JsonString(picture).c_str());
    std::printf("\n}\n");
  }
  else
  {
    std::printf("mesh:                    %s (%lld faces)\n",
      meshPath.c_str(),
      static_cast<long long>(faces));
    std::printf("tolerance (epsilon):     %.6g\n", detector->GetToleranceLength());
    std::printf("plane origin:            %.6g %.6g %.6g\n", o[0], o[1], o[2]);
    std::printf("plane normal:            %.6f %.6f %.6f\n", n[0], n[1], n[2]);
    std::printf("symmetric area fraction: %.1f%%\n", 100.0 * detector->GetSymmetricAreaFraction());
    std::printf("symmetry found:          %s\n", detector->GetSymmetryFound() ? "yes" : "no");
    std::printf("iterations:              %d coarse, %d fine\n",
      detector->GetCoarseIterations(),
      detector->GetFineIterations());
    std::printf("time:                    %.3f s\n", seconds);
    if (!noFiles)
    {
      std::printf("wrote:                   %s\n                         %s\n",
        output.c_str(),
        planeOutput.c_str());
      if (!picture.empty())
        std::printf("                         %s\n", picture.c_str());
    }
  }
  return 0;
}
}
}
