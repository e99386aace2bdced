/*=========================================================================

  Program:   ApertureLighting
  Module:    TestCompositeApertureLightingMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkCompositeApertureLightingMapper on a multiblock from vtkAperturePrecompute (a bunny on a
// floor, next to a ball whose aperture arrays were removed): the image equals the one of a
// vtkApertureLightingMapper per block, the ball falls back to standard shading with a warning,
// and the picture matches its baseline.

#include "vtkApertureLightingMapper.h"
#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"
#include "vtkCompositeApertureLightingMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>

namespace
{
using vtkApertureTest::Check;

void Light(vtkRenderer* renderer)
{
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0);
  lamp->SetPosition(0.25, 0.35, 0.25);
  lamp->SetIntensity(0.9);
  vtkApertureLightingMapper::SetLightRadius(lamp, 0.05);
  renderer->AddLight(lamp);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.1, 0.3, 0.5);
  camera->SetFocalPoint(0.0, 0.1, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.2);
}

void Settings(vtkApertureLightingInterface* lighting)
{
  lighting->SetSkyIntensity(0.35);
  lighting->SetSkyColor(0.6, 0.7, 1.0);
}
}

int TestCompositeApertureLightingMapper(int argc, char* argv[])
{
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/stanford-bunny.obj");
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(file);
  reader->Update();
  delete[] file;
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-0.2, 0.033, -0.15);
  floor->SetPoint1(0.15, 0.033, -0.15);
  floor->SetPoint2(-0.2, 0.033, 0.2);
  floor->SetResolution(40, 40);
  floor->Update();
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0.1, 0.12, 0.05);
  ball->SetRadius(0.02);
  ball->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(3);
  blocks->SetBlock(0, reader->GetOutput());
  blocks->SetBlock(1, floor->GetOutput());
  blocks->SetBlock(2, ball->GetOutput());
  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputData(blocks);
  apertures->SetNumberOfRays(128);
  apertures->Update();
  auto* shaded = vtkMultiBlockDataSet::SafeDownCast(apertures->GetOutputDataObject(0));
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(shaded->GetBlock(2));
  bare->GetPointData()->RemoveArray("BentNormal");
  shaded->SetBlock(2, bare);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.3, 0.35, 0.4);
  window->AddRenderer(renderer);

  // One vtkApertureLightingMapper per block first.
  vtkNew<vtkTest::ErrorObserver> observer;
  for (unsigned int b = 0; b < 3; ++b)
  {
    vtkNew<vtkApertureLightingMapper> mapper;
    mapper->SetInputData(vtkPolyData::SafeDownCast(shaded->GetBlock(b)));
    Settings(mapper->GetApertureLighting());
    mapper->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, observer);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
  Light(renderer);
  window->Render();
  vtkNew<vtkUnsignedCharArray> separate;
  window->GetPixelData(0, 0, 399, 299, 1, separate, 0);
  const bool warnedSeparate = observer->GetWarning();
  observer->Clear();

  // Then the composite mapper on the whole multiblock.
  renderer->RemoveAllViewProps();
  vtkNew<vtkCompositeApertureLightingMapper> composite;
  composite->SetInputDataObject(shaded);
  Settings(composite->GetApertureLighting());
  composite->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, observer);
  vtkNew<vtkActor> actor;
  actor->SetMapper(composite);
  renderer->AddActor(actor);
  window->Render();
  vtkNew<vtkUnsignedCharArray> together;
  window->GetPixelData(0, 0, 399, 299, 1, together, 0);

  double sum = 0.0;
  int worst = 0;
  for (vtkIdType i = 0; i < together->GetNumberOfValues(); ++i)
  {
    const int d = std::abs(static_cast<int>(together->GetValue(i)) - separate->GetValue(i));
    sum += d;
    worst = std::max(worst, d);
  }
  const double mean = sum / together->GetNumberOfValues();
  std::cout << "composite vs one mapper per block: mean |difference| " << mean << "/255, max "
            << worst << "/255; warnings: " << observer->GetWarningMessage();
  Check(mean <= 0.1 && worst <= 2, "the composite mapper must shade like one mapper per block");
  Check(warnedSeparate && observer->GetWarning() &&
      observer->GetWarningMessage().find("BentNormal") != std::string::npos,
    "the block without apertures must be reported");
  const int retVal = vtkRegressionTestImage(window);
  Check(retVal != 0, "the image matches its baseline");
  return vtkApertureTest::Result();
}
