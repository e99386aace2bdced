/*=========================================================================

  Program:   ApertureLighting
  Module:    TestOcclusionQueryVisibilityNoGL.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkOcclusionQueryVisibility where OpenGL falls short. ctest runs this test three times:
// - plainly: every backend works;
// - with --no-display and DISPLAY pointing nowhere (a name holding ESC and BEL): the OpenGL
//   backends fail with an error that says there is no OpenGL context (VTK's own window would
//   abort the program) and shows the name escaped, RayCast works;
// - with --old-gl under MESA_GL_VERSION_OVERRIDE=3.2: DepthCompare fails naming the OpenGL 4.3
//   it needs, OcclusionQuery works where the driver still offers its queries or names them,
//   RayCast works.

#include "vtkApertureTestHarness.h"
#include "vtkApertureText.h"
#include "vtkOcclusionQueryVisibility.h"

#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
using vtkApertureTest::Check;

// Runs a backend; returns its error message, empty on success.
std::string Run(vtkPolyData* input, int backend)
{
  vtkNew<vtkOcclusionQueryVisibility> filter;
  filter->SetInputData(input);
  filter->SetBackend(backend);
  filter->SetLevel(1);
  vtkNew<vtkTest::ErrorObserver> errors, executiveErrors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  const bool updated = filter->GetExecutive()->Update() != 0;
  const bool computed = filter->GetOutput()->GetPointData()->GetArray("Visibility") != nullptr;
  if (updated && computed && !errors->GetError())
  {
    return std::string();
  }
  const std::string message = errors->GetError() ? errors->GetErrorMessage() : "(no error)";
  std::string text = message.substr(message.find("): ") + 3);
  return text.erase(text.find_last_not_of('\n') + 1);
}
}

int TestOcclusionQueryVisibilityNoGL(int argc, char* argv[])
{
  std::string mode = "plain";
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    mode = arg == "--no-display" ? "no-display" : (arg == "--old-gl" ? "old-gl" : mode);
  }
  if (mode == "no-display")
  {
    // Nowhere, by a name that would retitle a terminal if printed raw.
    setenv("DISPLAY", "\x1b]2;owned\x07:4919", 1);
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();

  const std::string query = Run(sphere->GetOutput(), vtkOcclusionQueryVisibility::OCCLUSION_QUERY);
  const std::string depth = Run(sphere->GetOutput(), vtkOcclusionQueryVisibility::DEPTH_COMPARE);
  const std::string rays = Run(sphere->GetOutput(), vtkOcclusionQueryVisibility::RAY_CAST);
  std::cout << "mode " << mode << "\n  OcclusionQuery: " << (query.empty() ? "works" : query)
            << "\n  DepthCompare: " << (depth.empty() ? "works" : depth)
            << "\n  RayCast: " << (rays.empty() ? "works" : rays) << "\n";

  const std::string inMode = "mode " + mode + ": ";
  Check(rays.empty(), inMode + "RayCast must work");
  if (mode == "no-display")
  {
    Check(query.find("No OpenGL context") != std::string::npos,
      inMode + "OcclusionQuery must fail saying there is no OpenGL context");
    Check(depth.find("No OpenGL context") != std::string::npos,
      inMode + "DepthCompare must fail saying there is no OpenGL context");
    Check(
      vtkApertureText::IsSafe(query) && query.find("\\x1b]2;owned\\x07:4919") != std::string::npos,
      inMode + "the error shows the display's name escaped");
  }
  else if (mode == "old-gl")
  {
    Check(depth.find("OpenGL 4.3") != std::string::npos,
      inMode + "DepthCompare must fail naming the OpenGL 4.3 it needs");
    Check(query.empty() || query.find("OpenGL 3.3") != std::string::npos,
      inMode + "OcclusionQuery must work or fail naming OpenGL 3.3");
  }
  else
  {
    Check(query.empty(), inMode + "OcclusionQuery must work");
    Check(depth.empty(), inMode + "DepthCompare must work");
  }
  return vtkApertureTest::Result();
}
