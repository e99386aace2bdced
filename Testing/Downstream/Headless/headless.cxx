// Links ApertureLighting::Core alone and computes what needs no display: apertures, the
// visibility matrix by rays, and relighting under a uniform environment. A ground of 21 x 21
// points with a square roof above its middle: the point under the roof must see less sky than
// a corner, by each of the three.
#include "vtkAperturePrecompute.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightSphereVisibility.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <iostream>

namespace
{
constexpr int Side = 21;

// The ground (z = 0, [-1, 1]^2, points row by row) and a roof at z = 0.3 over [-0.4, 0.4]^2.
vtkNew<vtkPolyData> Scene()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j < Side; ++j)
  {
    for (int i = 0; i < Side; ++i)
    {
      points->InsertNextPoint(-1.0 + 0.1 * i, -1.0 + 0.1 * j, 0.0);
      if (i > 0 && j > 0)
      {
        const vtkIdType corner = j * Side + i;
        const vtkIdType quad[4] = { corner - Side - 1, corner - Side, corner, corner - 1 };
        polys->InsertNextCell(4, quad);
      }
    }
  }
  const vtkIdType roof = points->GetNumberOfPoints();
  const double r = 0.4, z = 0.3;
  points->InsertNextPoint(-r, -r, z);
  points->InsertNextPoint(-r, r, z);
  points->InsertNextPoint(r, r, z);
  points->InsertNextPoint(r, -r, z);
  const vtkIdType quad[4] = { roof, roof + 1, roof + 2, roof + 3 }; // facing down
  polys->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> scene;
  scene->SetPoints(points);
  scene->SetPolys(polys);
  return scene;
}

// A uniform latitude-longitude environment of radiance 1.
vtkNew<vtkImageData> UniformSky()
{
  vtkNew<vtkImageData> sky;
  sky->SetDimensions(32, 16, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(32 * 16);
  radiance->FillValue(1.0f);
  sky->GetPointData()->SetScalars(radiance);
  return sky;
}

bool Check(const char* what, double middle, double corner, double low, double high)
{
  const bool ok = std::isfinite(middle) && middle < corner && corner >= low && corner <= high;
  std::cout << what << ": under the roof " << middle << ", at a corner " << corner
            << (ok ? "" : "  WRONG") << "\n";
  return ok;
}
}

int main()
{
  vtkNew<vtkPolyData> scene = Scene();
  const vtkIdType middle = (Side / 2) * Side + Side / 2, corner = 0;

  vtkNew<vtkAperturePrecompute> apertures;
  apertures->SetInputData(scene);
  apertures->SetNumberOfRays(256);
  apertures->Update();
  vtkDataArray* radius = apertures->GetPolyDataOutput()->GetPointData()->GetArray("ApertureRadius");

  vtkNew<vtkLightSphereVisibility> visibility;
  visibility->SetInputData(scene);
  visibility->SetLevel(2);
  visibility->Update();
  vtkDataArray* matrix = visibility->GetOutput()->GetPointData()->GetArray("Visibility");

  vtkNew<vtkImageData> sky = UniformSky();
  vtkNew<vtkEnvironmentVisibilityLighting> relight;
  relight->SetInputConnection(visibility->GetOutputPort());
  relight->SetEnvironmentData(sky);
  relight->Update();
  vtkDataArray* light = relight->GetOutput()->GetPointData()->GetArray("EnvironmentLighting");
  if (!radius || !matrix || !light)
  {
    std::cout << "missing output arrays\n";
    return 1;
  }
  auto seen = [&](vtkIdType p)
  {
    double sum = 0.0;
    for (int j = 0; j < matrix->GetNumberOfComponents(); ++j)
    {
      sum += matrix->GetComponent(p, j) > 0.0 ? 1.0 : 0.0;
    }
    return sum;
  };
  // An open point sees a hemisphere: aperture radius pi/2, half of the 66 directions (those in
  // the plane excepted), and under a uniform sky of 1 the radiance 1 (to the sphere's accuracy).
  bool ok = Check(
    "aperture radius", radius->GetComponent(middle, 0), radius->GetComponent(corner, 0), 1.4, 1.58);
  ok = Check("directions seen", seen(middle), seen(corner), 20, 33) && ok;
  ok = Check("environment lighting", light->GetComponent(middle, 0), light->GetComponent(corner, 0),
         0.9, 1.1) &&
    ok;
  return ok ? 0 : 1;
}
