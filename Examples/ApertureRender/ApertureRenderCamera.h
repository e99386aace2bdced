/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderCamera.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's default view of a mesh: which way is up, and from where its broad side shows.

#ifndef ApertureRenderCamera_h
#define ApertureRenderCamera_h

#include <string>

class vtkPolyData;

namespace ApertureRender
{
struct MeshView
{
  std::string Up;       // "+x" ... "-z"
  double Azimuth = 0.0; // compass azimuth of the eye, degrees (see View::Direction)
  std::string UpReason; // why Up, for the line that describes the view
};

// The up axis (`up`, or when empty the axis opposite a flat base at the bottom, else +y, the
// convention of OBJ files and ParaView) and an eye along the mesh's thinner horizontal axis, so
// that its broad side faces the camera: on the side its surface faces most (the front of an
// open scan), else on the conventional front (+z with y up, -y with z up). No shape rule tells a
// lying figure from a standing one, so without a base the reason says how to change the guess.
MeshView ChooseView(vtkPolyData* mesh, const std::string& up);

// An azimuth in degrees turned into [0, 360).
double CompassAzimuth(double azimuth);

// The 16-point compass name of an azimuth in degrees: "N", "NNE", ... "NNW".
std::string CompassName(double azimuth);

// The unit east, north and up vectors of an up axis: east x north = up, east +x unless up is
// along x.
void CompassOf(const std::string& up, double east[3], double north[3], double upward[3]);
}

#endif
