#include "MeshIO.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkExpatSafeXMLPolyDataReader.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkGeometryFilter.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOBJWriter.h"
#include "vtkOFFReader.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <initializer_list>
#include <system_error>

namespace foldingmeshes
{
namespace
{
// Captures (and silences) the errors and warnings of the observed algorithms and executives.
class VTKMessages
{
public:
  VTKMessages()
  {
    this->Callback->SetCallback(&VTKMessages::OnMessage);
    this->Callback->SetClientData(this);
  }
  ~VTKMessages() { this->Callback->SetClientData(nullptr); }
  VTKMessages(const VTKMessages&) = delete;
  VTKMessages& operator=(const VTKMessages&) = delete;

  void Observe(vtkAlgorithm* algorithm)
  {
    for (vtkObject* object :
      { static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
      object->AddObserver(vtkCommand::WarningEvent, this->Callback);
    }
  }

  /** True if an error was raised or a request failed. */
  bool Failed() const { return !this->Error.empty() || !this->Failure.empty(); }

  /** The first error, else the first warning, else the failed request, else `fallback`. */
  std::string Explain(const std::string& fallback) const
  {
    for (const std::string* text : { &this->Error, &this->Warning, &this->Failure })
    {
      if (!text->empty())
      {
        return *text;
      }
    }
    return fallback;
  }

private:
  static void OnMessage(vtkObject*, unsigned long event, void* clientData, void* callData)
  {
    auto* self = static_cast<VTKMessages*>(clientData);
    if (!self || !callData)
    {
      return;
    }
    // "ERROR: In file.cxx, line N\nvtkClass (0x...): text" -> "text"
    std::string text = static_cast<const char*>(callData);
    const size_t pos = text.find("): ");
    if (pos != std::string::npos)
    {
      text.erase(0, pos + 3);
    }
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    {
      text.pop_back();
    }
    // The executive's "Algorithm vtkX (0x...) returned failure for request: <dump>".
    std::string* slot = event == vtkCommand::ErrorEvent ? &self->Error : &self->Warning;
    if (text.rfind("Algorithm ", 0) == 0 && text.find(" returned failure") != std::string::npos)
    {
      text = text.substr(10, text.find_first_of(" (", 10) - 10) + " failed";
      slot = &self->Failure;
    }
    if (slot->empty())
    {
      *slot = text.empty() ? "unknown VTK error" : text;
    }
  }

  vtkNew<vtkCallbackCommand> Callback;
  std::string Error, Warning, Failure;
};

std::string LowerExtension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(),
    ext.end(),
    ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

template <class Reader>
vtkSmartPointer<Reader> MakeReader(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

// Runs `writer` on `mesh`; false with `error` set on failure.
template <class Writer>
bool RunWriter(Writer* writer, vtkPolyData* mesh, const std::string& path, std::string& error)
{
  VTKMessages messages;
  messages.Observe(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(mesh);
  const int ok = writer->Write();
  const unsigned long code = writer->GetErrorCode();
  if (ok && !messages.Failed() && code == vtkErrorCode::NoError)
  {
    return true;
  }
  error = "cannot write '" + path +
    "': " + messages.Explain("writer failed (vtkErrorCode " + std::to_string(code) + ")");
  return false;
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error)
{
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    error = "cannot read '" + path + "': no such file";
    return nullptr;
  }
  if (std::filesystem::is_directory(path, ec))
  {
    error = "cannot read '" + path + "': is a directory";
    return nullptr;
  }

  // `reader` reads the file; `last` is the end of the pipeline (a surface filter for
  // legacy files that do not hold poly data).
  const std::string ext = LowerExtension(path);
  VTKMessages messages;
  vtkSmartPointer<vtkAlgorithm> reader, last;
  if (ext == ".vtp")
  {
    reader = MakeReader<vtkExpatSafeXMLPolyDataReader>(path);
  }
  else if (ext == ".vtk")
  {
    auto polyReader = MakeReader<vtkPolyDataReader>(path);
    messages.Observe(polyReader);
    if (polyReader->IsFilePolyData())
    {
      reader = polyReader;
    }
    else
    {
      reader = MakeReader<vtkGenericDataObjectReader>(path);
      last = vtkSmartPointer<vtkGeometryFilter>::New();
      last->SetInputConnection(reader->GetOutputPort());
      messages.Observe(last);
    }
  }
  else if (ext == ".ply")
  {
    reader = MakeReader<vtkPLYReader>(path);
  }
  else if (ext == ".obj")
  {
    reader = MakeReader<vtkOBJReader>(path);
  }
  else if (ext == ".stl")
  {
    reader = MakeReader<vtkSTLReader>(path);
  }
  else if (ext == ".off")
  {
    reader = MakeReader<vtkOFFReader>(path);
  }
  else
  {
    error = "unsupported extension '" + ext + "' (use .vtp .vtk .ply .obj .stl .off)";
    return nullptr;
  }
  messages.Observe(reader);
  last = last ? last : reader;
  last->Update();

  vtkPolyData* out = vtkPolyData::SafeDownCast(last->GetOutputDataObject(0));
  const unsigned long code = reader->GetErrorCode();
  std::string why;
  if (messages.Failed() || code != vtkErrorCode::NoError)
  {
    why = messages.Explain("reader failed (vtkErrorCode " + std::to_string(code) + ")");
  }
  else if (!out || out->GetNumberOfPoints() == 0 || out->GetNumberOfCells() == 0)
  {
    why =
      messages.Explain(!out || out->GetNumberOfPoints() == 0 ? "no points read" : "no cells read");
  }
  if (!why.empty())
  {
    error = "cannot read '" + path + "': " + why;
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(out);
  return mesh;
}

//------------------------------------------------------------------------------
bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error)
{
  if (!mesh)
  {
    error = "cannot write '" + path + "': no mesh";
    return false;
  }
  const std::string ext = LowerExtension(path);
  if (ext == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    // Inline binary, not appended: VTK <= 9.2 readers cannot read appended files on a
    // current expat (vtkExpatSafeXMLDataParser); inline files read everywhere.
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToZLib();
    return RunWriter(writer.Get(), mesh, path, error);
  }
  if (ext == ".vtk")
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetFileTypeToBinary();
    return RunWriter(writer.Get(), mesh, path, error);
  }
  if (ext == ".ply")
  {
    vtkNew<vtkPLYWriter> writer;
    writer->SetFileTypeToBinary();
    auto* colors = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetArray("Colors"));
    if (colors && colors->GetNumberOfComponents() >= 3)
    {
      writer->SetArrayName("Colors");
    }
    return RunWriter(writer.Get(), mesh, path, error);
  }
  if (ext == ".stl")
  {
    vtkNew<vtkSTLWriter> writer;
    writer->SetFileTypeToBinary();
    return RunWriter(writer.Get(), mesh, path, error);
  }
  if (ext == ".obj")
  {
    vtkNew<vtkOBJWriter> writer;
    return RunWriter(writer.Get(), mesh, path, error);
  }
  error = "cannot write '" + path + "': unsupported extension '" + ext +
    "' (use .vtp .vtk .ply .stl .obj)";
  return false;
}

std::vector<std::string> MeshFiles(const std::string& path)
{
  if (!std::filesystem::is_directory(path))
    return { path };
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(path))
  {
    const std::string ext = entry.path().extension().string();
    if (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".vtp" || ext == ".stl")
      found.push_back(entry.path().string());
  }
  std::sort(found.begin(), found.end());
  return found;
}
}
