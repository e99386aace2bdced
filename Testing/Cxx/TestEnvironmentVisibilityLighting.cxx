/*=========================================================================

  Program:   ApertureLighting
  Module:    TestEnvironmentVisibilityLighting.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkEnvironmentVisibilityLighting:
// - a sphere under a uniform environment of radiance 1 comes out at 1 (k = 258);
// - open points of a sphere under the forest map get the irradiance that direct integration of
//   the map over their hemisphere gives, over pi;
// - the bit-packed visibility gives what the float one gives; a full turn changes nothing,
//   a quarter turn does; exposure and gamma act on the colours only;
// - the output keeps the input's arrays; bad input is an error.

#include "vtkApertureTestHarness.h"
#include "vtkEnvironmentVisibilityLighting.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMap.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOcclusionQueryVisibility.h"
#include "vtkOpenEXRReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using vtkApertureTest::Check;

vtkSmartPointer<vtkImageData> Uniform(int w, int h, double value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  radiance->Fill(value);
  image->GetPointData()->SetScalars(radiance);
  return image;
}

vtkDataArray* Lighting(vtkEnvironmentVisibilityLighting* filter)
{
  return filter->GetOutput()->GetPointData()->GetArray("EnvironmentLighting");
}
}

int TestEnvironmentVisibilityLighting(int argc, char* argv[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkOcclusionQueryVisibility> visibility;
  visibility->SetInputConnection(sphere->GetOutputPort());
  visibility->SetBackendToRayCast();
  visibility->SetLevel(3);
  visibility->ComputeVisibilityBitsOn();
  visibility->Update();

  // A uniform environment of radiance 1.
  vtkNew<vtkEnvironmentVisibilityLighting> lighting;
  lighting->SetInputConnection(visibility->GetOutputPort());
  lighting->SetEnvironmentData(Uniform(128, 64, 1.0));
  lighting->Update();
  vtkDataArray* c = Lighting(lighting);
  double mean = 0.0, worst = 0.0;
  for (vtkIdType i = 0; i < c->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double error = std::abs(c->GetComponent(i, k) - 1.0);
      mean += error / (3.0 * c->GetNumberOfTuples());
      worst = std::max(worst, error);
    }
  }
  std::cout << "sphere under radiance 1, k = 258: mean |c - 1| = " << mean << ", worst " << worst
            << "\n";
  Check(mean <= 0.02 && worst <= 0.05, "a uniform environment gives 1 (2% mean, 5% worst)");

  // The forest: open points against direct integration of the map over their hemisphere.
  char* forestName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/env/forest.exr");
  vtkNew<vtkOpenEXRReader> forest;
  forest->SetFileName(forestName);
  delete[] forestName;
  forest->Update();
  if (forest->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cout << "FAIL the forest map cannot be read (is -D the Testing folder?)\n";
    return EXIT_FAILURE;
  }
  lighting->SetEnvironmentConnection(forest->GetOutputPort());
  lighting->SetUpAxisToY();
  lighting->Update();
  vtkNew<vtkEnvironmentMap> direct;
  direct->SetImage(forest->GetOutput());
  direct->SetUpAxisToY();
  vtkPolyData* out = lighting->GetOutput();
  double sumError = 0.0, sumDirect = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double n[3], e[3];
    out->GetPointData()->GetNormals()->GetTuple(i, n);
    direct->CapIrradiance(n, 0.5 * vtkMath::Pi(), e);
    for (int k = 0; k < 3; ++k)
    {
      sumError += std::abs(Lighting(lighting)->GetComponent(i, k) - e[k] / vtkMath::Pi());
      sumDirect += e[k] / vtkMath::Pi();
    }
  }
  std::cout << "forest on the sphere: mean relative difference from direct integration "
            << 100 * sumError / sumDirect << "%\n";
  Check(sumError / sumDirect < 0.03, "the forest's irradiance on open points, within 3%");

  // The bits give what the values give.
  vtkNew<vtkPolyData> bitsOnly;
  bitsOnly->ShallowCopy(visibility->GetOutput());
  bitsOnly->GetPointData()->RemoveArray("Visibility");
  vtkNew<vtkEnvironmentVisibilityLighting> fromBits;
  fromBits->SetInputData(bitsOnly);
  fromBits->SetEnvironmentConnection(forest->GetOutputPort());
  fromBits->SetUpAxisToY();
  fromBits->Update();
  double worstBits = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      worstBits = std::max(worstBits,
        std::abs(Lighting(fromBits)->GetComponent(i, k) - Lighting(lighting)->GetComponent(i, k)));
    }
  }
  Check(worstBits < 1e-4, "VisibilityBits give what Visibility gives");

  // Turning: a full turn changes nothing, a quarter turn does.
  vtkNew<vtkFloatArray> before;
  before->DeepCopy(Lighting(lighting));
  lighting->SetAzimuth(360.0);
  lighting->Update();
  double fullTurn = 0.0;
  for (vtkIdType v = 0; v < before->GetNumberOfValues(); ++v)
  {
    fullTurn = std::max(
      fullTurn, std::abs(Lighting(lighting)->GetComponent(v / 3, v % 3) - before->GetValue(v)));
  }
  lighting->SetAzimuth(90.0);
  lighting->Update();
  double quarterTurn = 0.0;
  for (vtkIdType v = 0; v < before->GetNumberOfValues(); ++v)
  {
    quarterTurn = std::max(
      quarterTurn, std::abs(Lighting(lighting)->GetComponent(v / 3, v % 3) - before->GetValue(v)));
  }
  std::cout << "largest change after a full turn " << fullTurn << ", after a quarter turn "
            << quarterTurn << "\n";
  Check(fullTurn < 1e-4 && quarterTurn > 0.05, "turning the environment relights");

  // Exposure and gamma: with gamma 1, one stop doubles the colours.
  lighting->SetGamma(1.0);
  lighting->SetExposure(-3.0);
  lighting->Update();
  vtkNew<vtkUnsignedCharArray> dim;
  dim->DeepCopy(out->GetPointData()->GetArray("EnvironmentColors"));
  lighting->SetExposure(-2.0);
  lighting->Update();
  auto* bright =
    vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("EnvironmentColors"));
  int worstStop = 0;
  for (vtkIdType v = 0; v < dim->GetNumberOfValues(); ++v)
  {
    if (bright->GetValue(v) < 255)
    {
      worstStop = std::max(worstStop, std::abs(bright->GetValue(v) - 2 * dim->GetValue(v)));
    }
  }
  Check(worstStop <= 1, "one stop of exposure doubles the colours");
  Check(out->GetPointData()->GetArray("Visibility") && out->GetPointData()->GetNormals() &&
      out->GetFieldData()->GetArray("LightWeights") &&
      !visibility->GetOutput()->GetPointData()->GetArray("EnvironmentLighting"),
    "the output keeps the input's arrays; the input is untouched");

  // Bad input.
  auto expect = [&](vtkPolyData* input, vtkImageData* environment, const std::string& words,
                  const std::string& what)
  {
    vtkNew<vtkEnvironmentVisibilityLighting> bad;
    bad->SetInputData(input);
    if (environment)
    {
      bad->SetEnvironmentData(environment);
    }
    vtkNew<vtkTest::ErrorObserver> errors, executive;
    bad->AddObserver(vtkCommand::ErrorEvent, errors);
    bad->AddObserver(vtkCommand::WarningEvent, errors);
    bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
    bad->GetExecutive()->Update();
    const std::string message =
      errors->GetError() ? errors->GetErrorMessage() : errors->GetWarningMessage();
    std::cout << what << ": " << message.substr(message.find("): ") + 3);
    Check(message.find(words) != std::string::npos, what);
  };
  vtkNew<vtkPolyData> plain;
  plain->ShallowCopy(sphere->GetOutput());
  expect(plain, Uniform(64, 32, 1.0), "no lightsphere", "no visibility at all");
  vtkNew<vtkPolyData> noValues;
  noValues->ShallowCopy(visibility->GetOutput());
  noValues->GetPointData()->RemoveArray("Visibility");
  noValues->GetPointData()->RemoveArray("VisibilityBits");
  expect(noValues, Uniform(64, 32, 1.0), "no visibility", "no visibility array");
  expect(visibility->GetOutput(), nullptr, "No environment", "no environment");
  expect(visibility->GetOutput(), Uniform(50, 50, 1.0), "not 2:1", "a square environment");
  return vtkApertureTest::Result();
}
