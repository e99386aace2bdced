/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSceneSurfaces.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSceneSurfaces
 * @brief   the surfaces of one ray-casting scene, around one local origin (private)
 *
 * The one path by which every caster (vtkAperturePrecompute, vtkApertureReference,
 * vtkLightSphereVisibility) turns its receivers and occluders into vtkApertureSurface: one local
 * origin at the middle of everything, which keeps single precision where the geometry is; each
 * receiver built from its polydata (vtkApertureMeshSurface) or height field
 * (vtkApertureGridSurface), with its ray offsets (vtkApertureRayOffsets); each occluder built as
 * a mesh.
 *
 * @sa vtkApertureSurface vtkApertureRayScene
 */

#ifndef vtkApertureSceneSurfaces_h
#define vtkApertureSceneSurfaces_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include <string>
#include <vector>

class vtkApertureSurface;
class vtkDataArray;
class vtkDataSet;
class vtkPolyData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureSceneSurfaces
{
public:
  /**
   * A receiving dataset: a polydata, or a vtkImageData height field with its heights. A
   * polydata piece of distributed data may have Ghosts: the other pieces' cells around its
   * border (vtkApertureDistributedOccluders::TakeGhosts), which its surface includes, so that
   * its border points get the normals, creases and own triangles of the whole surface. They
   * receive no output. Left out when the input has normals of its own.
   */
  struct Receiver
  {
    vtkDataSet* Input = nullptr;
    vtkDataArray* Heights = nullptr;
    vtkApertureSurface* Surface = nullptr;
    vtkPolyData* Ghosts = nullptr;
  };

  /// How surfaces are built.
  struct Settings
  {
    double FeatureAngle = 60.0;
    double RayOffset = 0.001;
    double HeightScale = 1.0;
  };

  /**
   * Builds every receiver's Surface and `occluderSurfaces` around one origin. False with one
   * sentence in `error` ("Cannot use the input: ...", "Cannot use occluder i: ...") when one of
   * them is unusable.
   */
  static bool Build(const std::vector<Receiver>& receivers,
    const std::vector<vtkPolyData*>& occluders, const Settings& settings,
    std::vector<vtkApertureSurface>& occluderSurfaces, std::string& error);

  /**
   * The same for one polydata receiver (with its ghost cells, or nullptr), and also an error when
   * neither it nor an occluder has a polygon or strip (nothing would cast shadows, and points would
   * have no normals).
   */
  static bool Build(vtkPolyData* input, vtkPolyData* ghosts,
    const std::vector<vtkPolyData*>& occluders, const Settings& settings,
    vtkApertureSurface& receivers, std::vector<vtkApertureSurface>& occluderSurfaces,
    std::string& error);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSceneSurfaces.h
