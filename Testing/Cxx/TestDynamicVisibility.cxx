/*=========================================================================

  Program:   ApertureLighting
  Module:    TestDynamicVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Dynamic scenes (Sattler et al. 2004, §4.2 and §6):
// - a deforming mesh: the first update uploads points and triangles, a deformation only the
//   points, and gives what a new filter gives on the same geometry;
// - rigid rotation: the lighting of the unrotated visibility with ObjectRotation R matches a
//   full recomputation on the rotated mesh (and not the unrotated lighting); a turn about the
//   environment's up axis is the same as the opposite Azimuth;
// - vtkDynamicVisibilityDriver: coarse level while moving, one level more per idle frame up to
//   MaximumLevel, reusing the directions already computed; a pipeline change is a moving frame
//   and recomputes; the adaptive level follows TargetUpdateTime; the interactor style's events
//   mark interaction; the prop's rotation reaches the lighting.

#include "vtkApertureTestHarness.h"
#include "vtkDynamicVisibilityDriver.h"
#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkOcclusionQueryVisibility.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkQuadricDecimation.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSimpleElevationFilter.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkWarpScalar.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using vtkApertureTest::Check;

// A latitude-longitude environment: a sky brighter toward the zenith (+z) and a bright lobe low
// in the north-east, so that turning it matters.
vtkSmartPointer<vtkImageData> Environment()
{
  const int w = 128, h = 64;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(w * h);
  const double lobe[3] = { 0.6, 0.6, 0.53 };
  for (int row = 0; row < h; ++row)
  {
    for (int column = 0; column < w; ++column)
    {
      // Row 0 is the top; any consistent mapping will do for the comparisons made here.
      const double theta = vtkMath::Pi() * (row + 0.5) / h;
      const double phi = 2.0 * vtkMath::Pi() * (column + 0.5) / w;
      const double d[3] = { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
        std::cos(theta) };
      const double glow = std::pow(std::max(0.0, vtkMath::Dot(d, lobe)), 8.0);
      const double sky = 0.2 + 0.8 * std::max(0.0, d[2]);
      const double rgb[3] = { sky + 4.0 * glow, sky + 3.0 * glow, 1.2 * sky + glow };
      radiance->SetTuple(row * w + column, rgb);
    }
  }
  image->GetPointData()->SetScalars(radiance);
  return image;
}

// Mean relative difference of two RGB arrays (over the mean of the first).
double MeanDifference(vtkDataArray* a, vtkDataArray* b)
{
  double difference = 0.0, total = 0.0;
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    difference += std::abs(a->GetComponent(v / 3, v % 3) - b->GetComponent(v / 3, v % 3));
    total += std::abs(a->GetComponent(v / 3, v % 3));
  }
  return total > 0.0 ? difference / total : 1.0;
}

// The rotation part of a transform, row-major, as SetObjectRotation() takes it.
void RotationOf(vtkTransform* transform, double rotation[9])
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      rotation[3 * i + j] = transform->GetMatrix()->GetElement(i, j);
    }
  }
}

vtkDataArray* LightingOf(vtkEnvironmentVisibilityLighting* lighting)
{
  return lighting->GetOutput()->GetPointData()->GetArray("EnvironmentLighting");
}
}

int TestDynamicVisibility(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(300, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();

  // A deforming mesh: a sphere warped along its normals by its height.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkSimpleElevationFilter> height;
  height->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(height->GetOutputPort());
  warp->SetScaleFactor(0.2);
  vtkNew<vtkOcclusionQueryVisibility> visibility;
  visibility->SetInputConnection(warp->GetOutputPort());
  visibility->SetRenderWindow(window);
  visibility->Update();
  const vtkIdType n = visibility->GetOutput()->GetNumberOfPoints();
  const vtkIdType pointBytes = 3 * n * static_cast<vtkIdType>(sizeof(float));
  const vtkIdType triangleBytes =
    3 * visibility->GetOutput()->GetNumberOfPolys() * static_cast<vtkIdType>(sizeof(std::uint32_t));
  std::cout << "first update uploads " << visibility->GetUploadedBytes() << " bytes\n";
  Check(visibility->GetUploadedBytes() == pointBytes + triangleBytes,
    "the first update uploads points and triangles");
  warp->SetScaleFactor(0.5);
  visibility->Update();
  std::cout << "a deformation uploads " << visibility->GetUploadedBytes() << " bytes\n";
  Check(visibility->GetUploadedBytes() == pointBytes, "a deformation uploads only the points");
  Check(visibility->GetNumberOfComputedPoints() == n, "a deformation recomputes every point");
  {
    vtkNew<vtkOcclusionQueryVisibility> fresh;
    fresh->SetInputConnection(warp->GetOutputPort());
    fresh->SetRenderWindow(window);
    fresh->Update();
    auto* a =
      vtkFloatArray::SafeDownCast(visibility->GetOutput()->GetPointData()->GetArray("Visibility"));
    auto* b =
      vtkFloatArray::SafeDownCast(fresh->GetOutput()->GetPointData()->GetArray("Visibility"));
    vtkIdType differ = 0;
    for (vtkIdType v = 0; a && b && v < a->GetNumberOfValues(); ++v)
    {
      differ += a->GetValue(v) != b->GetValue(v);
    }
    Check(a && b && differ == 0, "the deformed mesh's visibility equals a new filter's");
  }

  // Two objects moving relative to each other: a plate over the ball, moved; the ball's
  // visibility follows it.
  vtkNew<vtkSphereSource> plateSource;
  plateSource->SetThetaResolution(16);
  plateSource->SetPhiResolution(8);
  vtkNew<vtkTransform> plateMotion;
  plateMotion->Translate(0.0, 0.0, 1.5);
  plateMotion->Scale(1.5, 1.5, 0.1);
  vtkNew<vtkTransformPolyDataFilter> plate;
  plate->SetInputConnection(plateSource->GetOutputPort());
  plate->SetTransform(plateMotion);
  visibility->AddOccluderConnection(plate->GetOutputPort());
  visibility->Update();
  auto topVisibility = [&]()
  {
    // The visible directions of the ball's top point, summed.
    vtkPolyData* out = visibility->GetOutput();
    vtkDataArray* values = out->GetPointData()->GetArray("Visibility");
    if (!values)
    {
      return 0.0; // the filter failed and said why
    }
    vtkIdType top = 0;
    for (vtkIdType i = 1; i < out->GetNumberOfPoints(); ++i)
    {
      top = out->GetPoint(i)[2] > out->GetPoint(top)[2] ? i : top;
    }
    double sum = 0.0;
    for (int j = 0; j < values->GetNumberOfComponents(); ++j)
    {
      sum += values->GetComponent(top, j);
    }
    return sum;
  };
  const double covered = topVisibility();
  plateMotion->Translate(3.0, 0.0, 0.0);
  visibility->Update();
  const double uncovered = topVisibility();
  std::cout << "the ball's top under the plate sees " << covered << ", with the plate moved away "
            << uncovered << "\n";
  Check(visibility->GetNumberOfComputedPoints() == n && uncovered > covered + 1.0,
    "a moving occluder recomputes the receiver's visibility");
  visibility->RemoveAllInputConnections(1);

  // Rigid rotation on the bunny (decimated to keep the test short).
  char* name = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/stanford-bunny.obj");
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(name);
  delete[] name;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputConnection(triangles->GetOutputPort());
  decimate->SetTargetReduction(0.8);
  decimate->Update();
  vtkSmartPointer<vtkImageData> environment = Environment();
  vtkNew<vtkOcclusionQueryVisibility> still;
  still->SetInputConnection(decimate->GetOutputPort());
  still->SetRenderWindow(window);
  still->SetLevel(3);
  vtkNew<vtkEnvironmentVisibilityLighting> lit;
  lit->SetInputConnection(still->GetOutputPort());
  lit->SetEnvironmentData(environment);
  lit->SetBlurAngle(0.15);
  lit->Update();
  vtkNew<vtkFloatArray> unturned;
  unturned->DeepCopy(LightingOf(lit));

  vtkNew<vtkTransform> turn;
  turn->RotateX(35.0);
  turn->RotateZ(70.0);
  vtkNew<vtkTransformPolyDataFilter> turned;
  turned->SetInputConnection(decimate->GetOutputPort());
  turned->SetTransform(turn);
  vtkNew<vtkOcclusionQueryVisibility> recomputed;
  recomputed->SetInputConnection(turned->GetOutputPort());
  recomputed->SetRenderWindow(window);
  recomputed->SetLevel(3);
  vtkNew<vtkEnvironmentVisibilityLighting> truth;
  truth->SetInputConnection(recomputed->GetOutputPort());
  truth->SetEnvironmentData(environment);
  truth->SetBlurAngle(0.15);
  truth->Update();
  double rotation[9];
  RotationOf(turn, rotation);
  lit->SetObjectRotation(rotation);
  lit->Update();
  const double rotated = MeanDifference(LightingOf(truth), LightingOf(lit));
  const double ignored = MeanDifference(LightingOf(truth), unturned);
  std::cout << "rigid rotation: turning the directions is " << 100.0 * rotated
            << "% from recomputing, ignoring the turn " << 100.0 * ignored << "%\n";
  Check(rotated < 0.03, "turning the directions matches recomputing the turned mesh");
  Check(ignored > 3.0 * rotated, "the comparison sees the turn");

  // A turn about the environment's up axis (z) is the opposite azimuth.
  vtkNew<vtkTransform> spin;
  spin->RotateZ(40.0);
  RotationOf(spin, rotation);
  lit->SetObjectRotation(rotation);
  lit->Update();
  vtkNew<vtkFloatArray> spun;
  spun->DeepCopy(LightingOf(lit));
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  lit->SetObjectRotation(identity);
  lit->SetAzimuth(40.0);
  lit->Update();
  const double azimuth = MeanDifference(spun, LightingOf(lit));
  std::cout << "object turned 40 degrees vs environment at azimuth 40: " << azimuth << "\n";
  Check(azimuth < 1e-5, "an object turn about up equals the environment's azimuth");
  lit->SetAzimuth(0.0);

  // The driver on the warped sphere.
  vtkNew<vtkOcclusionQueryVisibility> dynamic;
  dynamic->SetInputConnection(warp->GetOutputPort());
  dynamic->SetRenderWindow(window);
  vtkNew<vtkDynamicVisibilityDriver> driver;
  driver->SetVisibility(dynamic);
  driver->SetMinimumLevel(0);
  driver->SetMaximumLevel(2);
  driver->SetTargetUpdateTime(0.0);
  driver->Attach(renderer);
  for (int frame = 0; frame < 4 && (frame == 0 || driver->GetMoving()); ++frame)
  {
    window->Render();
  }
  Check(!driver->GetMoving() && driver->GetLevel() == 1, "a still scene refines");
  Check(dynamic->GetNumberOfDepthPasses() == (18 - 6) / 2,
    "raising the level renders only the new directions (" +
      std::to_string(dynamic->GetNumberOfDepthPasses()) + " passes)");
  window->Render();
  Check(driver->GetLevel() == 2 && dynamic->GetNumberOfDepthPasses() == (66 - 18) / 2,
    "the next idle frame refines again");
  const vtkMTimeType computedAt = dynamic->GetOutput()->GetMTime();
  window->Render();
  Check(driver->GetLevel() == 2 && dynamic->GetOutput()->GetMTime() == computedAt,
    "refinement stops at MaximumLevel");
  Check(!driver->NeedsRefinement(), "nothing left to refine");

  // Interaction over a mesh whose visibility is all there computes nothing and keeps the level.
  const vtkMTimeType before = dynamic->GetOutput()->GetMTime();
  driver->StartInteraction();
  window->Render();
  Check(
    driver->GetMoving() && driver->GetLevel() == 2 && dynamic->GetOutput()->GetMTime() == before,
    "interaction over computed visibility keeps the level and computes nothing");
  driver->EndInteraction();

  // A lower level is a prefix of what is computed: nothing is rendered for it.
  dynamic->SetLevel(0);
  dynamic->Update();
  Check(dynamic->GetNumberOfDepthPasses() == 0 && dynamic->GetNumberOfComputedPoints() == 0 &&
      dynamic->GetOutput()->GetPointData()->GetArray("Visibility")->GetNumberOfComponents() == 6,
    "a coarser level reuses the computed directions");
  dynamic->SetLevel(2);

  warp->SetScaleFactor(0.3);
  window->Render();
  Check(driver->GetMoving() && driver->GetLevel() == 0 && dynamic->GetNumberOfComputedPoints() == n,
    "a pipeline change is a moving frame and recomputes at the moving level");
  window->Render();
  Check(!driver->GetMoving() && driver->GetLevel() == 1 &&
      dynamic->GetNumberOfDepthPasses() == (18 - 6) / 2,
    "then idle frames refine it, rendering only the new directions");

  // Adaptive level: a generous budget climbs to the maximum, an impossible one falls to the
  // minimum.
  driver->SetTargetUpdateTime(100.0);
  driver->StartInteraction();
  for (int frame = 0; frame < 4; ++frame)
  {
    warp->SetScaleFactor(0.3 + 0.05 * frame);
    window->Render();
  }
  Check(driver->GetLevel() == 2, "a generous budget climbs to MaximumLevel");
  driver->SetTargetUpdateTime(1e-9);
  for (int frame = 0; frame < 4; ++frame)
  {
    warp->SetScaleFactor(0.5 + 0.05 * frame);
    window->Render();
  }
  Check(driver->GetLevel() == 0, "an impossible budget falls to MinimumLevel");
  driver->EndInteraction();

  // The interactor style's events, and the prop's rotation handed to the lighting.
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(window);
  vtkNew<vtkEnvironmentVisibilityLighting> lighting;
  lighting->SetInputConnection(dynamic->GetOutputPort());
  lighting->SetEnvironmentData(environment);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(lighting->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  driver->SetLighting(lighting);
  driver->SetProp(actor);
  driver->Attach(renderer, interactor);
  style->InvokeEvent(vtkCommand::StartInteractionEvent);
  Check(driver->GetInteracting(), "the style's StartInteractionEvent starts interaction");
  style->InvokeEvent(vtkCommand::EndInteractionEvent);
  Check(!driver->GetInteracting(), "the style's EndInteractionEvent ends it");
  actor->RotateZ(30.0);
  window->Render();
  double* r = lighting->GetObjectRotation();
  Check(std::abs(r[0] - std::cos(vtkMath::RadiansFromDegrees(30.0))) < 1e-9 &&
      std::abs(r[3] - std::sin(vtkMath::RadiansFromDegrees(30.0))) < 1e-9,
    "the prop's rotation reaches the lighting");
  Check(driver->GetMoving(), "a turned prop is a moving frame");
  driver->Detach();

  // Misuse is an error, not a crash.
  vtkNew<vtkDynamicVisibilityDriver> idle;
  vtkNew<vtkTest::ErrorObserver> errors;
  idle->AddObserver(vtkCommand::ErrorEvent, errors);
  idle->Update();
  Check(errors->GetError() && errors->GetErrorMessage().find("SetVisibility") != std::string::npos,
    "a driver without a visibility filter says so");
  errors->Clear();
  idle->Attach(nullptr);
  Check(errors->GetError() && errors->GetErrorMessage().find("renderer") != std::string::npos,
    "attaching to no renderer says so");
  return vtkApertureTest::Result();
}
