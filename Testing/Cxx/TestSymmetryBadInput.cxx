// vtkSymmetryPlaneDetector on bad and unusual input:
// - failures: empty poly data, points without cells, only lines and vertices, a NaN and an Inf
//   coordinate, all faces degenerate (zero area), point ids out of range (negative, >= number of
//   points) in triangles and quads, NaN parameters (Tolerance, CompatibilityAngle,
//   MinimumSymmetricAreaFraction), a zero or non-finite initial
//   normal, a NaN initial origin: Update() returns 0 and an ErrorEvent with a non-empty message
//   is raised (captured and silenced by vtkCallbackCommand observers);
// - an initial normal whose norm overflows (1e300 0 1e300) gives the result of (1 0 1);
// - scale: a blob scaled beyond the supported bounding-box diagonals [1e-60, 1e60] fails with an
//   error naming the range; scaled by 2^-196 or 2^196 it gives the unscaled blob's plane,
//   SymmetryFound and (within 0.01) area fraction;
// - quads (a subdivided box) and hexagons + quads (a prism) are triangulated and work: every
//   output cell is a triangle lying in one input polygon, whose cell values it carries; the
//   exactly symmetric shapes are found symmetric about one of their mirror planes;
// - a non-manifold fin (three triangles on one edge), an open hemisphere, a multi-part mesh and
//   an asymmetric blob succeed: unit normal, SymmetryRegion in {0,1,2}, area fraction in [0,1];
//   the asymmetric blob gives SymmetryFound false;
// - input point and cell arrays reach output 0 unchanged;
// - determinism: two runs (fresh filters, and a re-run) give bit-identical results, and
//   vtkSMPTools Sequential and STDThread (2 threads) agree bit for bit.
#include "ProceduralMeshes.h"
#include "TestExpect.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Vec3 = Eigen::Vector3d;
int failures = 0;

#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(failures, cond, msg)

/// Captures (and so silences) the error and warning events of the filter and its executive.
struct EventLog
{
  std::vector<std::string> errors, warnings, executiveErrors;
  static void Callback(vtkObject* caller, unsigned long event, void* clientData, void* callData)
  {
    auto* log = static_cast<EventLog*>(clientData);
    const std::string message = callData ? static_cast<const char*>(callData) : "";
    if (vtkExecutive::SafeDownCast(caller))
      log->executiveErrors.push_back(message);
    else if (event == vtkCommand::ErrorEvent)
      log->errors.push_back(message);
    else
      log->warnings.push_back(message);
  }
};

struct Run
{
  vtkNew<vtkSymmetryPlaneDetector> filter;
  EventLog log;
  vtkNew<vtkCallbackCommand> callback;
  int status = -1;
  vtkPolyData* output = nullptr;
};

/// Runs a fresh filter on `input` with the observers attached.
void Execute(Run& run, vtkPolyData* input)
{
  run.callback->SetCallback(EventLog::Callback);
  run.callback->SetClientData(&run.log);
  run.filter->AddObserver(vtkCommand::ErrorEvent, run.callback);
  run.filter->AddObserver(vtkCommand::WarningEvent, run.callback);
  run.filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, run.callback);
  run.filter->SetInputData(input);
  run.status = run.filter->GetExecutive()->Update();
  run.output = run.filter->GetOutput(0);
}

vtkSmartPointer<vtkPolyData> MakePolyData(const std::vector<Vec3>& points,
  const std::vector<std::vector<vtkIdType>>& polys)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const Vec3& p : points)
    pts->InsertNextPoint(p.x(), p.y(), p.z());
  pd->SetPoints(pts);
  vtkNew<vtkCellArray> cells;
  for (const auto& c : polys)
    cells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  pd->SetPolys(cells);
  return pd;
}

/// `configure` sets parameters before the run; the first error must contain `mustContain`.
void ExpectFailure(const std::string& name,
  vtkPolyData* input,
  const std::function<void(vtkSymmetryPlaneDetector*)>& configure = nullptr,
  const std::string& mustContain = std::string())
{
  Run run;
  if (configure)
    configure(run.filter);
  Execute(run, input);
  EXPECT(run.status == 0, name << ": Update() returned " << run.status << ", expected 0");
  EXPECT(!run.log.errors.empty() && !run.log.errors[0].empty(),
    name << ": no ErrorEvent with a message");
  EXPECT(run.log.errors.empty() || run.log.errors[0].find(mustContain) != std::string::npos,
    name << ": the error does not mention \"" << mustContain << "\"");
  std::printf("%-28s -> error: %s",
    name.c_str(),
    run.log.errors.empty() ? "(none)\n" : run.log.errors[0].c_str());
}

/// The result invariants of a successful run; returns the SymmetryRegion labels.
std::vector<int> ExpectSuccess(const std::string& name, Run& run, vtkPolyData* input)
{
  std::vector<int> labels;
  EXPECT(run.status == 1, name << ": Update() returned " << run.status);
  EXPECT(run.log.errors.empty() && run.log.executiveErrors.empty(),
    name << ": unexpected error: " << (run.log.errors.empty() ? "" : run.log.errors[0]));
  if (run.status != 1)
    return labels;
  const double* n = run.filter->GetPlaneNormal();
  EXPECT(std::abs(Vec3(n[0], n[1], n[2]).norm() - 1.0) < 1e-12, name << ": normal not unit");
  const double fraction = run.filter->GetSymmetricAreaFraction();
  EXPECT(fraction >= 0.0 && fraction <= 1.0, name << ": area fraction " << fraction);
  vtkPolyData* out = run.output;
  EXPECT(out->GetNumberOfPoints() == input->GetNumberOfPoints(), name << ": point count changed");
  vtkDataArray* region = out->GetCellData()->GetArray("SymmetryRegion");
  EXPECT(region && region->GetNumberOfTuples() == out->GetNumberOfCells(),
    name << ": no SymmetryRegion");
  if (region)
    for (vtkIdType c = 0; c < region->GetNumberOfTuples(); ++c)
    {
      const double v = region->GetTuple1(c);
      EXPECT(v == 0 || v == 1 || v == 2, name << ": SymmetryRegion value " << v);
      labels.push_back(static_cast<int>(v));
    }
  vtkDataArray* fieldNormal = out->GetFieldData()->GetArray("SymmetryPlaneNormal");
  EXPECT(fieldNormal &&
      std::abs(Vec3(fieldNormal->GetComponent(0, 0),
                 fieldNormal->GetComponent(0, 1),
                 fieldNormal->GetComponent(0, 2))
                 .norm() -
        1.0) < 1e-12,
    name << ": field SymmetryPlaneNormal missing or not unit");
  vtkDataArray* fieldFraction = out->GetFieldData()->GetArray("SymmetricAreaFraction");
  EXPECT(fieldFraction && fieldFraction->GetTuple1(0) == fraction,
    name << ": field SymmetricAreaFraction");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    out->GetCellPoints(c, npts, pts); // GetCellSize() is VTK >= 9.2
    if (npts != 3)
    {
      EXPECT(false, name << ": output cell " << c << " has " << npts << " points");
      break;
    }
  }
  std::printf("%-28s -> ok: found %d, area fraction %.3f, normal (%.3f %.3f %.3f)\n",
    name.c_str(),
    int(run.filter->GetSymmetryFound()),
    fraction,
    n[0],
    n[1],
    n[2]);
  return labels;
}

/// Smallest angle between the found normal and a list of plane normals.
double BestAngle(vtkSymmetryPlaneDetector* f, const std::vector<Vec3>& normals)
{
  const double* n = f->GetPlaneNormal();
  double best = 90;
  for (const Vec3& m : normals)
    best = std::min(best, foldingmeshes::testing::PlaneAngleDegrees(Vec3(n[0], n[1], n[2]), m));
  return best;
}

/// Box [-1,1] x [-0.7,0.7] x [-0.4,0.4] made of n^3-lattice quads (shared points, closed).
vtkSmartPointer<vtkPolyData> QuadBox(int n)
{
  std::map<std::array<int, 3>, vtkIdType> ids;
  std::vector<Vec3> points;
  auto id = [&](int i, int j, int k)
  {
    const std::array<int, 3> key{ i, j, k };
    auto it = ids.find(key);
    if (it != ids.end())
      return it->second;
    points.push_back(Vec3(-1 + 2.0 * i / n, -0.7 + 1.4 * j / n, -0.4 + 0.8 * k / n));
    return ids[key] = static_cast<vtkIdType>(points.size() - 1);
  };
  std::vector<std::vector<vtkIdType>> quads;
  for (int axis = 0; axis < 3; ++axis)
    for (int side : { 0, n })
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
        {
          auto at = [&](int u, int v)
          {
            int c[3];
            c[axis] = side;
            c[(axis + 1) % 3] = u;
            c[(axis + 2) % 3] = v;
            return id(c[0], c[1], c[2]);
          };
          std::vector<vtkIdType> q = { at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1) };
          if (side == 0)
            std::swap(q[1], q[3]); // outward
          quads.push_back(q);
        }
  return MakePolyData(points, quads);
}

/// Hexagonal prism (radius 1, z in [-0.75, 0.75]): two hexagons and six quads.
vtkSmartPointer<vtkPolyData> HexPrism()
{
  std::vector<Vec3> points;
  for (double z : { -0.75, 0.75 })
    for (int k = 0; k < 6; ++k)
      points.push_back(Vec3(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), z));
  std::vector<std::vector<vtkIdType>> polys = { { 5, 4, 3, 2, 1, 0 }, { 6, 7, 8, 9, 10, 11 } };
  for (int k = 0; k < 6; ++k)
    polys.push_back({ k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k });
  return MakePolyData(points, polys);
}

/// Open hemisphere z >= 0 (latitude-longitude grid with a pole), radius 1.
vtkSmartPointer<vtkPolyData> Hemisphere(int rings, int sectors)
{
  std::vector<Vec3> points = { Vec3(0, 0, 1) };
  for (int r = 1; r <= rings; ++r)
    for (int s = 0; s < sectors; ++s)
    {
      const double theta = 0.5 * M_PI * r / rings, phi = 2 * M_PI * s / sectors;
      points.push_back(
        Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  auto ring = [sectors](int r, int s)
  { return static_cast<vtkIdType>(1 + (r - 1) * sectors + (s % sectors)); };
  std::vector<std::vector<vtkIdType>> tris;
  for (int s = 0; s < sectors; ++s)
    tris.push_back({ 0, ring(1, s), ring(1, s + 1) });
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < sectors; ++s)
    {
      tris.push_back({ ring(r, s), ring(r + 1, s), ring(r + 1, s + 1) });
      tris.push_back({ ring(r, s), ring(r + 1, s + 1), ring(r, s + 1) });
    }
  return MakePolyData(points, tris);
}

/// Checks that each output triangle lies in the input polygon whose "PolyId" value it carries.
void CheckTriangulation(const std::string& name, vtkPolyData* input, vtkPolyData* output)
{
  vtkDataArray* polyId = output->GetCellData()->GetArray("PolyId");
  EXPECT(polyId, name << ": cell array PolyId lost");
  if (!polyId)
    return;
  vtkNew<vtkIdList> in, out;
  double area = 0.0;
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    output->GetCellPoints(c, out);
    input->GetCellPoints(static_cast<vtkIdType>(polyId->GetTuple1(c)), in);
    std::set<vtkIdType> polygon;
    for (vtkIdType k = 0; k < in->GetNumberOfIds(); ++k)
      polygon.insert(in->GetId(k));
    bool inside = out->GetNumberOfIds() == 3;
    for (vtkIdType k = 0; inside && k < 3; ++k)
      inside = polygon.count(out->GetId(k)) > 0;
    EXPECT(inside,
      name << ": output triangle " << c << " is not in input polygon " << polyId->GetTuple1(c));
    Vec3 p[3];
    for (int k = 0; k < 3 && k < out->GetNumberOfIds(); ++k)
      output->GetPoint(out->GetId(k), p[k].data());
    area += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  }
  // The triangles tile the polygons: same total area as the input surface.
  double expected = 0.0;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    input->GetCellPoints(c, in);
    Vec3 a, b, d;
    input->GetPoint(in->GetId(0), a.data());
    for (vtkIdType k = 1; k + 1 < in->GetNumberOfIds(); ++k)
    {
      input->GetPoint(in->GetId(k), b.data());
      input->GetPoint(in->GetId(k + 1), d.data());
      expected += 0.5 * (b - a).cross(d - a).norm(); // convex polygons: a fan is exact
    }
  }
  EXPECT(std::abs(area - expected) < 1e-12 * expected,
    name << ": triangles cover area " << area << ", polygons " << expected);
}

void AddPolyIds(vtkPolyData* pd)
{
  vtkNew<vtkIntArray> ids;
  ids->SetName("PolyId");
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
    ids->InsertNextValue(static_cast<int>(c));
  pd->GetCellData()->AddArray(ids);
}

bool SameBits(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
    return false;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < a->GetNumberOfComponents(); ++k)
    {
      const double x = a->GetComponent(i, k), y = b->GetComponent(i, k);
      if (std::memcmp(&x, &y, sizeof(double)) != 0)
        return false;
    }
  return true;
}

/// Bit-identical results of two runs (plane, found, fraction and all output arrays).
bool SameResult(Run& a, Run& b, std::string& what)
{
  what.clear();
  if (std::memcmp(a.filter->GetPlaneNormal(), b.filter->GetPlaneNormal(), 3 * sizeof(double)) ||
    std::memcmp(a.filter->GetPlaneOrigin(), b.filter->GetPlaneOrigin(), 3 * sizeof(double)))
    what += " plane";
  if (a.filter->GetSymmetryFound() != b.filter->GetSymmetryFound() ||
    a.filter->GetSymmetricAreaFraction() != b.filter->GetSymmetricAreaFraction())
    what += " found/fraction";
  if (!SameBits(a.output->GetCellData()->GetArray("SymmetryRegion"),
        b.output->GetCellData()->GetArray("SymmetryRegion")))
    what += " SymmetryRegion";
  for (const char* name : { "SymmetryDistance", "SymmetryWeight" })
    if (!SameBits(
          a.output->GetPointData()->GetArray(name), b.output->GetPointData()->GetArray(name)))
      what += std::string(" ") + name;
  return what.empty();
}
}

/// A copy of `input` with every coordinate multiplied by `scale`.
vtkSmartPointer<vtkPolyData> ScaledCopy(vtkPolyData* input, double scale)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(input);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    points->SetPoint(i, scale * p[0], scale * p[1], scale * p[2]);
  }
  copy->SetPoints(points);
  return copy;
}

int main()
{
  using namespace foldingmeshes::testing;
  const auto t0 = std::chrono::steady_clock::now();
  const double nan = std::numeric_limits<double>::quiet_NaN();

  // ---- Failures ----
  {
    vtkNew<vtkPolyData> empty;
    ExpectFailure("empty poly data", empty);

    vtkNew<vtkPolyData> pointsOnly;
    vtkNew<vtkPoints> pts;
    for (int i = 0; i < 10; ++i)
      pts->InsertNextPoint(i, i * i, 1.0 / (1 + i));
    pointsOnly->SetPoints(pts);
    ExpectFailure("points without cells", pointsOnly);

    vtkNew<vtkPolyData> linesVerts;
    linesVerts->SetPoints(pts);
    vtkNew<vtkCellArray> lines, verts;
    const vtkIdType line[3] = { 0, 1, 2 }, vert[2] = { 3, 4 };
    lines->InsertNextCell(3, line);
    verts->InsertNextCell(2, vert);
    linesVerts->SetLines(lines);
    linesVerts->SetVerts(verts);
    ExpectFailure("only lines and vertices", linesVerts);

    for (double bad : { nan, std::numeric_limits<double>::infinity() })
    {
      ProceduralMesh blob = MakeBilateralBlob(600);
      double p[3];
      blob.mesh->GetPoint(17, p);
      p[1] = bad;
      blob.mesh->GetPoints()->SetPoint(17, p);
      ExpectFailure(std::isnan(bad) ? "NaN coordinate" : "Inf coordinate", blob.mesh);
    }

    // Triangles with collinear or coincident points only.
    auto degenerate =
      MakePolyData({ Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3), Vec3(1, 1, 1) },
        { { 0, 1, 2 }, { 1, 2, 3 }, { 1, 4, 2 }, { 0, 0, 3 } });
    ExpectFailure("all faces degenerate", degenerate);

    // Point ids out of range (a negative id used to crash, a small one to read out of bounds),
    // in a triangle and in a quad (triangulated before the core sees it).
    const std::vector<Vec3> tetra{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1) };
    for (vtkIdType bad : { vtkIdType(-1000000), vtkIdType(-1), vtkIdType(4), vtkIdType(7) })
    {
      const std::string id = std::to_string(static_cast<long long>(bad));
      ExpectFailure("triangle with point id " + id,
        MakePolyData(tetra, { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, bad } }),
        nullptr,
        "a triangle refers to a point that does not exist");
      ExpectFailure("quad with point id " + id,
        MakePolyData(tetra, { { 0, 1, 2 }, { 0, 1, 3, bad } }),
        nullptr,
        "a triangle refers to a point that does not exist");
    }

    // Parameters that pass the clamping setters (NaN) or are unusable.
    ProceduralMesh blob = MakeBilateralBlob(600);
    ExpectFailure("Tolerance NaN",
      blob.mesh,
      [&](vtkSymmetryPlaneDetector* f) { f->SetTolerance(nan); },
      "Tolerance must be a positive, finite number");
    ExpectFailure("absolute Tolerance NaN",
      blob.mesh,
      [&](vtkSymmetryPlaneDetector* f)
      {
        f->SetToleranceMode(vtkSymmetryPlaneDetector::ABSOLUTE);
        f->SetTolerance(nan);
      },
      "Tolerance must be a positive, finite number");
    ExpectFailure("CompatibilityAngle NaN",
      blob.mesh,
      [&](vtkSymmetryPlaneDetector* f) { f->SetCompatibilityAngle(nan); },
      "CompatibilityAngle");
    ExpectFailure("MinimumSymmetricAreaFraction NaN",
      blob.mesh,
      [&](vtkSymmetryPlaneDetector* f) { f->SetMinimumSymmetricAreaFraction(nan); },
      "MinimumSymmetricAreaFraction");
    for (const Vec3& normal :
      { Vec3(0, 0, 0), Vec3(nan, 0, 0), Vec3(std::numeric_limits<double>::infinity(), 0, 0) })
      ExpectFailure("initial normal (" + std::to_string(normal.x()) + " 0 0)",
        blob.mesh,
        [&](vtkSymmetryPlaneDetector* f)
        {
          f->SetUseInitialPlane(true);
          f->SetInitialPlaneNormal(normal.data());
        },
        "finite, non-zero normal");
    ExpectFailure("initial origin NaN",
      blob.mesh,
      [&](vtkSymmetryPlaneDetector* f)
      {
        f->SetUseInitialPlane(true);
        f->SetInitialPlaneOrigin(nan, 0, 0);
      },
      "finite origin");
  }

  // ---- Scale: outside the supported diagonals [1e-60, 1e60] a clear error, inside a result ----
  {
    ProceduralMesh blob = MakeBilateralBlob(600);
    Run reference;
    Execute(reference, blob.mesh);
    for (double scale : { 1e-100, 1e-62, 1e62, 1e150, 1e200, 1e300 })
      ExpectFailure("blob scaled by 1e" +
          std::to_string(static_cast<int>(std::round(std::log10(scale)))),
        ScaledCopy(blob.mesh, scale),
        nullptr,
        "is outside the supported range [1e-60, 1e+60]");
    for (double scale : { std::ldexp(1.0, -196), std::ldexp(1.0, 196) })
    {
      vtkSmartPointer<vtkPolyData> scaled = ScaledCopy(blob.mesh, scale);
      Run run;
      Execute(run, scaled);
      const std::string name = "blob scaled by 2^" + std::to_string(std::ilogb(scale));
      ExpectSuccess(name, run, scaled);
      const double *n = run.filter->GetPlaneNormal(), *m = reference.filter->GetPlaneNormal();
      EXPECT(run.status == 1 && run.filter->GetSymmetryFound() == reference.filter->GetSymmetryFound() &&
          std::abs(run.filter->GetSymmetricAreaFraction() -
            reference.filter->GetSymmetricAreaFraction()) < 0.01 &&
          std::abs(std::abs(Vec3(n[0], n[1], n[2]).dot(Vec3(m[0], m[1], m[2]))) - 1.0) < 1e-4,
        name << ": not the plane and region of the unscaled blob");
    }
  }

  // ---- An initial normal whose norm overflows is still a direction ----
  for (int method : { vtkSymmetryPlaneDetector::ROBUST, vtkSymmetryPlaneDetector::PAPER })
  {
    ProceduralMesh blob = MakeBilateralBlob(600);
    Run run, reference;
    for (Run* r : { &run, &reference })
    {
      r->filter->SetMethod(method);
      r->filter->SetUseInitialPlane(true);
    }
    run.filter->SetInitialPlaneNormal(1e300, 0, 1e300);
    reference.filter->SetInitialPlaneNormal(1, 0, 1);
    Execute(run, blob.mesh);
    Execute(reference, blob.mesh);
    ExpectSuccess("initial normal (1e300 0 1e300)", run, blob.mesh);
    const double *n = run.filter->GetPlaneNormal(), *m = reference.filter->GetPlaneNormal();
    EXPECT(run.status == 1 && Vec3(n[0], n[1], n[2]) == Vec3(m[0], m[1], m[2]),
      "initial normal (1e300 0 1e300) does not give the result of (1 0 1)");
  }

  // ---- Quads and hexagons ----
  {
    auto box = QuadBox(6);
    AddPolyIds(box);
    Run run;
    Execute(run, box);
    ExpectSuccess("quad box", run, box);
    if (run.status == 1)
    {
      EXPECT(run.output->GetNumberOfCells() == 2 * box->GetNumberOfCells(),
        "quad box: " << run.output->GetNumberOfCells() << " triangles for "
                     << box->GetNumberOfCells() << " quads");
      CheckTriangulation("quad box", box, run.output);
      // Every lattice vertex has its mirror image in the lattice: exactly symmetric about x, y, z =
      // 0.
      EXPECT(run.filter->GetSymmetryFound() && run.filter->GetSymmetricAreaFraction() > 0.9 &&
          BestAngle(run.filter, { Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ() }) < 1.0,
        "quad box: not found symmetric about a coordinate plane");
    }
  }
  {
    auto prism = HexPrism();
    AddPolyIds(prism);
    Run run;
    Execute(run, prism);
    ExpectSuccess("hexagonal prism", run, prism);
    if (run.status == 1)
    {
      EXPECT(run.output->GetNumberOfCells() == 2 * 4 + 6 * 2,
        "hexagonal prism: " << run.output->GetNumberOfCells() << " triangles, expected 20");
      CheckTriangulation("hexagonal prism", prism, run.output);
      std::vector<Vec3> mirrors = { Vec3::UnitZ() };
      for (int k = 0; k < 6; ++k) // vertical planes through vertices and through edge midpoints
        mirrors.push_back(Vec3(std::cos(k * M_PI / 6), std::sin(k * M_PI / 6), 0));
      EXPECT(run.filter->GetSymmetryFound() && BestAngle(run.filter, mirrors) < 1.0,
        "hexagonal prism: not found symmetric about one of its 7 mirror planes");
    }
  }

  // ---- Unusual but valid meshes ----
  {
    // Three triangles on the edge (0,0,-1)-(0,0,1), fins at 0, 120 and 240 degrees.
    std::vector<Vec3> p = { Vec3(0, 0, -1), Vec3(0, 0, 1) };
    for (int k = 0; k < 3; ++k)
      p.push_back(Vec3(std::cos(2 * M_PI * k / 3), std::sin(2 * M_PI * k / 3), 0));
    auto fin = MakePolyData(p, { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 0, 4 } });
    Run run;
    Execute(run, fin);
    ExpectSuccess("non-manifold fin", run, fin);
  }
  {
    auto hemisphere = Hemisphere(10, 24);
    Run run;
    Execute(run, hemisphere);
    ExpectSuccess("open hemisphere", run, hemisphere);
  }
  {
    ProceduralMesh parts = MakeMultiPartSymmetric(3000);
    Run run;
    Execute(run, parts.mesh);
    ExpectSuccess("multi-part symmetric", run, parts.mesh);
  }
  {
    ProceduralMesh blob = MakeAsymmetricBlob(3000, 2);
    vtkPolyData* in = blob.mesh;
    vtkNew<vtkDoubleArray> temperature;
    temperature->SetName("Temperature");
    for (vtkIdType i = 0; i < in->GetNumberOfPoints(); ++i)
      temperature->InsertNextValue(std::sin(0.37 * i) * 100 + i);
    in->GetPointData()->SetScalars(temperature);
    vtkNew<vtkIntArray> material;
    material->SetName("Material");
    material->SetNumberOfComponents(2);
    for (vtkIdType c = 0; c < in->GetNumberOfCells(); ++c)
    {
      material->InsertNextValue(static_cast<int>(c % 7));
      material->InsertNextValue(static_cast<int>(3 * c + 1));
    }
    in->GetCellData()->AddArray(material);
    Run run;
    Execute(run, in);
    ExpectSuccess("asymmetric blob", run, in);
    if (run.status == 1)
    {
      EXPECT(!run.filter->GetSymmetryFound(), "asymmetric blob: SymmetryFound is true");
      vtkDataArray* found = run.output->GetFieldData()->GetArray("SymmetryFound");
      EXPECT(found && found->GetTuple1(0) == 0.0, "asymmetric blob: field SymmetryFound not 0");
      // Input arrays on output 0, same values (the input is all triangles: cells map 1:1).
      EXPECT(run.output->GetNumberOfCells() == in->GetNumberOfCells(),
        "asymmetric blob: cell count changed");
      EXPECT(SameBits(in->GetPointData()->GetArray("Temperature"),
               run.output->GetPointData()->GetArray("Temperature")),
        "point array Temperature missing or changed");
      EXPECT(SameBits(in->GetCellData()->GetArray("Material"),
               run.output->GetCellData()->GetArray("Material")),
        "cell array Material missing or changed");
    }
  }

  // ---- Determinism and SMP backends ----
  {
    ProceduralMesh m = MakeBlobWithAsymmetricPart(3000, 0.3, 4);
    ApplyRigidMotion(m, RandomRigidMotion(9));
    std::string what;
    Run a, b;
    Execute(a, m.mesh);
    Execute(b, m.mesh);
    ExpectSuccess("determinism run 1", a, m.mesh);
    EXPECT(a.status == 1 && b.status == 1 && SameResult(a, b, what), "two runs differ:" << what);
    // Re-execution of the same filter.
    Run c;
    Execute(c, m.mesh);
    vtkNew<vtkPolyData> first;
    first->DeepCopy(c.output);
    c.filter->Modified();
    c.status = c.filter->GetExecutive()->Update();
    EXPECT(c.status == 1 &&
        SameBits(first->GetCellData()->GetArray("SymmetryRegion"),
          c.output->GetCellData()->GetArray("SymmetryRegion")) &&
        SameResult(a, c, what),
      "re-execution differs:" << what);

    EXPECT(vtkSMPTools::SetBackend("Sequential"), "SetBackend(Sequential) failed");
    Run sequential;
    Execute(sequential, m.mesh);
    EXPECT(vtkSMPTools::SetBackend("STDThread"), "SetBackend(STDThread) failed");
    vtkSMPTools::Initialize(2);
    EXPECT(std::strcmp(vtkSMPTools::GetBackend(), "STDThread") == 0 &&
        vtkSMPTools::GetEstimatedNumberOfThreads() == 2,
      "STDThread backend with 2 threads not active: "
        << vtkSMPTools::GetBackend() << ", " << vtkSMPTools::GetEstimatedNumberOfThreads());
    Run threaded;
    Execute(threaded, m.mesh);
    vtkSMPTools::SetBackend("Sequential");
    EXPECT(sequential.status == 1 && threaded.status == 1 && SameResult(sequential, threaded, what),
      "Sequential and STDThread differ:" << what);
  }

  std::printf("TestSymmetryBadInput: %.2f s\n",
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  if (failures)
    std::printf("TestSymmetryBadInput: %d check(s) FAILED\n", failures);
  else
    std::printf("TestSymmetryBadInput: all checks passed\n");
  return failures ? 1 : 0;
}
