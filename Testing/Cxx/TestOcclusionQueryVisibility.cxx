/*=========================================================================

  Program:   ApertureLighting
  Module:    TestOcclusionQueryVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkOcclusionQueryVisibility, every backend:
// - analytic scenes: a plane sees exactly the directions above it; a point on the crease of a
//   90 degree corner sees a quarter of the sphere (pi sr, summed with the lightsphere's weights);
//   a point of a convex sphere sees its hemisphere;
// - the bunny at k = 66: OcclusionQuery and DepthCompare agree on at least 99% of the entries
//   with n.l > 0.1, and each agrees with RayCast on at least 97%;
// - an occluder on port 1 darkens what is under it, and gets no output;
// - raising the level renders only the new directions; the output keeps the input's arrays,
//   adds Normals where there were none, the bits match the values, the input is untouched;
// - sharing a render window leaves its GL state as it was: the same picture before and after;
// - progress events, abort, and bad input.

#include "vtkApertureTestHarness.h"
#include "vtkOcclusionQueryVisibility.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkBitArray.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;

const int Backends[] = { vtkOcclusionQueryVisibility::OCCLUSION_QUERY,
  vtkOcclusionQueryVisibility::DEPTH_COMPARE, vtkOcclusionQueryVisibility::RAY_CAST };
const char* const Names[] = { "OcclusionQuery", "DepthCompare", "RayCast" };

vtkSmartPointer<vtkPolyData> Run(vtkPolyData* input, int backend, int level,
  vtkPolyData* occluder = nullptr, vtkOcclusionQueryVisibility* reuse = nullptr)
{
  vtkSmartPointer<vtkOcclusionQueryVisibility> filter = reuse;
  if (!filter)
  {
    filter = vtkSmartPointer<vtkOcclusionQueryVisibility>::New();
  }
  filter->SetInputData(input);
  if (occluder)
  {
    filter->SetInputData(1, occluder);
  }
  filter->SetBackend(backend);
  filter->SetLevel(level);
  filter->ComputeVisibilityBitsOn();
  if (!filter->GetExecutive()->Update())
  {
    // Everything below reads the matrix: stop here (no OpenGL context, e.g. outside xvfb-run).
    std::cerr << "FAIL the filter failed (see its error above)\n";
    std::exit(EXIT_FAILURE);
  }
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}

// Whether point i sees direction j.
bool Sees(vtkPolyData* output, vtkIdType i, int j)
{
  auto* bits =
    vtkBitArray::SafeDownCast(output->GetPointData()->GetAbstractArray("VisibilityBits"));
  return bits->GetValue(i * bits->GetNumberOfComponents() + j) != 0;
}

// Solid angle seen by point i: the weights of the directions it sees.
double SeenSolidAngle(vtkPolyData* output, vtkIdType i)
{
  vtkDataArray* weights = output->GetFieldData()->GetArray("LightWeights");
  double sum = 0.0;
  for (vtkIdType j = 0; j < weights->GetNumberOfTuples(); ++j)
  {
    sum += Sees(output, i, static_cast<int>(j)) ? weights->GetTuple1(j) : 0.0;
  }
  return sum;
}

double Dot(vtkPolyData* output, vtkIdType i, int j)
{
  double n[3], l[3];
  output->GetPointData()->GetNormals()->GetTuple(i, n);
  output->GetFieldData()->GetArray("LightDirections")->GetTuple(j, l);
  return vtkMath::Dot(n, l);
}

// Geometry in a generic orientation, so that no lightsphere direction lies exactly in a plane's
// horizon (where "above the tangent plane" would be decided by rounding).
vtkSmartPointer<vtkPolyData> Rotated(vtkPolyData* input)
{
  vtkNew<vtkTransform> rotation;
  rotation->RotateWXYZ(37.0, 1.0, 2.0, 3.0);
  vtkNew<vtkTransformPolyDataFilter> rotate;
  rotate->SetInputData(input);
  rotate->SetTransform(rotation);
  rotate->Update();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->DeepCopy(rotate->GetOutput());
  return output;
}

// A 90 degree corner, rotated: a floor (z = 0, x in [0, 1]) and a wall (x = 0, z in [0, 1]),
// y in [-1, 1]. Its crease point (0, 0, 0) sees the quarter space x, z > 0, pi sr; the floor
// point (0.2, 0, 0) sees its hemisphere less the wall, a rectangle whose solid angle is known.
vtkSmartPointer<vtkPolyData> Corner(vtkIdType& creasePoint, vtkIdType& floorPoint)
{
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(0, -1, 0);
  floor->SetPoint1(1, -1, 0);
  floor->SetPoint2(0, 1, 0);
  floor->SetResolution(10, 20);
  vtkNew<vtkPlaneSource> wall;
  wall->SetOrigin(0, -1, 0);
  wall->SetPoint1(0, 1, 0);
  wall->SetPoint2(0, -1, 1);
  wall->SetResolution(20, 10);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(floor->GetOutputPort());
  both->AddInputConnection(wall->GetOutputPort());
  // One surface: the crease's points are shared, and their normals bisect the corner.
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputConnection(both->GetOutputPort());
  merge->Update();
  auto corner = vtkSmartPointer<vtkPolyData>::New();
  corner->DeepCopy(merge->GetOutput());
  corner->GetPointData()->Initialize(); // no normals: the filter computes them
  for (vtkIdType i = 0; i < corner->GetNumberOfPoints(); ++i)
  {
    double p[3];
    corner->GetPoint(i, p);
    creasePoint = vtkMath::Norm(p) < 1e-6 ? i : creasePoint;
    const double onFloor[3] = { p[0] - 0.2, p[1], p[2] };
    floorPoint = vtkMath::Norm(onFloor) < 1e-6 ? i : floorPoint;
  }
  return Rotated(corner);
}

std::vector<unsigned char> Picture(vtkRenderWindow* window)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto* pixels =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  return std::vector<unsigned char>(
    pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
}
}

int TestOcclusionQueryVisibility(int argc, char* argv[])
{
  // A plane sees exactly the directions above it.
  vtkNew<vtkPlaneSource> planeSource;
  planeSource->SetResolution(8, 8);
  planeSource->Update();
  auto plane = Rotated(planeSource->GetOutput());
  for (int b = 0; b < 3; ++b)
  {
    auto out = Run(plane, Backends[b], 2);
    int wrong = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      for (int j = 0; j < 66; ++j)
      {
        wrong += Sees(out, i, j) != (Dot(out, i, j) > 1e-9);
      }
    }
    std::cout << Names[b] << ": plane, " << wrong << " wrong entries of "
              << 66 * out->GetNumberOfPoints() << "\n";
    Check(wrong == 0, std::string(Names[b]) + ": a plane sees the directions above it");
  }

  // The corner: the crease sees pi sr, the floor point its hemisphere less the wall; the points
  // of a convex sphere see their hemisphere. Sums of the lightsphere's weights at levels 4 and 3.
  vtkIdType crease = -1, floorPoint = -1;
  auto corner = Corner(crease, floorPoint);
  // A rectangle of half-width a and height b, seen from a distance d in front of the middle of
  // its base: 2 atan(a b / (d sqrt(d^2 + a^2 + b^2))).
  const double d = 0.2, wall = 2.0 * std::atan(1.0 / (d * std::sqrt(d * d + 2.0)));
  const double floorSees = 2.0 * vtkMath::Pi() - wall;
  vtkNew<vtkSphereSource> ballSource;
  ballSource->SetThetaResolution(48);
  ballSource->SetPhiResolution(24);
  ballSource->Update();
  auto ball = Rotated(ballSource->GetOutput());
  for (int b = 0; b < 3; ++b)
  {
    auto out = Run(corner, Backends[b], 4);
    const double seenCrease = SeenSolidAngle(out, crease);
    const double seenFloor = SeenSolidAngle(out, floorPoint);
    auto sphere = Run(ball, Backends[b], 3);
    double worstSphere = 0.0;
    for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); i += 7)
    {
      worstSphere = std::max(worstSphere, std::abs(SeenSolidAngle(sphere, i) - 2 * vtkMath::Pi()));
    }
    std::cout << Names[b] << ": corner crease sees " << seenCrease << " sr (pi = " << vtkMath::Pi()
              << "), floor point " << seenFloor << " sr (" << floorSees
              << "); sphere points see 2 pi within " << worstSphere << " sr\n";
    // The OpenGL backends' polygon offset lets a point see through the surfaces that meet at
    // it, so on the crease itself they see the whole hemisphere: only rays are held to pi.
    Check(b != 2 || std::abs(seenCrease - vtkMath::Pi()) < 0.1,
      std::string(Names[b]) + ": the crease sees pi");
    Check(std::abs(seenFloor - floorSees) < 0.15,
      std::string(Names[b]) + ": the floor point sees its hemisphere less the wall");
    Check(worstSphere < 0.3, std::string(Names[b]) + ": a convex sphere sees its hemisphere");
  }

  // The bunny at k = 66: agreement between the backends where n.l > 0.1.
  char* bunnyName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/stanford-bunny.obj");
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(bunnyName);
  delete[] bunnyName;
  reader->Update();
  vtkPolyData* bunny = reader->GetOutput();
  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (int b = 0; b < 3; ++b)
  {
    results.push_back(Run(bunny, Backends[b], 2));
  }
  auto agreement = [&](int a, int c)
  {
    vtkIdType same = 0, total = 0;
    for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); ++i)
    {
      for (int j = 0; j < 66; ++j)
      {
        if (Dot(results[a], i, j) > 0.1)
        {
          ++total;
          same += Sees(results[a], i, j) == Sees(results[c], i, j);
        }
      }
    }
    return static_cast<double>(same) / total;
  };
  const double queryDepth = agreement(0, 1), queryRay = agreement(0, 2), depthRay = agreement(1, 2);
  std::cout << "bunny, k = 66, entries with n.l > 0.1: OcclusionQuery = DepthCompare on "
            << 100 * queryDepth << "%, OcclusionQuery = RayCast on " << 100 * queryRay
            << "%, DepthCompare = RayCast on " << 100 * depthRay << "%\n";
  Check(queryDepth >= 0.99, "OcclusionQuery and DepthCompare agree on 99%");
  Check(queryRay >= 0.97 && depthRay >= 0.97, "each OpenGL backend agrees with RayCast on 97%");

  // An occluder on port 1: a plate above the plane hides the zenith from the plane's middle.
  vtkNew<vtkPlaneSource> plateSource;
  plateSource->SetOrigin(-0.3, -0.3, 0.2);
  plateSource->SetPoint1(0.3, -0.3, 0.2);
  plateSource->SetPoint2(-0.3, 0.3, 0.2);
  plateSource->Update();
  auto plate = Rotated(plateSource->GetOutput());
  vtkIdType middle = -1;
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    double p[3];
    plane->GetPoint(i, p);
    middle = vtkMath::Norm(p) < 1e-9 ? i : middle;
  }
  // The plate covers a square of solid angle 4 atan(a^2 / (h sqrt(h^2 + 2 a^2))), a = 0.3 its
  // half side, h = 0.2 its height.
  const double covered = 4.0 * std::atan(0.09 / (0.2 * std::sqrt(0.04 + 0.18)));
  for (int b = 0; b < 3; ++b)
  {
    auto open = Run(plane, Backends[b], 3);
    auto shaded = Run(plane, Backends[b], 3, plate);
    const double before = SeenSolidAngle(open, middle), after = SeenSolidAngle(shaded, middle);
    std::cout << Names[b] << ": plane middle sees " << before << " sr, under the plate " << after
              << " sr: " << before - after << " sr covered (" << covered << ")\n";
    Check(shaded->GetNumberOfPoints() == plane->GetNumberOfPoints() &&
        std::abs((before - after) - covered) < 0.2,
      std::string(Names[b]) + ": an occluder darkens what is under it");
  }

  // Raising the level renders only the new directions; the output keeps the input's arrays.
  auto tagged = vtkSmartPointer<vtkPolyData>::New();
  tagged->DeepCopy(bunny);
  vtkNew<vtkFloatArray> tag;
  tag->SetName("Tag");
  tag->SetNumberOfTuples(tagged->GetNumberOfPoints());
  tag->Fill(7.0f);
  tagged->GetPointData()->AddArray(tag);
  const int inputArrays = tagged->GetPointData()->GetNumberOfArrays();
  for (int b = 1; b < 3; ++b)
  {
    vtkNew<vtkOcclusionQueryVisibility> filter;
    Run(tagged, Backends[b], 2, nullptr, filter);
    const int first = filter->GetNumberOfDepthPasses();
    auto raised = Run(tagged, Backends[b], 3, nullptr, filter);
    const int second = filter->GetNumberOfDepthPasses();
    Run(tagged, Backends[b], 2, nullptr, filter);
    const int third = filter->GetNumberOfDepthPasses();
    tagged->Modified();
    Run(tagged, Backends[b], 2, nullptr, filter);
    const int fourth = filter->GetNumberOfDepthPasses();
    std::cout << Names[b] << ": passes at level 2: " << first << ", raised to 3: " << second
              << ", back to 2: " << third << ", after the input changed: " << fourth << "\n";
    // DepthCompare renders a direction and its opposite in one pass; RayCast counts directions.
    const int per = Backends[b] == vtkOcclusionQueryVisibility::DEPTH_COMPARE ? 2 : 1;
    Check(first == 66 / per && second == (258 - 66) / per && third == 0 && fourth == 66 / per,
      std::string(Names[b]) + ": a higher level renders only its new directions");
    vtkPointData* pd = raised->GetPointData();
    auto* values = vtkFloatArray::SafeDownCast(pd->GetArray("Visibility"));
    bool bitsMatch = values && values->GetNumberOfComponents() == 258;
    for (vtkIdType i = 0; bitsMatch && i < raised->GetNumberOfPoints(); i += 13)
    {
      for (int j = 0; j < 258; ++j)
      {
        bitsMatch = bitsMatch && (values->GetComponent(i, j) > 0) == Sees(raised, i, j);
      }
    }
    Check(bitsMatch, "VisibilityBits match Visibility");
    Check(pd->GetArray("Tag") && pd->GetNormals() &&
        raised->GetFieldData()->GetArray("LightDirections")->GetNumberOfTuples() == 258 &&
        raised->GetFieldData()->GetArray("LightWeights")->GetNumberOfTuples() == 258,
      "the output keeps the input's arrays and adds normals and the lightsphere");
  }
  Check(tagged->GetPointData()->GetNumberOfArrays() == inputArrays &&
      !tagged->GetPointData()->GetArray("Visibility") && !tagged->GetPointData()->GetNormals(),
    "the input is not modified");

  // Sharing a render window leaves its GL state as it was.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(200, 160);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  renderer->ResetCamera();
  const std::vector<unsigned char> before = Picture(window);
  for (int b = 0; b < 2; ++b)
  {
    vtkNew<vtkOcclusionQueryVisibility> shared;
    shared->SetRenderWindow(window);
    Run(bunny, Backends[b], 1, nullptr, shared);
    Check(shared->GetOutput()->GetPointData()->GetArray("Visibility") != nullptr,
      std::string(Names[b]) + " in a shared window");
    shared->ReleaseGraphicsResources(window);
  }
  const std::vector<unsigned char> after = Picture(window);
  Check(before == after, "the shared window renders the same picture afterwards");

  // A window that renders the filter's output: the pipeline frees itself (the filter keeps no
  // reference to the window), and the filter outlives the window it shared.
  vtkWeakPointer<vtkOcclusionQueryVisibility> freed;
  vtkSmartPointer<vtkPolyData> inWindow, afterWindow;
  {
    vtkNew<vtkOcclusionQueryVisibility> drawn;
    freed = drawn;
    vtkNew<vtkRenderWindow> loop;
    loop->SetOffScreenRendering(1);
    loop->SetSize(64, 64);
    vtkNew<vtkRenderer> loopRenderer;
    loop->AddRenderer(loopRenderer);
    vtkNew<vtkPolyDataMapper> loopMapper;
    loopMapper->SetInputConnection(drawn->GetOutputPort());
    vtkNew<vtkActor> loopActor;
    loopActor->SetMapper(loopMapper);
    loopRenderer->AddActor(loopActor);
    drawn->SetRenderWindow(loop);
    inWindow = Run(bunny, vtkOcclusionQueryVisibility::DEPTH_COMPARE, 1, nullptr, drawn);
    loop->Render();
  }
  Check(!freed, "a window drawing the filter's output does not keep the pipeline alive");
  {
    vtkNew<vtkOcclusionQueryVisibility> outlives;
    {
      vtkNew<vtkRenderWindow> gone;
      gone->SetOffScreenRendering(1);
      outlives->SetRenderWindow(gone);
      Run(bunny, vtkOcclusionQueryVisibility::DEPTH_COMPARE, 1, nullptr, outlives);
    }
    Check(outlives->GetRenderWindow() == nullptr, "the filter forgets a window that is gone");
    afterWindow = Run(bunny, vtkOcclusionQueryVisibility::DEPTH_COMPARE, 1, nullptr, outlives);
  }
  vtkDataArray* seenBefore = inWindow->GetPointData()->GetArray("Visibility");
  vtkDataArray* seenAfter = afterWindow->GetPointData()->GetArray("Visibility");
  vtkIdType differ = 0;
  for (vtkIdType i = 0; seenBefore && seenAfter && i < seenBefore->GetNumberOfValues(); ++i)
  {
    differ += seenBefore->GetVariantValue(i) == seenAfter->GetVariantValue(i) ? 0 : 1;
  }
  Check(seenBefore && seenAfter && differ == 0 &&
      seenBefore->GetNumberOfValues() == seenAfter->GetNumberOfValues(),
    "the filter runs again, in its own window, once the shared one is gone: same visibility");

  // Progress and abort.
  vtkNew<vtkOcclusionQueryVisibility> watched;
  watched->SetInputData(bunny);
  watched->SetBackendToRayCast();
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&progressEvents);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  watched->AddObserver(vtkCommand::ProgressEvent, progress);
  watched->Update();
  Check(progressEvents >= 66 / 8, "progress events while computing");
  vtkNew<vtkOcclusionQueryVisibility> aborted;
  aborted->SetInputData(bunny);
  aborted->SetBackendToRayCast();
  vtkNew<vtkCallbackCommand> stop;
  stop->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
    { static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn(); });
  aborted->AddObserver(vtkCommand::ProgressEvent, stop);
  aborted->Update();
  Check(aborted->GetOutput()->GetNumberOfPoints() == 0, "an aborted run leaves an empty output");

  // Bad input.
  vtkNew<vtkOcclusionQueryVisibility> bad;
  bad->SetLevel(9);
  Check(bad->GetLevel() == 4, "level clamped to 4");
  bad->SetLevel(-1);
  Check(bad->GetLevel() == 0, "level clamped to 0");
  auto expectError = [&](vtkPolyData* input, const std::string& words, const std::string& what)
  {
    vtkNew<vtkTest::ErrorObserver> errors, executiveErrors;
    bad->SetInputData(input);
    bad->AddObserver(vtkCommand::ErrorEvent, errors);
    bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
    const bool updated = bad->GetExecutive()->Update() != 0;
    bad->RemoveAllObservers();
    bad->GetExecutive()->RemoveAllObservers();
    const std::string message = errors->GetErrorMessage();
    std::cout << what << ": " << message.substr(message.find("): ") + 3);
    Check(!updated && message.find(words) != std::string::npos, what);
  };
  vtkNew<vtkPolyData> empty;
  expectError(empty, "empty", "empty input");
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  cloud->SetPoints(points);
  vtkNew<vtkCellArray> vertices;
  vertices->InsertNextCell({ 0 });
  vertices->InsertNextCell({ 1 });
  cloud->SetVerts(vertices);
  expectError(cloud, "polygons", "points without polygons");
  return vtkApertureTest::Result();
}
