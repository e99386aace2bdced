/*=========================================================================

  Program:   ApertureLighting
  Module:    TestLightSphereVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkLightSphereVisibility, the visibility matrix by rays in the core:
// - a convex sphere sees the directions above each point's tangent plane, with Visibility =
//   n . l there, and none below (directions within 17 degrees of the tangent plane may graze
//   the neighbouring facets of the polygonal sphere: either answer is right there);
// - a sphere over a ground plane given on port 1: a direction is seen only where a ray along it
//   misses the plane, which a line-plane test decides independently;
// - vtkOcclusionQueryVisibility's RAY_CAST backend gives the same arrays, value for value (it
//   delegates to this filter), on the sphere and with the occluder;
// - raising the level casts only the new directions and gives the fresh level's matrix;
// - an abort gives an empty output; an empty input an error.

#include "vtkApertureTestHarness.h"
#include "vtkLightSphereVisibility.h"
#include "vtkOcclusionQueryVisibility.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <iostream>
#include <sstream>

namespace
{
using vtkApertureTest::Check;

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  sphere->SetCenter(0.0, 0.0, 0.6);
  sphere->SetRadius(0.5);
  sphere->Update();
  return sphere->GetOutput();
}

// A ground plane at z = 0 facing up, wide enough to hide all of the sphere's lower sky but the
// grazing directions.
vtkSmartPointer<vtkPolyData> Ground()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-50.0, -50.0, 0.0);
  plane->SetPoint1(50.0, -50.0, 0.0);
  plane->SetPoint2(-50.0, 50.0, 0.0);
  plane->SetResolution(4, 4);
  plane->Update();
  return plane->GetOutput();
}

// Grazing directions: either answer is right.
constexpr double Either = -1.0;
constexpr double Grazing = 0.3;

// Counts the entries where `matrix` differs from `want(point, normal, direction)` (Either:
// none), and the entries checked in `checked`.
template <typename Want>
int Mismatches(vtkPolyData* output, Want want, int& checked)
{
  checked = 0;
  vtkDataArray* matrix = output->GetPointData()->GetArray("Visibility");
  vtkDataArray* normals = output->GetPointData()->GetArray("Normals");
  vtkDataArray* directions = output->GetFieldData()->GetArray("LightDirections");
  if (!matrix || !normals || !directions)
  {
    return -1;
  }
  int wrong = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3], l[3];
    output->GetPoint(i, p);
    normals->GetTuple(i, n);
    for (int j = 0; j < matrix->GetNumberOfComponents(); ++j)
    {
      directions->GetTuple(j, l);
      const double expected = want(p, n, l);
      checked += expected != Either ? 1 : 0;
      wrong += expected != Either && std::abs(matrix->GetComponent(i, j) - expected) > 1e-5;
    }
  }
  return wrong;
}

double Cosine(const double n[3], const double l[3])
{
  return n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
}

// Both filters on the same input; true when every array value agrees.
bool SameAsOcclusionQueryRays(vtkPolyData* input, vtkPolyData* occluder, vtkPolyData* output)
{
  vtkNew<vtkOcclusionQueryVisibility> rays;
  rays->SetBackendToRayCast();
  rays->SetInputData(input);
  if (occluder)
  {
    rays->AddInputData(1, occluder);
  }
  rays->ComputeVisibilityBitsOn();
  rays->SetLevel(2);
  rays->Update();
  bool same = rays->GetOutput()->GetNumberOfPoints() == output->GetNumberOfPoints();
  for (const char* name : { "Visibility", "VisibilityBits", "Normals" })
  {
    vtkDataArray* a = rays->GetOutput()->GetPointData()->GetArray(name);
    vtkDataArray* b = output->GetPointData()->GetArray(name);
    same = same && a && b && a->GetNumberOfValues() == b->GetNumberOfValues();
    for (vtkIdType v = 0; same && v < a->GetNumberOfValues(); ++v)
    {
      same = a->GetVariantValue(v) == b->GetVariantValue(v);
    }
  }
  return same;
}

vtkSmartPointer<vtkPolyData> Run(vtkPolyData* input, vtkPolyData* occluder, int level)
{
  vtkNew<vtkLightSphereVisibility> filter;
  filter->SetInputData(input);
  if (occluder)
  {
    filter->AddInputData(1, occluder);
  }
  filter->ComputeVisibilityBitsOn();
  filter->SetLevel(level);
  filter->Update();
  return filter->GetOutput();
}

void Unoccluded()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkSmartPointer<vtkPolyData> output = Run(sphere, nullptr, 2);
  int checked = 0;
  const int wrong = Mismatches(
    output,
    [](const double*, const double* n, const double* l)
    {
      const double c = Cosine(n, l);
      return c > Grazing ? c : (c > 0.0 ? Either : 0.0);
    },
    checked);
  Check(wrong == 0 && checked > 30 * output->GetNumberOfPoints(),
    "a convex sphere sees what is above each tangent plane, with M = n . l", wrong, 0);
  Check(SameAsOcclusionQueryRays(sphere, nullptr, output),
    "vtkOcclusionQueryVisibility's RayCast gives the same arrays");
}

void Occluded()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkSmartPointer<vtkPolyData> ground = Ground();
  vtkSmartPointer<vtkPolyData> output = Run(sphere, ground, 2);
  // A ray from p along l meets the plane z = 0 within its 100 x 100 square or misses it.
  int checked = 0;
  const int wrong = Mismatches(
    output,
    [](const double* p, const double* n, const double* l)
    {
      const double c = Cosine(n, l);
      if (c <= 0.0)
      {
        return 0.0;
      }
      const double t = -p[2] / l[2];
      const bool hits =
        t > 0.0 && std::abs(p[0] + t * l[0]) < 49.0 && std::abs(p[1] + t * l[1]) < 49.0;
      return c <= Grazing || std::abs(l[2]) < 0.05 ? Either : (hits ? 0.0 : c);
    },
    checked);
  Check(wrong == 0 && checked > 20 * output->GetNumberOfPoints(),
    "the ground on port 1 hides the directions whose rays meet it", wrong, 0);
  Check(SameAsOcclusionQueryRays(sphere, ground, output),
    "vtkOcclusionQueryVisibility's RayCast gives the same arrays with an occluder");
}

void LevelsAndAbort()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkLightSphereVisibility> filter;
  filter->SetInputData(sphere);
  filter->SetLevel(1);
  filter->Update();
  filter->SetLevel(2);
  filter->Update();
  vtkSmartPointer<vtkPolyData> fresh = Run(sphere, nullptr, 2);
  vtkDataArray* raised = filter->GetOutput()->GetPointData()->GetArray("Visibility");
  vtkDataArray* direct = fresh->GetPointData()->GetArray("Visibility");
  bool same = raised && direct && raised->GetNumberOfValues() == direct->GetNumberOfValues();
  for (vtkIdType v = 0; same && v < raised->GetNumberOfValues(); ++v)
  {
    same = raised->GetVariantValue(v) == direct->GetVariantValue(v);
  }
  Check(same && raised->GetNumberOfComponents() == 66,
    "level 1 raised to 2 gives the matrix of level 2 computed at once");
  filter->Modified();
  filter->Update();
  Check(filter->GetNumberOfComputedPoints() == 0 &&
      filter->GetOutput()->GetPointData()->GetArray("Visibility"),
    "an update with nothing new casts nothing and keeps the matrix");

  vtkNew<vtkLightSphereVisibility> aborted;
  aborted->SetInputData(sphere);
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
    { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
  aborted->AddObserver(vtkCommand::ProgressEvent, abort);
  aborted->Update();
  Check(aborted->GetOutput()->GetNumberOfPoints() == 0, "an abort gives an empty output");
}

void BadInput()
{
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkLightSphereVisibility> filter;
  filter->SetInputData(empty);
  vtkNew<vtkTest::ErrorObserver> errors, executiveErrors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  Check(filter->GetExecutive()->Update() == 0 && errors->GetError() &&
      errors->GetErrorMessage().find("empty") != std::string::npos,
    "an empty input is an error that says so");
  std::ostringstream printed;
  filter->Print(printed);
  Check(printed.str().find("RayOffset") != std::string::npos, "PrintSelf prints the settings");
}
}

int TestLightSphereVisibility(int, char*[])
{
  Unoccluded();
  Occluded();
  LevelsAndAbort();
  BadInput();
  return vtkApertureTest::Result();
}
