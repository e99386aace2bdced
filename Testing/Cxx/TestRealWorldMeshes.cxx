/*=========================================================================

  Program:   ApertureLighting
  Module:    TestRealWorldMeshes.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// What real files bring, through every caster (vtkAperturePrecompute, vtkOcclusionQueryVisibility
// with RAY_CAST, vtkApertureReference) alike:
// - bad point ids are refused with the cell named, the input untouched; the mappers draw nothing;
// - texture seams: a mesh with every face corner its own point (and an OBJ with per-corner vt)
//   gets the apertures of the welded mesh, from no more rays;
// - creases: shared points split, normals of their faces, each side its own aperture;
// - contacts: the foot of a wall standing on the ground sees the open half of its hemisphere,
//   the ground under the box stays closed;
// - self-hits: folded and sliver triangles of a scan close no point, real crevices stay dark;
// - refinement: large faces get points for contact shadows, point data interpolated, cell data
//   copied, texture seams kept.
// Each visible fraction is of the hemisphere around the point's normal: uniform in solid angle
// for the precompute (1 - cos r) and the visibility matrix (the visible directions' weights over
// those of the directions above the tangent plane), cosine-weighted for the reference (its sky).

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkApertureReference.h"
#include "vtkApertureTestHarness.h"
#include "vtkCompositeApertureLightingMapper.h"
#include "vtkOcclusionQueryVisibility.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkStripper.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkTriangle.h"
#include "vtkTriangleFilter.h"

#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;
constexpr double Pi = vtkMath::Pi();

enum Caster
{
  PRECOMPUTE,
  VISIBILITY,
  REFERENCE
};
const char* const CasterNames[] = { "precompute", "RayCast visibility", "reference" };

struct Result
{
  bool Ok = false;
  vtkSmartPointer<vtkPolyData> Output;
  std::vector<double> Fraction; // per output point
  std::string Error;
  vtkIdType SurfacePoints = 0; // precompute only
};

// The sentence of an error message (after "ClassName (address): ", up to its line's end).
std::string Sentence(const std::string& message)
{
  const size_t start = message.find("): ");
  const size_t begin = start == std::string::npos ? 0 : start + 3;
  return message.substr(begin, message.find('\n', begin) - begin);
}

// Runs a caster on `input`; the visible fraction of every output point.
Result Run(Caster caster, vtkPolyData* input, int rays = 256, double featureAngle = 60.0,
  double maximumEdge = 0.0)
{
  Result result;
  vtkSmartPointer<vtkAlgorithm> filter;
  vtkNew<vtkTest::ErrorObserver> errors;
  if (caster == PRECOMPUTE)
  {
    auto precompute = vtkSmartPointer<vtkAperturePrecompute>::New();
    precompute->SetNumberOfRays(rays);
    precompute->SetFeatureAngle(featureAngle);
    precompute->SetMaximumEdgeLength(maximumEdge);
    filter = precompute;
  }
  else if (caster == VISIBILITY)
  {
    auto visibility = vtkSmartPointer<vtkOcclusionQueryVisibility>::New();
    visibility->SetBackendToRayCast();
    visibility->SetLevel(rays >= 1024 ? 4 : 3);
    visibility->SetFeatureAngle(featureAngle);
    filter = visibility;
  }
  else
  {
    auto reference = vtkSmartPointer<vtkApertureReference>::New();
    reference->SetSourceToSky();
    reference->SetNumberOfSamples(rays);
    reference->SetFeatureAngle(featureAngle);
    filter = reference;
  }
  filter->SetInputDataObject(input);
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  result.Ok = filter->GetExecutive()->Update() != 0;
  result.Error = errors->GetError() ? Sentence(errors->GetErrorMessage()) : std::string();
  if (!result.Ok)
  {
    return result;
  }
  result.Output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  vtkPointData* pd = result.Output->GetPointData();
  const vtkIdType n = result.Output->GetNumberOfPoints();
  result.Fraction.resize(n);
  if (caster == PRECOMPUTE)
  {
    result.SurfacePoints = vtkAperturePrecompute::SafeDownCast(filter)->GetNumberOfSurfacePoints();
    vtkDataArray* radius = pd->GetArray("ApertureRadius");
    for (vtkIdType i = 0; i < n; ++i)
    {
      result.Fraction[i] = 1.0 - std::cos(radius->GetTuple1(i));
    }
  }
  else if (caster == VISIBILITY)
  {
    vtkDataArray* matrix = pd->GetArray("Visibility");
    vtkDataArray* weights = result.Output->GetFieldData()->GetArray("LightWeights");
    vtkDataArray* directions = result.Output->GetFieldData()->GetArray("LightDirections");
    vtkDataArray* normals = pd->GetNormals();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double seen = 0.0, above = 0.0, normal[3], l[3];
      normals->GetTuple(i, normal);
      for (int j = 0; j < matrix->GetNumberOfComponents(); ++j)
      {
        directions->GetTuple(j, l);
        seen += matrix->GetComponent(i, j) > 0.0 ? weights->GetTuple1(j) : 0.0;
        above += vtkMath::Dot(normal, l) > 0.0 ? weights->GetTuple1(j) : 0.0;
      }
      result.Fraction[i] = above > 0.0 ? seen / above : 0.0;
    }
  }
  else
  {
    vtkDataArray* irradiance = pd->GetArray("ReferenceIrradiance");
    for (vtkIdType i = 0; i < n; ++i)
    {
      result.Fraction[i] = irradiance->GetTuple1(i);
    }
  }
  return result;
}

vtkSmartPointer<vtkPolyData> Triangles(vtkAlgorithm* source)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(triangles->GetOutput());
  return pd;
}

// Every triangle corner its own point, with the corner's texture coordinate: what an OBJ
// reader makes of a file with vt seams everywhere.
vtkSmartPointer<vtkPolyData> Explode(vtkPolyData* mesh)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    std::vector<vtkIdType> corners;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      corners.push_back(points->InsertNextPoint(mesh->GetPoint(ids[k])));
      tcoords->InsertNextTuple2(0.1 * k, 0.001 * corners.size());
    }
    cells->InsertNextCell(npts, corners.data());
  }
  auto exploded = vtkSmartPointer<vtkPolyData>::New();
  exploded->SetPoints(points);
  exploded->SetPolys(cells);
  exploded->GetPointData()->SetTCoords(tcoords);
  return exploded;
}

// The mesh written as an OBJ file with one vt per face corner, and read back.
vtkSmartPointer<vtkPolyData> SeamOBJ(vtkPolyData* mesh, const std::string& path)
{
  {
    std::ofstream obj(path);
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      const double* p = mesh->GetPoint(i);
      obj << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    vtkIdType npts, corner = 0;
    const vtkIdType* ids;
    vtkCellArray* polys = mesh->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
    {
      obj << "vt 0.1 0.2\nvt 0.3 0.4\nvt 0.5 0.6\nf";
      for (vtkIdType k = 0; k < npts; ++k)
      {
        obj << " " << ids[k] + 1 << "/" << ++corner;
      }
      obj << "\n";
    }
  }
  // The file's own coordinates, as written, are the welded reference.
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->ShallowCopy(reader->GetOutput());
  return pd;
}

// The output point of `welded` at the same position as point i of `split`, whose normal is
// closest to that point's: the same surface point.
struct PositionIndex
{
  std::map<std::array<double, 3>, std::vector<vtkIdType>> Points;
  explicit PositionIndex(vtkPolyData* pd)
  {
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      const double* p = pd->GetPoint(i);
      this->Points[{ p[0], p[1], p[2] }].push_back(i);
    }
  }
  vtkIdType Find(vtkPolyData* welded, vtkPolyData* split, vtkIdType i) const
  {
    const double* p = split->GetPoint(i);
    const auto found = this->Points.find({ p[0], p[1], p[2] });
    if (found == this->Points.end())
    {
      return -1;
    }
    double n[3], m[3];
    split->GetPointData()->GetNormals()->GetTuple(i, n);
    vtkIdType best = found->second.front();
    double closest = -2.0;
    for (vtkIdType candidate : found->second)
    {
      welded->GetPointData()->GetNormals()->GetTuple(candidate, m);
      if (vtkMath::Dot(n, m) > closest)
      {
        closest = vtkMath::Dot(n, m);
        best = candidate;
      }
    }
    return best;
  }
};

double AngleBetween(vtkDataArray* a, vtkIdType i, vtkDataArray* b, vtkIdType j)
{
  double u[3], v[3];
  a->GetTuple(i, u);
  b->GetTuple(j, v);
  return vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(u, v));
}

//------------------------------------------------------------------------------
void TestBadPointIds()
{
  vtkNew<vtkPlaneSource> source;
  source->SetResolution(10, 10);
  const vtkSmartPointer<vtkPolyData> plane = Triangles(source);
  const vtkIdType n = plane->GetNumberOfPoints();
  struct Case
  {
    std::string What;
    std::vector<vtkIdType> Cell;
    bool Storage64;
  };
  const std::vector<Case> cases = { { "an id past the end", { 0, 1, n + 99 }, false },
    { "a negative id", { -1, 0, 1 }, false }, { "id 4000000000", { 0, 4000000000LL, 1 }, true } };
  for (const Case& c : cases)
  {
    auto bad = vtkSmartPointer<vtkPolyData>::New();
    bad->DeepCopy(plane);
    vtkNew<vtkCellArray> polys;
    if (c.Storage64)
    {
      polys->Use64BitStorage();
    }
    polys->DeepCopy(plane->GetPolys());
    polys->InsertNextCell(3, c.Cell.data());
    bad->SetPolys(polys);
    const vtkIdType arrays = bad->GetPointData()->GetNumberOfArrays();
    const vtkIdType cells = bad->GetNumberOfCells();
    for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
    {
      const Result r = Run(caster, bad, 16);
      const std::string what = std::string(CasterNames[caster]) + ", " + c.What;
      std::cout << what << ": " << r.Error << "\n";
      Check(!r.Ok && r.Error.find("polygon 200") != std::string::npos &&
          r.Error.find("uses point id") != std::string::npos,
        what + ": an error naming the first bad cell");
      Check(bad->GetPointData()->GetNumberOfArrays() == arrays && bad->GetNumberOfCells() == cells,
        what + ": the input untouched");
    }
  }

  // Offsets that do not describe the connectivity.
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  for (vtkIdType v : { 0, 3, 7 })
  {
    offsets->InsertNextValue(v);
  }
  for (vtkIdType v : { 0, 1, 2, 2, 1, 3 })
  {
    connectivity->InsertNextValue(v);
  }
  vtkNew<vtkCellArray> damaged;
  damaged->SetData(offsets, connectivity);
  auto broken = vtkSmartPointer<vtkPolyData>::New();
  broken->SetPoints(plane->GetPoints());
  broken->SetPolys(damaged);
  const Result r = Run(PRECOMPUTE, broken, 16);
  Check(!r.Ok && r.Error.find("damaged") != std::string::npos, "damaged offsets are refused");

  // Both mappers draw nothing, with an error, instead of reading through bad ids.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  auto bad = vtkSmartPointer<vtkPolyData>::New();
  bad->DeepCopy(plane);
  const vtkIdType cell[3] = { 0, 1, n + 500000 };
  bad->GetPolys()->InsertNextCell(3, cell);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, plane);
  blocks->SetBlock(1, bad);
  vtkNew<vtkApertureLightingMapper> single;
  single->SetInputData(bad);
  vtkNew<vtkCompositeApertureLightingMapper> composite;
  composite->SetInputDataObject(blocks);
  for (vtkMapper* mapper : { static_cast<vtkMapper*>(single), static_cast<vtkMapper*>(composite) })
  {
    vtkNew<vtkTest::ErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    window->Render();
    renderer->RemoveActor(actor);
    std::cout << mapper->GetClassName() << ": " << Sentence(errors->GetErrorMessage()) << "\n";
    Check(
      errors->GetError() && errors->GetErrorMessage().find("uses point id") != std::string::npos,
      std::string(mapper->GetClassName()) + " refuses cells with bad point ids");
  }
}

//------------------------------------------------------------------------------
void TestSeams(vtkPolyData* bunny, const std::string& temporary)
{
  const vtkSmartPointer<vtkPolyData> exploded = Explode(bunny);
  const vtkSmartPointer<vtkPolyData> obj = SeamOBJ(bunny, temporary + "/bunny-seams.obj");
  // The OBJ's own coordinates (written in decimal) are the welded model it is compared with.
  vtkNew<vtkPolyData> objWelded;
  {
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputData(obj);
    clean->PointMergingOn();
    clean->SetTolerance(0.0);
    clean->Update();
    objWelded->ShallowCopy(clean->GetOutput());
    objWelded->GetPointData()->Initialize();
  }
  std::cout << "seams: the bunny has " << bunny->GetNumberOfPoints() << " points, exploded "
            << exploded->GetNumberOfPoints() << ", as an OBJ with per-corner vt "
            << obj->GetNumberOfPoints() << "\n";
  for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const std::pair<vtkPolyData*, vtkPolyData*> pairs[] = { { bunny, exploded },
      { objWelded, obj } };
    for (const auto& pair : pairs)
    {
      const Result welded = Run(caster, pair.first);
      const Result split = Run(caster, pair.second);
      const std::string what = std::string(CasterNames[caster]) +
        (pair.second == obj ? ", OBJ with vt seams" : ", exploded bunny");
      if (!welded.Ok || !split.Ok)
      {
        Check(false, what + ": runs");
        continue;
      }
      const PositionIndex index(welded.Output);
      double difference = 0.0, radiusDifference = 0.0, worstNormal = 0.0;
      vtkIdType unmatched = 0;
      vtkDataArray* weldedNormals = welded.Output->GetPointData()->GetNormals();
      vtkDataArray* splitNormals = split.Output->GetPointData()->GetNormals();
      for (vtkIdType i = 0; i < split.Output->GetNumberOfPoints(); ++i)
      {
        const vtkIdType j = index.Find(welded.Output, split.Output, i);
        if (j < 0)
        {
          ++unmatched;
          continue;
        }
        difference += std::abs(split.Fraction[i] - welded.Fraction[j]);
        radiusDifference += std::abs(
          std::acos(1.0 - split.Fraction[i]) - std::acos(1.0 - std::min(1.0, welded.Fraction[j])));
        worstNormal = std::max(worstNormal, AngleBetween(splitNormals, i, weldedNormals, j));
      }
      const double count = static_cast<double>(split.Output->GetNumberOfPoints());
      std::cout << what << ": mean |d fraction| " << difference / count << ", mean |d radius| "
                << radiusDifference / count << " rad, worst normal " << worstNormal
                << " deg, unmatched points " << unmatched << "\n";
      Check(unmatched == 0, what + ": every point is a point of the welded model");
      Check(difference / count <= 0.005, what + ": the welded model's visibility",
        difference / count, 0.0);
      Check(caster != PRECOMPUTE || radiusDifference / count <= 0.02,
        what + ": mean |d ApertureRadius| <= 0.02 rad", radiusDifference / count, 0.0);
      Check(worstNormal <= 3.0, what + ": normals within 3 degrees", worstNormal, 0.0);
      Check(caster != PRECOMPUTE || split.SurfacePoints <= welded.SurfacePoints,
        what + ": no more rays than for the welded model", static_cast<double>(split.SurfacePoints),
        static_cast<double>(welded.SurfacePoints));
    }
  }
}

//------------------------------------------------------------------------------
// Whether two outputs have the same points, polygons and point arrays, value for value.
bool SameBits(vtkPolyData* a, vtkPolyData* b)
{
  bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    a->GetPointData()->GetNumberOfArrays() == b->GetPointData()->GetNumberOfArrays();
  for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  }
  vtkNew<vtkIdTypeArray> ca, cb;
  a->GetPolys()->ExportLegacyFormat(ca);
  b->GetPolys()->ExportLegacyFormat(cb);
  same = same && ca->GetNumberOfValues() == cb->GetNumberOfValues();
  for (vtkIdType k = 0; same && k < ca->GetNumberOfValues(); ++k)
  {
    same = ca->GetValue(k) == cb->GetValue(k);
  }
  for (int k = 0; same && k < a->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* x = a->GetPointData()->GetArray(k);
    vtkDataArray* y = x ? b->GetPointData()->GetArray(x->GetName()) : nullptr;
    same = x && y && x->GetNumberOfValues() == y->GetNumberOfValues();
    for (vtkIdType v = 0; same && v < x->GetNumberOfValues(); ++v)
    {
      same = x->GetComponent(v / x->GetNumberOfComponents(), v % x->GetNumberOfComponents()) ==
        y->GetComponent(v / y->GetNumberOfComponents(), v % y->GetNumberOfComponents());
    }
  }
  return same;
}

//------------------------------------------------------------------------------
// A box whose faces share their corner points, as an STL reader merges them: a CAD part.
vtkSmartPointer<vtkPolyData> SharedBox(const double bounds[6])
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(triangles->GetOutputPort());
  merged->Update();
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->DeepCopy(merged->GetOutput());
  box->GetPointData()->Initialize();
  return box;
}

// Checks that every output point's normal is within `degrees` of the normals of all its cells.
double WorstFaceNormal(vtkPolyData* pd)
{
  double worst = 0.0;
  vtkDataArray* normals = pd->GetPointData()->GetNormals();
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    double p[3][3], face[3];
    for (int k = 0; k < 3; ++k)
    {
      pd->GetPoint(ids[k], p[k]);
    }
    vtkTriangle::ComputeNormal(p[0], p[1], p[2], face);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double n[3];
      normals->GetTuple(ids[k], n);
      worst = std::max(worst, vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(n, face)));
    }
  }
  return worst;
}

void TestCreases(vtkPolyData* bunny)
{
  const double unit[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  const vtkSmartPointer<vtkPolyData> box = SharedBox(unit);
  for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const Result split = Run(caster, box, 64);
    const Result smooth = Run(caster, box, 64, 180.0);
    const std::string what = std::string(CasterNames[caster]) + ", box with shared corners";
    if (!split.Ok || !smooth.Ok)
    {
      Check(false, what + ": runs");
      continue;
    }
    const double worst = WorstFaceNormal(split.Output);
    std::cout << what << ": " << box->GetNumberOfPoints() << " points in, "
              << split.Output->GetNumberOfPoints() << " out at 60 degrees, "
              << smooth.Output->GetNumberOfPoints() << " at 180; worst normal off its faces "
              << worst << " deg (averaged: " << WorstFaceNormal(smooth.Output) << ")\n";
    Check(split.Output->GetNumberOfPoints() == 24, "each corner split into its three faces",
      static_cast<double>(split.Output->GetNumberOfPoints()), 24);
    Check(worst < 0.01, what + ": normals of their faces, no bevels", worst, 0.0);
    Check(smooth.Output->GetNumberOfPoints() == 8, what + ": FeatureAngle 180 never splits",
      static_cast<double>(smooth.Output->GetNumberOfPoints()), 8);
    double least = 1.0;
    for (const double f : split.Fraction)
    {
      least = std::min(least, f);
    }
    Check(least > 0.99, what + ": every face of a convex part sees its hemisphere", least, 1.0);
  }

  // Strips that run across a crease (the shared box as strips) become triangles, each with its
  // strip's cell data, as vtkPolyDataNormals does.
  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(box);
  stripper->Update();
  vtkNew<vtkPolyData> stripped;
  stripped->DeepCopy(stripper->GetOutput());
  vtkNew<vtkIntArray> stripId;
  stripId->SetName("StripId");
  for (vtkIdType c = 0; c < stripped->GetNumberOfCells(); ++c)
  {
    stripId->InsertNextValue(static_cast<int>(c));
  }
  stripped->GetCellData()->AddArray(stripId);
  const Result fromStrips = Run(PRECOMPUTE, stripped, 64);
  vtkDataArray* ids = fromStrips.Output->GetCellData()->GetArray("StripId");
  std::cout << "box as " << stripped->GetNumberOfStrips()
            << " strips: " << fromStrips.Output->GetNumberOfPolys() << " triangles, "
            << fromStrips.Output->GetNumberOfStrips() << " strips out\n";
  Check(fromStrips.Output->GetNumberOfStrips() == 0 &&
      fromStrips.Output->GetNumberOfPolys() == 12 && ids && ids->GetNumberOfTuples() == 12 &&
      WorstFaceNormal(fromStrips.Output) < 0.01,
    "strips across a crease become triangles with their strip's data and their faces' normals");

  // Polygons and strips in one input (the box, and its strips moved aside): strip corners are
  // numbered after all polygon corners, so the strips still break at the creases.
  vtkNew<vtkPolyData> aside;
  aside->DeepCopy(stripped);
  for (vtkIdType i = 0; i < aside->GetNumberOfPoints(); ++i)
  {
    double p[3];
    aside->GetPoint(i, p);
    p[0] += 3.0;
    aside->GetPoints()->SetPoint(i, p);
  }
  vtkNew<vtkAppendPolyData> both;
  both->AddInputData(box);
  both->AddInputData(aside);
  both->Update();
  const Result mixed = Run(PRECOMPUTE, both->GetOutput(), 64);
  const vtkIdType boxCells = box->GetNumberOfPolys();
  std::cout << "box as " << boxCells << " polygons and " << aside->GetNumberOfStrips()
            << " strips: " << mixed.Output->GetNumberOfPolys() << " polygons, "
            << mixed.Output->GetNumberOfStrips() << " strips out\n";
  Check(mixed.Output->GetNumberOfStrips() == 0 &&
      mixed.Output->GetNumberOfPolys() == boxCells + 12 &&
      mixed.Output->GetNumberOfPoints() == 48 && WorstFaceNormal(mixed.Output) < 0.01,
    "polygons and strips in one input: every corner on its face's side");

  // A tessellated cylinder with caps: the rim splits, the 32 facets stay smooth.
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(32);
  cylinder->CappingOn();
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(cylinder->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(merged->GetOutputPort());
  triangles->Update();
  vtkNew<vtkPolyData> part;
  part->DeepCopy(triangles->GetOutput());
  part->GetPointData()->Initialize();
  const Result cad = Run(PRECOMPUTE, part, 64);
  vtkDataArray* normals = cad.Output->GetPointData()->GetNormals();
  int side = 0, cap = 0;
  for (vtkIdType i = 0; i < cad.Output->GetNumberOfPoints(); ++i)
  {
    double n[3];
    normals->GetTuple(i, n);
    side += std::abs(n[1]) < 1e-3 ? 1 : 0;
    cap += std::abs(std::abs(n[1]) - 1.0) < 1e-3 ? 1 : 0;
  }
  std::cout << "capped cylinder: " << part->GetNumberOfPoints() << " points in, "
            << cad.Output->GetNumberOfPoints() << " out: " << side << " with side normals, " << cap
            << " with cap normals\n";
  Check(side == 64 && cap == 64,
    "a capped cylinder's rims split into smooth side normals and flat cap normals");

  // A concave crease (floor and wall sharing their edge's points): each side its own aperture,
  // as for the same faces with points of their own.
  auto lShape = [](bool shared)
  {
    vtkNew<vtkPlaneSource> floor, wall;
    floor->SetOrigin(0, 0, 0);
    floor->SetPoint1(2, 0, 0);
    floor->SetPoint2(0, 2, 0);
    floor->SetResolution(8, 8);
    wall->SetOrigin(0, 0, 0);
    wall->SetPoint1(0, 2, 0);
    wall->SetPoint2(0, 0, 2);
    wall->SetResolution(8, 8);
    vtkNew<vtkAppendPolyData> both;
    both->AddInputConnection(floor->GetOutputPort());
    both->AddInputConnection(wall->GetOutputPort());
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(both->GetOutputPort());
    clean->SetPointMerging(shared);
    vtkNew<vtkTriangleFilter> tri;
    tri->SetInputConnection(clean->GetOutputPort());
    tri->Update();
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->DeepCopy(tri->GetOutput());
    pd->GetPointData()->Initialize();
    return pd;
  };
  const vtkSmartPointer<vtkPolyData> sharedL = lShape(true), separateL = lShape(false);
  for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const Result a = Run(caster, sharedL, 1024), b = Run(caster, separateL, 1024);
    if (!a.Ok || !b.Ok)
    {
      Check(false, std::string(CasterNames[caster]) + ", L crease: runs");
      continue;
    }
    const PositionIndex index(b.Output);
    double worst = 0.0, crease = 0.0;
    int onCrease = 0;
    for (vtkIdType i = 0; i < a.Output->GetNumberOfPoints(); ++i)
    {
      const vtkIdType j = index.Find(b.Output, a.Output, i);
      worst = std::max(worst, j >= 0 ? std::abs(a.Fraction[i] - b.Fraction[j]) : 1.0);
      const double* p = a.Output->GetPoint(i);
      if (p[0] == 0.0 && p[2] == 0.0 && p[1] > 0.4 && p[1] < 1.6)
      {
        crease += a.Fraction[i];
        ++onCrease;
      }
    }
    crease /= std::max(onCrease, 1);
    // On the crease each side sees a quarter of the sphere: half its hemisphere, uniformly or
    // cosine-weighted alike.
    const double expected = 0.5;
    std::cout << CasterNames[caster] << ", L crease: " << onCrease
              << " crease points (both sides) see " << crease << " (" << expected
              << "), worst difference from separate faces " << worst << "\n";
    Check(onCrease == 10, "both sides of the crease have their points", onCrease, 10);
    Check(std::abs(crease - expected) < 0.03, "a crease point sees its side's quarter sphere",
      crease, expected);
    Check(worst < 0.03, "shared points split as faces with points of their own", worst, 0.0);
  }

  // Scans: the default splits few points of the bunny (its noise), unlike 30 degrees.
  const Result scan60 = Run(PRECOMPUTE, bunny, 16);
  const Result scan30 = Run(PRECOMPUTE, bunny, 16, 30.0);
  const double split60 = double(scan60.Output->GetNumberOfPoints() - bunny->GetNumberOfPoints()) /
    bunny->GetNumberOfPoints();
  const double split30 = double(scan30.Output->GetNumberOfPoints() - bunny->GetNumberOfPoints()) /
    bunny->GetNumberOfPoints();
  std::cout << "bunny points split at 60 degrees " << 100 * split60 << "%, at 30 degrees "
            << 100 * split30 << "%\n";
  Check(split60 < 0.005 && split30 > 2 * split60, "the default splits a scan's noise rarely");

  // The sides are found on every core, a block of vertices each (the bunny has 36 blocks in 3
  // waves): one thread gives the same split points, in the same order, and the same apertures,
  // bit for bit.
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  Result oneThread;
  vtkSMPTools::LocalScope(
    vtkSMPTools::Config{ 1 }, [&]() { oneThread = Run(PRECOMPUTE, bunny, 16, 30.0); });
  vtkSMPTools::Initialize(threads); // VTK 9.1's TBB backend keeps the scope's one thread
  std::cout << "bunny at 30 degrees on " << threads
            << " threads and on 1: " << scan30.Output->GetNumberOfPoints() << " and "
            << oneThread.Output->GetNumberOfPoints() << " points\n";
  Check(SameBits(scan30.Output, oneThread.Output),
    "one thread gives the output of all of them, bit for bit");

  // Polygons are ear-cut on every core (thousands of bent quads: every cut depends on the
  // coordinates each thread reads): one thread gives the same output.
  vtkNew<vtkPlaneSource> sheet;
  sheet->SetResolution(120, 120);
  sheet->Update();
  vtkNew<vtkPolyData> quads;
  quads->DeepCopy(sheet->GetOutput());
  quads->GetPointData()->Initialize();
  for (vtkIdType i = 0; i < quads->GetNumberOfPoints(); ++i)
  {
    double p[3];
    quads->GetPoint(i, p);
    p[2] = 0.05 * std::sin(37.0 * p[0]) * std::cos(29.0 * p[1]);
    quads->GetPoints()->SetPoint(i, p);
  }
  const Result bentAll = Run(PRECOMPUTE, quads, 16);
  Result bentOne;
  vtkSMPTools::LocalScope(
    vtkSMPTools::Config{ 1 }, [&]() { bentOne = Run(PRECOMPUTE, quads, 16); });
  vtkSMPTools::Initialize(threads);
  Check(bentAll.Ok && bentOne.Ok && SameBits(bentAll.Output, bentOne.Output),
    "14,400 bent quads: one thread gives the output of all of them, bit for bit");
}

//------------------------------------------------------------------------------
// `mesh` with triangle t wound the other way where reverse(t).
vtkSmartPointer<vtkPolyData> Rewound(
  vtkPolyData* mesh, const std::function<bool(vtkIdType)>& reverse)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(mesh);
  out->GetPointData()->SetNormals(nullptr);
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
  {
    out->GetCellPoints(t, ids);
    if (reverse(t) && ids->GetNumberOfIds() == 3)
    {
      const vtkIdType flipped[3] = { ids->GetId(0), ids->GetId(2), ids->GetId(1) };
      out->ReplaceCell(t, 3, flipped);
    }
  }
  return out;
}

// Inconsistent winding: a third of the bunny's triangles reversed gives the bunny's own
// visibility; two thirds reversed, the visibility of the bunny turned inside out (each piece
// takes the winding most of its triangles have). Non-manifold edges run.
void TestWinding(vtkPolyData* bunny)
{
  const vtkSmartPointer<vtkPolyData> outward = Rewound(bunny, [](vtkIdType) { return false; });
  const vtkSmartPointer<vtkPolyData> inward = Rewound(bunny, [](vtkIdType) { return true; });
  const vtkSmartPointer<vtkPolyData> third = Rewound(bunny, [](vtkIdType t) { return t % 3 == 0; });
  const vtkSmartPointer<vtkPolyData> twoThirds =
    Rewound(bunny, [](vtkIdType t) { return t % 3 != 0; });
  for (Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const std::string what = std::string(CasterNames[caster]) + ", inconsistent winding";
    const Result out = Run(caster, outward, 64), in = Run(caster, inward, 64);
    const Result mostlyOut = Run(caster, third, 64), mostlyIn = Run(caster, twoThirds, 64);
    if (!out.Ok || !in.Ok || !mostlyOut.Ok || !mostlyIn.Ok ||
      mostlyOut.Fraction.size() != out.Fraction.size() ||
      mostlyIn.Fraction.size() != in.Fraction.size())
    {
      Check(false,
        what + ": runs, with the bunny's points (" + out.Error + in.Error + mostlyOut.Error +
          mostlyIn.Error + ")");
      continue;
    }
    // The same surface points (the points a crease adds come in the cells' corner order); the
    // bunny's points in no triangle have no estimate (NaN) from the reference.
    const PositionIndex outIndex(out.Output), inIndex(in.Output);
    auto difference = [](double a, double b)
    { return std::isnan(a) && std::isnan(b) ? 0.0 : (std::isnan(a - b) ? 1.0 : std::abs(a - b)); };
    double worstOut = 0.0, worstIn = 0.0, apart = 0.0;
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(out.Fraction.size()); ++i)
    {
      const vtkIdType o = outIndex.Find(out.Output, mostlyOut.Output, i);
      const vtkIdType n = inIndex.Find(in.Output, mostlyIn.Output, i);
      worstOut =
        std::max(worstOut, o < 0 ? 1.0 : difference(mostlyOut.Fraction[i], out.Fraction[o]));
      worstIn = std::max(worstIn, n < 0 ? 1.0 : difference(mostlyIn.Fraction[i], in.Fraction[n]));
      apart += difference(out.Fraction[i], in.Fraction[i]) / out.Fraction.size();
    }
    std::cout << what << ": worst difference " << worstOut << " (a third reversed), " << worstIn
              << " (two thirds); outward and inward differ by " << apart << " on average\n";
    Check(worstOut < 1e-6, what + ": a third reversed is the bunny", worstOut, 0.0);
    Check(worstIn < 1e-6, what + ": two thirds reversed is the bunny inside out", worstIn, 0.0);
    Check(apart > 0.1, what + ": inside out differs from outside out", apart, 0.1);
  }
  // A pyramid with one side naming the wrong corner (non-manifold edges): apertures for all.
  static const double corners[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.5, 0.5, 1 } };
  static const vtkIdType faces[5][4] = { { 0, 3, 2, 1 }, { 0, 1, 4, -1 }, { 1, 3, 4, -1 },
    { 2, 3, 4, -1 }, { 3, 0, 4, -1 } };
  vtkNew<vtkPoints> points;
  for (const double* p : corners)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  for (const vtkIdType* f : faces)
  {
    polys->InsertNextCell(f[3] < 0 ? 3 : 4, f);
  }
  vtkNew<vtkPolyData> pyramid;
  pyramid->SetPoints(points);
  pyramid->SetPolys(polys);
  for (Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const Result r = Run(caster, pyramid, 16);
    Check(r.Ok && r.Fraction.size() >= 5,
      std::string(CasterNames[caster]) + ": a non-manifold pyramid gets its apertures");
  }
}

// A 4 x 4 ground at z = 0 with a unit box standing on it (both refined to edges of 1/8): in one
// polydata, the box's corners shared between its faces; with `welded`, the ground's points
// under the box's edges are the same points as the box's.
vtkSmartPointer<vtkPolyData> BoxOnGround()
{
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-2, -2, 0);
  ground->SetPoint1(2, -2, 0);
  ground->SetPoint2(-2, 2, 0);
  ground->SetResolution(32, 32);
  const double bounds[6] = { -0.5, 0.5, -0.5, 0.5, 0.0, 1.0 };
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputData(Triangles(ground));
  scene->AddInputData(SharedBox(bounds));
  scene->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(scene->GetOutput());
  pd->GetPointData()->Initialize();
  return pd;
}

void TestContacts()
{
  // The precompute refines the box's faces; the others take its refined output as input.
  const vtkSmartPointer<vtkPolyData> scene = BoxOnGround();
  const Result refined = Run(PRECOMPUTE, scene, 1024, 60.0, 0.125);
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->DeepCopy(refined.Output);
  input->GetPointData()->Initialize();
  for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const Result r = caster == PRECOMPUTE ? refined : Run(caster, input, 1024);
    if (!r.Ok)
    {
      Check(false, std::string(CasterNames[caster]) + ", box on ground: runs");
      continue;
    }
    vtkDataArray* normals = r.Output->GetPointData()->GetNormals();
    double footLo = 1.0, footHi = 0.0, footSum = 0.0, under = 0.0;
    int feet = 0, unders = 0;
    for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
    {
      const double* p = r.Output->GetPoint(i);
      double n[3];
      normals->GetTuple(i, n);
      const bool onWall = std::max(std::abs(p[0]), std::abs(p[1])) == 0.5 && std::abs(n[2]) < 1e-6;
      if (p[2] == 0.0 && onWall && std::min(std::abs(p[0]), std::abs(p[1])) < 0.45)
      {
        footLo = std::min(footLo, r.Fraction[i]);
        footHi = std::max(footHi, r.Fraction[i]);
        footSum += r.Fraction[i];
        ++feet;
      }
      if (p[2] == 0.0 && n[2] > 0.99 && std::max(std::abs(p[0]), std::abs(p[1])) < 0.4)
      {
        under = std::max(under, r.Fraction[i]);
        ++unders;
      }
    }
    std::cout << CasterNames[caster] << ", box on ground: " << feet << " wall-foot points see "
              << footLo << " to " << footHi << " (mean " << footSum / std::max(feet, 1) << "), "
              << unders << " ground points under the box at most " << under << "\n";
    Check(feet > 20 && footLo >= 0.42 && footHi <= 0.58,
      std::string(CasterNames[caster]) + ": a wall's foot sees the open half, 0.5 +- 0.08");
    Check(unders > 20 && under <= 0.01,
      std::string(CasterNames[caster]) + ": the ground under the box stays closed", under, 0.0);
  }

  // The box as a leaf of its own beside the ground's (a multiblock), or as an occluder.
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-2, -2, 0);
  ground->SetPoint1(2, -2, 0);
  ground->SetPoint2(-2, 2, 0);
  ground->SetResolution(32, 32);
  const double bounds[6] = { -0.5, 0.5, -0.5, 0.5, 0.0, 1.0 };
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, Triangles(ground));
  blocks->SetBlock(1, SharedBox(bounds));
  vtkNew<vtkAperturePrecompute> leaves;
  leaves->SetInputData(blocks);
  leaves->SetNumberOfRays(1024);
  leaves->SetMaximumEdgeLength(0.125);
  leaves->Update();
  auto* boxLeaf = vtkPolyData::SafeDownCast(
    vtkMultiBlockDataSet::SafeDownCast(leaves->GetOutputDataObject(0))->GetBlock(1));
  double lo = 1.0, hi = 0.0;
  for (vtkIdType i = 0; i < boxLeaf->GetNumberOfPoints(); ++i)
  {
    const double* p = boxLeaf->GetPoint(i);
    double n[3];
    boxLeaf->GetPointData()->GetNormals()->GetTuple(i, n);
    if (p[2] == 0.0 && std::abs(n[2]) < 1e-6 && std::min(std::abs(p[0]), std::abs(p[1])) < 0.45)
    {
      const double f =
        1.0 - std::cos(boxLeaf->GetPointData()->GetArray("ApertureRadius")->GetTuple1(i));
      lo = std::min(lo, f);
      hi = std::max(hi, f);
    }
  }
  std::cout << "box as a leaf beside the ground's: wall feet see " << lo << " to " << hi << "\n";
  Check(lo >= 0.42 && hi <= 0.58, "a leaf standing on another leaf: the open half");
}

//------------------------------------------------------------------------------
// The bunny with the defects of real scans at 50 vertices: folded triangles (a vertex pushed
// 30% across its triangle's opposite edge, a little above, on, or under the surface), slivers
// (an edge split next to its end) and crumples (a point a hair off a triangle, fanned).
vtkSmartPointer<vtkPolyData> Damaged(vtkPolyData* bunny, std::set<vtkIdType>& touched)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(bunny);
  normals->SplittingOff();
  normals->Update();
  vtkDataArray* n = normals->GetOutput()->GetPointData()->GetNormals();
  vtkNew<vtkPoints> points;
  points->DeepCopy(bunny->GetPoints());
  std::vector<std::array<vtkIdType, 3>> triangles;
  std::map<vtkIdType, std::vector<size_t>> incident;
  vtkIdType npts;
  const vtkIdType* ids;
  for (bunny->GetPolys()->InitTraversal(); bunny->GetPolys()->GetNextCell(npts, ids);)
  {
    for (int k = 0; k < 3; ++k)
    {
      incident[ids[k]].push_back(triangles.size());
    }
    triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  double edge = 0.0;
  for (size_t t = 0; t < 1000; ++t)
  {
    edge += std::sqrt(vtkMath::Distance2BetweenPoints(
              bunny->GetPoint(triangles[t][0]), bunny->GetPoint(triangles[t][1]))) /
      1000.0;
  }
  int defect = 0;
  for (vtkIdType v = 100; v < 35000; v += 700)
  {
    if (!incident.count(v))
    {
      continue;
    }
    auto& t = triangles[incident[v][0]];
    const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
    const vtkIdType a = t[(k + 1) % 3], b = t[(k + 2) % 3];
    double pv[3], pa[3], pb[3], nv[3], x[3];
    bunny->GetPoint(v, pv);
    bunny->GetPoint(a, pa);
    bunny->GetPoint(b, pb);
    n->GetTuple(v, nv);
    touched.insert(v);
    switch (defect++ % 5)
    {
      case 0:
      case 1:
      case 2:
      {
        // A fold: v pushed across the opposite edge.
        const double lift = 0.02 * ((defect - 1) % 5 - 1) * edge;
        for (int c = 0; c < 3; ++c)
        {
          const double mid = 0.5 * (pa[c] + pb[c]);
          x[c] = mid + 0.3 * (mid - pv[c]) + lift * nv[c];
        }
        points->SetPoint(v, x);
        break;
      }
      case 3:
      {
        // Slivers: the edge (v, a) split at 1/10000 of its length.
        for (int c = 0; c < 3; ++c)
        {
          x[c] = pv[c] + 1e-4 * (pa[c] - pv[c]);
        }
        const vtkIdType m = points->InsertNextPoint(x);
        touched.insert(m);
        for (const size_t ti : std::vector<size_t>(incident[v]))
        {
          auto tri = triangles[ti];
          if (std::find(tri.begin(), tri.end(), a) == tri.end())
          {
            continue;
          }
          auto first = tri, second = tri;
          *std::find(first.begin(), first.end(), a) = m;
          *std::find(second.begin(), second.end(), v) = m;
          triangles[ti] = first;
          triangles.push_back(second);
        }
        break;
      }
      default:
      {
        // A crumple: a point a hair above the triangle, fanned to its corners.
        for (int c = 0; c < 3; ++c)
        {
          x[c] = pv[c] + 2e-4 * (pa[c] - pv[c]) + 1e-4 * (pb[c] - pv[c]) + 3e-5 * edge * nv[c];
        }
        const vtkIdType q = points->InsertNextPoint(x);
        touched.insert(q);
        const size_t ti = incident[v][0];
        triangles[ti] = { v, a, q };
        triangles.push_back({ a, b, q });
        triangles.push_back({ b, v, q });
      }
    }
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : triangles)
  {
    cells->InsertNextCell(3, t.data());
  }
  auto damaged = vtkSmartPointer<vtkPolyData>::New();
  damaged->SetPoints(points);
  damaged->SetPolys(cells);
  return damaged;
}

// Output points with (almost) nothing visible while a neighbour sees much: with the
// precompute's radius, r < 0.05 next to r > 0.6.
int IsolatedClosed(const Result& r)
{
  const double closed = 1.0 - std::cos(0.05), open = 1.0 - std::cos(0.6);
  std::vector<unsigned char> isolated(r.Output->GetNumberOfPoints(), 0);
  vtkIdType npts;
  const vtkIdType* ids;
  for (r.Output->GetPolys()->InitTraversal(); r.Output->GetPolys()->GetNextCell(npts, ids);)
  {
    for (vtkIdType a = 0; a < npts; ++a)
    {
      for (vtkIdType b = 0; b < npts; ++b)
      {
        isolated[ids[a]] |= r.Fraction[ids[a]] < closed && r.Fraction[ids[b]] > open;
      }
    }
  }
  return static_cast<int>(std::count(isolated.begin(), isolated.end(), 1));
}

// Two planes meeting at an edge along y with an opening of `opening` radians, sharing the
// edge's points; long, so that its ends leave little open to the middle of its bottom.
vtkSmartPointer<vtkPolyData> Groove(double opening)
{
  const double half = 0.5 * opening;
  vtkNew<vtkPlaneSource> left, right;
  for (const double side : { -1.0, 1.0 })
  {
    vtkPlaneSource* plane = side < 0 ? left.Get() : right.Get();
    plane->SetOrigin(0, -30, 0);
    plane->SetPoint1(0, 30, 0);
    plane->SetPoint2(side * 3 * std::sin(half), -30, 3 * std::cos(half));
    plane->SetResolution(240, 12);
  }
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(left->GetOutputPort());
  both->AddInputConnection(right->GetOutputPort());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(both->GetOutputPort());
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputConnection(clean->GetOutputPort());
  tri->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(tri->GetOutput());
  pd->GetPointData()->Initialize();
  return pd;
}

// The fraction of a groove's bottom point i's directions (the visibility's light sphere) above
// its tangent plane that see out of the groove, between walls `opening` apart: above both walls.
double GrooveFraction(vtkPolyData* output, vtkIdType i, double opening)
{
  vtkDataArray* weights = output->GetFieldData()->GetArray("LightWeights");
  vtkDataArray* directions = output->GetFieldData()->GetArray("LightDirections");
  double normal[3], l[3], seen = 0.0, above = 0.0;
  output->GetPointData()->GetNormals()->GetTuple(i, normal);
  const double slope = std::tan(0.5 * (Pi - opening)); // the walls' rise
  for (vtkIdType j = 0; j < directions->GetNumberOfTuples(); ++j)
  {
    directions->GetTuple(j, l);
    if (vtkMath::Dot(normal, l) > 0.0)
    {
      above += weights->GetTuple1(j);
      seen += l[2] > slope * std::abs(l[0]) ? weights->GetTuple1(j) : 0.0;
    }
  }
  return above > 0.0 ? seen / above : 0.0;
}

void TestSelfHits(vtkPolyData* bunny)
{
  std::set<vtkIdType> touched;
  const vtkSmartPointer<vtkPolyData> damaged = Damaged(bunny, touched);
  for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
  {
    const Result clean = Run(caster, bunny), hurt = Run(caster, damaged);
    if (!clean.Ok || !hurt.Ok)
    {
      Check(false, std::string(CasterNames[caster]) + ", damaged scan: runs");
      continue;
    }
    // Real darkening elsewhere is kept: the untouched points see what they saw.
    double shift = 0.0;
    int count = 0;
    for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); ++i)
    {
      if (!touched.count(i) && std::isfinite(clean.Fraction[i]))
      {
        shift += hurt.Fraction[i] - clean.Fraction[i];
        ++count;
      }
    }
    const int isolated = IsolatedClosed(hurt);
    std::cout << CasterNames[caster] << ", bunny with 50 folds, slivers and crumples: " << isolated
              << " isolated closed points (clean: " << IsolatedClosed(clean)
              << "), untouched points' mean change " << shift / count << "\n";
    Check(isolated <= 2, std::string(CasterNames[caster]) + ": at most 2 isolated closed points",
      isolated, 2);
    Check(
      std::abs(shift / count) < 0.005, "the rest of the scan sees what it saw", shift / count, 0.0);
  }

  // Crevices stay dark: the bottom of a V groove sees the lune between its walls, 2 x opening,
  // a fraction opening / pi of a hemisphere. Cosine-weighted: (1 - cos opening) / 2 around a
  // wall's normal (the sides split at the crease), sin(opening / 2) around the bisector (one
  // side, 150 degrees). The visibility matrix: what its own directions see of the lune.
  for (const double degrees : { 60.0, 90.0, 150.0 })
  {
    const double opening = vtkMath::RadiansFromDegrees(degrees);
    const vtkSmartPointer<vtkPolyData> groove = Groove(opening);
    for (const Caster caster : { PRECOMPUTE, VISIBILITY, REFERENCE })
    {
      const Result r = Run(caster, groove, 1024);
      double sum = 0.0, discrete = 0.0;
      int count = 0;
      for (vtkIdType i = 0; r.Ok && i < r.Output->GetNumberOfPoints(); ++i)
      {
        const double* p = r.Output->GetPoint(i);
        if (p[0] == 0.0 && p[2] == 0.0 && std::abs(p[1]) < 2.0)
        {
          sum += r.Fraction[i];
          discrete += caster == VISIBILITY ? GrooveFraction(r.Output, i, opening) : 0.0;
          ++count;
        }
      }
      const double got = sum / std::max(count, 1);
      // The visibility matrix is exact for its own directions: what they see of the lune.
      const double want = caster == VISIBILITY ? discrete / std::max(count, 1)
        : caster == PRECOMPUTE
        ? opening / Pi
        : (degrees < 120.0 ? 0.5 * (1.0 - std::cos(opening)) : std::sin(0.5 * opening));
      std::cout << CasterNames[caster] << ", groove of " << degrees << " degrees: its bottom ("
                << count << " points) sees " << got << " (" << want << ")\n";
      Check(count > 0 && std::abs(got - want) < 0.05 * want,
        std::string(CasterNames[caster]) + ": a crevice's bottom stays dark", got, want);
    }
  }
}

//------------------------------------------------------------------------------
void TestRefinement()
{
  // Coarse: a ground of two triangles and a box of twelve.
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-2, -2, 0);
  ground->SetPoint1(2, -2, 0);
  ground->SetPoint2(-2, 2, 0);
  const double bounds[6] = { -0.5, 0.5, -0.5, 0.5, 0.0, 1.0 };
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputData(Triangles(ground));
  scene->AddInputData(SharedBox(bounds));
  scene->Update();
  vtkNew<vtkPolyData> coarse;
  coarse->DeepCopy(scene->GetOutput());
  coarse->GetPointData()->Initialize();
  // A linear point field and a cell id, to follow through.
  vtkNew<vtkFloatArray> x;
  x->SetName("X");
  for (vtkIdType i = 0; i < coarse->GetNumberOfPoints(); ++i)
  {
    x->InsertNextValue(static_cast<float>(coarse->GetPoint(i)[0]));
  }
  coarse->GetPointData()->AddArray(x);
  vtkNew<vtkIdTypeArray> cellId;
  cellId->SetName("CellId");
  for (vtkIdType c = 0; c < coarse->GetNumberOfCells(); ++c)
  {
    cellId->InsertNextValue(c);
  }
  coarse->GetCellData()->AddArray(cellId);

  auto nearWall = [](const Result& r, double& darkest, double& far)
  {
    darkest = 1.0;
    far = 1.0;
    int near = 0;
    for (vtkIdType i = 0; i < r.Output->GetNumberOfPoints(); ++i)
    {
      const double* p = r.Output->GetPoint(i);
      const double out = std::max(std::abs(p[0]), std::abs(p[1]));
      if (p[2] == 0.0 && out > 0.5 && out < 0.65)
      {
        darkest = std::min(darkest, r.Fraction[i]);
        ++near;
      }
      if (p[2] == 0.0 && out > 1.8)
      {
        far = std::min(far, r.Fraction[i]);
      }
    }
    return near;
  };
  double darkest, far;
  const Result before = Run(PRECOMPUTE, coarse, 256);
  const int nearBefore = nearWall(before, darkest, far);
  const Result after = Run(PRECOMPUTE, coarse, 256, 60.0, 0.1);
  const int nearAfter = nearWall(after, darkest, far);
  std::cout << "refinement: " << coarse->GetNumberOfPolys() << " triangles refined to "
            << after.Output->GetNumberOfPolys() << "; ground points by the walls " << nearBefore
            << " before, " << nearAfter << " after; the darkest sees " << darkest
            << ", the far ground at least " << far << "\n";
  Check(nearBefore == 0 && nearAfter > 50, "refinement gives the ground points by the walls");
  Check(darkest < 0.8 && far > 0.9, "a contact shadow at the walls' feet, open ground away",
    darkest, 0.8);
  // Point data interpolated (a linear field exactly), cell data copied, areas kept.
  vtkDataArray* refinedX = after.Output->GetPointData()->GetArray("X");
  double worst = 0.0;
  for (vtkIdType i = 0; refinedX && i < after.Output->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst, std::abs(refinedX->GetTuple1(i) - after.Output->GetPoint(i)[0]));
  }
  Check(refinedX && worst < 1e-6, "point data interpolated along the refinement", worst, 0.0);
  vtkDataArray* refinedId = after.Output->GetCellData()->GetArray("CellId");
  std::vector<double> area(coarse->GetNumberOfCells(), 0.0), areaBefore(area.size(), 0.0);
  for (vtkIdType c = 0; c < coarse->GetNumberOfCells(); ++c)
  {
    areaBefore[c] = vtkTriangle::SafeDownCast(coarse->GetCell(c))->ComputeArea();
  }
  for (vtkIdType c = 0; refinedId && c < after.Output->GetNumberOfCells(); ++c)
  {
    area[static_cast<size_t>(refinedId->GetTuple1(c))] +=
      vtkTriangle::SafeDownCast(after.Output->GetCell(c))->ComputeArea();
  }
  double worstArea = 0.0;
  for (size_t c = 0; c < area.size(); ++c)
  {
    worstArea = std::max(worstArea, std::abs(area[c] - areaBefore[c]) / areaBefore[c]);
  }
  Check(refinedId && worstArea < 1e-9,
    "each cell's data on the triangles it becomes, its area kept", worstArea, 0.0);

  // Texture seams stay: a box whose faces have points of their own keeps them apart.
  vtkNew<vtkCubeSource> cube;
  const vtkSmartPointer<vtkPolyData> seams = Triangles(cube);
  vtkNew<vtkAperturePrecompute> refine;
  refine->SetInputData(seams);
  refine->SetNumberOfRays(16);
  refine->SetMaximumEdgeLength(0.2);
  refine->Update();
  vtkPolyData* out = refine->GetPolyDataOutput();
  std::vector<std::set<int>> faces(out->GetNumberOfPoints());
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType cell = 0;
  for (out->GetPolys()->InitTraversal(); out->GetPolys()->GetNextCell(npts, ids); ++cell)
  {
    double p[3][3], nrm[3];
    for (int k = 0; k < 3; ++k)
    {
      out->GetPoint(ids[k], p[k]);
    }
    vtkTriangle::ComputeNormal(p[0], p[1], p[2], nrm);
    const int face = static_cast<int>(std::round(nrm[0] + 2 * nrm[1] + 4 * nrm[2]));
    for (int k = 0; k < 3; ++k)
    {
      faces[ids[k]].insert(face);
    }
  }
  size_t shared = 0;
  for (const auto& f : faces)
  {
    shared += f.size() > 1 ? 1 : 0;
  }
  std::cout << "a box with points per face refined to " << out->GetNumberOfPolys()
            << " triangles: " << shared << " points shared between faces\n";
  Check(shared == 0 && out->GetPointData()->GetTCoords(),
    "refinement keeps the faces' own points and texture coordinates apart");
}
}

int TestRealWorldMeshes(int argc, char* argv[])
{
  char* name = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/stanford-bunny.obj");
  const std::string file = name;
  delete[] name;
  char* tempDir =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string temporary = tempDir;
  delete[] tempDir;
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkNew<vtkPolyData> bunny;
  bunny->ShallowCopy(reader->GetOutput());
  if (bunny->GetNumberOfPoints() == 0)
  {
    std::cerr << "FAIL cannot read " << file << " (pass -D <Testing folder>)\n";
    return EXIT_FAILURE;
  }
  TestBadPointIds();
  TestSeams(bunny, temporary);
  TestCreases(bunny);
  TestWinding(bunny);
  TestContacts();
  TestSelfHits(bunny);
  TestRefinement();
  return vtkApertureTest::Result();
}
