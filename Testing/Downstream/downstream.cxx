// Links VTK::ApertureLighting from its CMake package and uses it.
#include "vtkNew.h"
#include "vtkSphericalCap.h"

#include <cmath>
#include <iostream>

int main()
{
  vtkNew<vtkSphericalCap> cap;
  const double area = vtkSphericalCap::IntersectionArea(0.5, 0.3, 0.4);
  // Two caps: radius 0.3 fully inside radius 0.5 needs d <= 0.2; at d = 0.4 they cross.
  const double inner = vtkSphericalCap::SolidAngleFromCapRadius(0.3);
  std::cout << cap->GetClassName() << " IntersectionArea(0.5, 0.3, 0.4) = " << area << "\n";
  return (area > 0.0 && area < inner && std::isfinite(area)) ? 0 : 1;
}
