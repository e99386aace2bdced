/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureTestEnvironment.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Environments the project's C++ tests light with: latitude-longitude images made from a
// function of the image point.

#ifndef vtkApertureTestEnvironment_h
#define vtkApertureTestEnvironment_h

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <functional>

namespace vtkApertureTest
{
// A w x h latitude-longitude image of RGB floats whose pixel (i, j) holds f at its centre,
// u = (i + 1/2)/w, v = (j + 1/2)/h (vtkEnvironmentMap's image points).
inline vtkSmartPointer<vtkImageData> LatLong(
  int w, int h, const std::function<void(double u, double v, double rgb[3])>& f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (vtkIdType p = 0; p < radiance->GetNumberOfTuples(); ++p)
  {
    double rgb[3];
    f((p % w + 0.5) / w, (p / w + 0.5) / h, rgb);
    radiance->SetTuple(p, rgb);
  }
  image->GetPointData()->SetScalars(radiance);
  return image;
}

// A sky whose channels all differ: red a warm glow low in the north-east over a floor that
// brightens upward, green and blue brighter toward the zenith.
inline vtkSmartPointer<vtkImageData> GlowSky()
{
  return LatLong(128, 64,
    [](double u, double v, double rgb[3])
    {
      const double glow = std::exp(-15.0 * ((u - 0.6) * (u - 0.6) + (v - 0.6) * (v - 0.6)));
      rgb[0] = 0.3 + 0.4 * v + 2.0 * glow;
      rgb[1] = 0.3 + v;
      rgb[2] = 0.6 + 0.5 * v;
    });
}
}

#endif
// VTK-HeaderTest-Exclude: vtkApertureTestEnvironment.h
