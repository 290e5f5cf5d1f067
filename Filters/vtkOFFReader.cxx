#include "vtkOFFReader.h"

#include "vtkCellArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace
{
// Line-aware tokenizer over a NUL-terminated buffer.
struct OFFParser
{
  OFFParser(const char* begin, const char* end)
    : P(begin)
    , End(end)
  {
  }

  const char* P;
  const char* End;
  long Line = 1;
  std::string Error;

  static bool IsBlank(char c)
  {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  bool IsDelimiter(const char* q) const
  {
    return q == this->End || IsBlank(*q) || *q == '\n' || *q == '#';
  }

  // Moves to the first token of the next line holding data; false at end of file.
  bool NextDataLine()
  {
    while (this->P < this->End)
    {
      const char c = *this->P;
      if (c == '\n')
      {
        ++this->Line;
        ++this->P;
      }
      else if (c == '#')
      {
        this->SkipLine();
      }
      else if (IsBlank(c))
      {
        ++this->P;
      }
      else
      {
        return true;
      }
    }
    return false;
  }

  // Skips the rest of the current line, stopping at its '\n'.
  void SkipLine()
  {
    while (this->P < this->End && *this->P != '\n')
    {
      ++this->P;
    }
  }

  bool AtEndOfLine()
  {
    while (this->P < this->End && IsBlank(*this->P))
    {
      ++this->P;
    }
    return this->P == this->End || *this->P == '\n' || *this->P == '#';
  }

  std::string Token() const
  {
    const char* q = this->P;
    while (!this->IsDelimiter(q) && q - this->P < 40)
    {
      ++q;
    }
    return std::string(this->P, q);
  }

  bool Fail(const std::string& msg)
  {
    this->Error = msg;
    return false;
  }

  // Reads a number on the current line; `what` names it in error messages.
  bool ReadDouble(double& value, const char* what)
  {
    if (this->AtEndOfLine())
    {
      return this->Fail(std::string("missing ") + what);
    }
    char* e = nullptr;
    value = std::strtod(this->P, &e);
    if (e == this->P || !this->IsDelimiter(e) || !std::isfinite(value))
    {
      return this->Fail(std::string("invalid ") + what + " '" + this->Token() + "'");
    }
    this->P = e;
    return true;
  }

  bool ReadLong(long& value, const char* what)
  {
    if (this->AtEndOfLine())
    {
      return this->Fail(std::string("missing ") + what);
    }
    char* e = nullptr;
    errno = 0;
    value = std::strtol(this->P, &e, 10);
    if (e == this->P || !this->IsDelimiter(e) || errno == ERANGE)
    {
      return this->Fail(std::string("invalid ") + what + " '" + this->Token() + "'");
    }
    this->P = e;
    return true;
  }

  // Reads the [C][N]OFF keyword at the first data line.
  bool ReadKeyword(bool& colors, bool& normals)
  {
    if (!this->NextDataLine())
    {
      return this->Fail("empty file");
    }
    const std::string key = this->Token();
    colors = key == "COFF" || key == "CNOFF" || key == "NCOFF";
    normals = key == "NOFF" || key == "CNOFF" || key == "NCOFF";
    if (key != "OFF" && !colors && !normals)
    {
      return this->Fail(
        "not an OFF file: header keyword '" + key + "' (expected OFF, COFF, NOFF or CNOFF)");
    }
    this->P += key.size();
    if (!this->AtEndOfLine() && this->Token() == "BINARY")
    {
      return this->Fail("binary OFF files are not supported");
    }
    return true;
  }
};
/// The header after the [C][N]OFF keyword: what each vertex line holds and the counts.
struct OFFHeader
{
  bool colors = false;
  bool normals = false;
  long nv = 0;
  long nf = 0;
  long ne = 0;
};

/// Reads the keyword and "nv nf [ne]" (on the same or a later line) of a file of `size`
/// bytes; vtkErrorCode::NoError, or the error code with the message in ps.Error.
unsigned long ReadHeader(OFFParser& ps, std::streamoff size, OFFHeader& h)
{
  if (!ps.ReadKeyword(h.colors, h.normals))
    return vtkErrorCode::UnrecognizedFileTypeError;
  if (ps.AtEndOfLine() && !ps.NextDataLine())
  {
    ps.Error = "missing vertex and face counts";
    return vtkErrorCode::PrematureEndOfFileError;
  }
  if (!ps.ReadLong(h.nv, "vertex count") || !ps.ReadLong(h.nf, "face count") ||
    (!ps.AtEndOfLine() && !ps.ReadLong(h.ne, "edge count")))
    return vtkErrorCode::FileFormatError;
  // Every vertex line takes at least 6 bytes ("0 0 0\n"), every face line 4 ("1 0\n").
  if (h.nv < 0 || h.nf < 0 || h.nv > size / 5 || h.nf > size / 3)
  {
    ps.Error = "invalid counts " + std::to_string(h.nv) + " " + std::to_string(h.nf) +
      " (negative, or more than the file can hold)";
    return vtkErrorCode::FileFormatError;
  }
  ps.SkipLine();
  return vtkErrorCode::NoError;
}

/// The vertex lines: positions (float), normals (NOFF), colours (COFF: 4 values per vertex,
/// NaN alpha where none is given; the first line sets 3 or 4 components).
struct OFFVertices
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  std::vector<double> rgba;
  int colorComps = 0;
  double colorMax = 0.0;
};

unsigned long ReadVertices(OFFParser& ps,
  const OFFHeader& h,
  OFFVertices& out,
  vtkAlgorithm* progress)
{
  const long nv = h.nv;
  out.points->SetDataTypeToFloat();
  out.points->SetNumberOfPoints(nv);
  float* xyz = static_cast<vtkFloatArray*>(out.points->GetData())->GetPointer(0);
  if (h.normals)
  {
    out.normals->SetName("Normals");
    out.normals->SetNumberOfComponents(3);
    out.normals->SetNumberOfTuples(nv);
  }
  out.rgba.assign(
    h.colors ? 4 * static_cast<size_t>(nv) : 0, std::numeric_limits<double>::quiet_NaN());
  const char* coordNames[3] = { "x coordinate", "y coordinate", "z coordinate" };
  const char* normalNames[3] = { "normal x", "normal y", "normal z" };
  const char* colorNames[3] = { "red value", "green value", "blue value" };
  for (long i = 0; i < nv; ++i)
  {
    if (!ps.NextDataLine())
    {
      ps.Error = "unexpected end of file after " + std::to_string(i) + " of " + std::to_string(nv) +
        " vertices";
      return vtkErrorCode::PrematureEndOfFileError;
    }
    for (int k = 0; k < 3; ++k)
    {
      double v;
      if (!ps.ReadDouble(v, coordNames[k]))
        return vtkErrorCode::FileFormatError;
      xyz[3 * i + k] = static_cast<float>(v);
    }
    for (int k = 0; h.normals && k < 3; ++k)
    {
      double v;
      if (!ps.ReadDouble(v, normalNames[k]))
        return vtkErrorCode::FileFormatError;
      out.normals->SetTypedComponent(i, k, static_cast<float>(v));
    }
    if (h.colors)
    {
      double* c = &out.rgba[4 * i];
      for (int k = 0; k < 3; ++k)
        if (!ps.ReadDouble(c[k], colorNames[k]))
          return vtkErrorCode::FileFormatError;
      if (out.colorComps != 3 && !ps.AtEndOfLine() && !ps.ReadDouble(c[3], "alpha value"))
        return vtkErrorCode::FileFormatError;
      out.colorComps = out.colorComps ? out.colorComps : (std::isnan(c[3]) ? 3 : 4);
      out.colorMax = std::max({ out.colorMax, c[0], c[1], c[2], std::isnan(c[3]) ? 0.0 : c[3] });
    }
    ps.SkipLine();
    if ((i & 0xffff) == 0)
      progress->UpdateProgress(0.5 * static_cast<double>(i) / static_cast<double>(nv));
  }
  return vtkErrorCode::NoError;
}

/// The face lines: polygons (n >= 3) as the output's polys, n = 1 and 2 as verts and lines.
unsigned long ReadFaces(OFFParser& ps,
  const OFFHeader& h,
  vtkPolyData* output,
  vtkAlgorithm* progress)
{
  const long nv = h.nv, nf = h.nf;
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->Allocate(nf + 1);
  offsets->InsertNextValue(0);
  connectivity->Allocate(3 * static_cast<vtkIdType>(nf));
  vtkNew<vtkCellArray> verts, lines;
  std::vector<vtkIdType> ids;
  for (long f = 0; f < nf; ++f)
  {
    long n = 0;
    if (!ps.NextDataLine())
    {
      ps.Error = "unexpected end of file after " + std::to_string(f) + " of " + std::to_string(nf) +
        " faces";
      return vtkErrorCode::PrematureEndOfFileError;
    }
    if (!ps.ReadLong(n, "face size"))
      return vtkErrorCode::FileFormatError;
    if (n < 1)
    {
      ps.Error = "invalid face size " + std::to_string(n);
      return vtkErrorCode::FileFormatError;
    }
    ids.clear();
    for (long k = 0; k < n; ++k)
    {
      long id = 0;
      if (!ps.ReadLong(id, "vertex index"))
      {
        ps.Error += " (face " + std::to_string(f) + " has " + std::to_string(k) + " of " +
          std::to_string(n) + " indices)";
        return vtkErrorCode::FileFormatError;
      }
      if (id < 0 || id >= nv)
      {
        ps.Error =
          "vertex index " + std::to_string(id) + " out of range [0, " + std::to_string(nv) + ")";
        return vtkErrorCode::FileFormatError;
      }
      if (n >= 3)
        connectivity->InsertNextValue(id);
      else
        ids.push_back(id);
    }
    if (n >= 3)
      offsets->InsertNextValue(connectivity->GetNumberOfValues());
    else
    {
      vtkCellArray* cells = n == 1 ? verts.Get() : lines.Get();
      cells->InsertNextCell(static_cast<vtkIdType>(n), ids.data());
    }
    ps.SkipLine();
    if ((f & 0xffff) == 0)
      progress->UpdateProgress(0.5 + 0.5 * static_cast<double>(f) / static_cast<double>(nf));
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
  if (verts->GetNumberOfCells() > 0)
    output->SetVerts(verts);
  if (lines->GetNumberOfCells() > 0)
    output->SetLines(lines);
  return vtkErrorCode::NoError;
}

/// The COFF colours as unsigned chars: floats in [0,1] unless some value exceeds 1, then
/// integers in 0..255; a missing alpha is opaque.
vtkSmartPointer<vtkUnsignedCharArray> ColorArray(const OFFVertices& v, long nv)
{
  const double scale = v.colorMax <= 1.0 ? 255.0 : 1.0;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(v.colorComps);
  colors->SetNumberOfTuples(nv);
  unsigned char* out = colors->GetPointer(0);
  for (long i = 0; i < nv; ++i)
    for (int k = 0; k < v.colorComps; ++k)
    {
      const double c = v.rgba[4 * i + k];
      out[v.colorComps * i + k] = std::isnan(c)
        ? 255
        : static_cast<unsigned char>(std::min(255.0, std::max(0.0, std::round(c * scale))));
    }
  return colors;
}
}

vtkStandardNewMacro(vtkOFFReader);

//------------------------------------------------------------------------------
vtkOFFReader::vtkOFFReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOFFReader::~vtkOFFReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}

//------------------------------------------------------------------------------
int vtkOFFReader::CanReadFile(const char* fname)
{
  std::ifstream in(fname ? fname : "", std::ios::binary);
  if (!in)
  {
    return 0;
  }
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  OFFParser ps(head.c_str(), head.c_str() + head.size());
  bool colors, normals;
  return ps.ReadKeyword(colors, normals) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkOFFReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outVec)
{
  vtkPolyData* output = vtkPolyData::GetData(outVec);
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  const std::string fname = this->FileName ? this->FileName : "";
  if (fname.empty())
  {
    vtkErrorMacro(<< "no FileName set");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 0;
  }

  // Read the whole file (NUL-terminated, so strtod/strtol always stop).
  std::ifstream in(fname, std::ios::binary | std::ios::ate);
  if (!in)
  {
    vtkErrorMacro(<< fname << ": cannot open file");
    this->SetErrorCode(vtkErrorCode::FileNotFoundError);
    return 0;
  }
  const std::streamoff size = in.tellg();
  std::vector<char> buffer(static_cast<size_t>(std::max<std::streamoff>(size, 0)) + 1, '\0');
  in.seekg(0);
  if (size < 0 || !in.read(buffer.data(), size))
  {
    vtkErrorMacro(<< fname << ": cannot read file");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return 0;
  }
  in.close();

  OFFParser ps(buffer.data(), buffer.data() + size);
  OFFHeader header;
  OFFVertices vertices;
  unsigned long code = ReadHeader(ps, size, header);
  if (code == vtkErrorCode::NoError)
    code = ReadVertices(ps, header, vertices, this);
  if (code == vtkErrorCode::NoError)
    code = ReadFaces(ps, header, output, this);
  if (code != vtkErrorCode::NoError)
  {
    output->Initialize();
    vtkErrorMacro(<< fname << ":" << ps.Line << ": " << ps.Error);
    this->SetErrorCode(code);
    return 0;
  }
  output->SetPoints(vertices.points);
  if (header.normals)
    output->GetPointData()->SetNormals(vertices.normals);
  if (header.colors && header.nv > 0)
    output->GetPointData()->SetScalars(ColorArray(vertices, header.nv));
  this->UpdateProgress(1.0);
  return 1;
}
