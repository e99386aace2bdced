/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderInput.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's input: a mesh, or a height field as a 2D grid of heights in metres.

#ifndef ApertureRenderInput_h
#define ApertureRenderInput_h

#include "vtkImageData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace ApertureRender
{
struct Options;
class MessageCapture;

struct Input
{
  vtkSmartPointer<vtkPolyData> Mesh;
  // A height field: a 2D grid whose active scalars, a float array named Elevation, are heights.
  vtkSmartPointer<vtkImageData> Heights;
  // A CT or MR volume, one scalar component (drawn by vtkApertureVolumeMapper), and the compass
  // azimuth its front (a patient's face) is seen from.
  vtkSmartPointer<vtkImageData> Volume;
  double FrontAzimuth = 180.0;
  std::string Description;
  // The --env environment, a float RGB latitude-longitude image; null without --env.
  vtkSmartPointer<vtkImageData> Environment;
  // What was changed on the way (resampling, filled voids), for the user.
  std::vector<std::string> Notes;
  // Meshes: the edge length they are refined to (0: not refined).
  double MaximumEdge = 0.0;
  // Points that are not finite (the cells that use them are not drawn).
  vtkIdType NonFinitePoints = 0;
};

// Reads the input the options name, or the embedded Mount Fuji tile. Returns false with one
// sentence in `error` when the input cannot be used.
bool LoadInput(const Options& options, MessageCapture& messages, Input& input, std::string& error);

// Resamples a height field larger than `maximum` samples a side to at most that, keeping its
// extent on the ground (for rays, which cost per sample).
void Resample(Input& input, int maximum);

// Reads the --env environment, if any, into `input`. Returns false with one sentence in `error`
// when the file cannot be used.
bool LoadEnvironment(
  const Options& options, MessageCapture& messages, Input& input, std::string& error);
}

#endif
