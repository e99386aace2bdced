/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurface.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSurface
 * @brief   triangulated surface in single precision, as the ray casters see it (private)
 *
 * Converts the polygons and strips of a vtkPolyData, or a vtkImageData height field, into what
 * Embree and the per-point ray loops need: points relative to a local origin in float (so that
 * large coordinates keep their precision), uint32 triangles, unit point normals, which points
 * receive rays, and each point's mean edge length (the scale of its ray offset).
 *
 * Triangles with a non-finite vertex are left out. Points that are not finite, or whose normal is
 * undefined, are flagged invalid; the counts are kept for the caller's warnings.
 */

#ifndef vtkApertureSurface_h
#define vtkApertureSurface_h

#include "vtkApertureLightingModule.h" // For export macro

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkFloatArray;
class vtkImageData;
class vtkPolyData;

class VTKAPERTURELIGHTING_EXPORT vtkApertureSurface
{
public:
  ///@{
  /**
   * Grows bounds (xmin, xmax, ymin, ymax, zmin, zmax), which InitializeBounds() makes empty, by
   * the finite points of a dataset, so that all surfaces of a scene can share one local origin.
   */
  static void InitializeBounds(double bounds[6]);
  static void ExpandBounds(vtkPolyData* input, double bounds[6]);
  static void ExpandBounds(
    vtkImageData* input, vtkDataArray* heights, double heightScale, double bounds[6]);
  ///@}

  /**
   * The local origin of a scene: the centre of its bounds (0 for empty bounds). Single precision
   * is kept where the geometry is, even at UTM-sized coordinates.
   */
  static void OriginOf(const double bounds[6], double origin[3]);

  /**
   * Builds the surface from the polygons and strips of a polydata. Point normals are taken from
   * the input when it has a usable normals array; otherwise they are the normalised sums of the
   * unit normals of each point's triangles (as vtkPolyDataNormals computes them without
   * splitting), after vtkPolyDataNormals has made the orientation consistent if the triangles'
   * winding is not. Returns false with a message when the input is unusable (2^32 points or more).
   */
  bool SetPolyData(vtkPolyData* input, const double origin[3], std::string& error);

  /**
   * Builds the surfaces of a scene of receivers and occluders (polydata), all around one local
   * origin. Returns false with one sentence in `error` when one of them is unusable or none has
   * a polygon or strip (then nothing casts shadows and points have no normals).
   */
  static bool SetScene(vtkPolyData* input, const std::vector<vtkPolyData*>& occluders,
    vtkApertureSurface& receivers, std::vector<vtkApertureSurface>& occluderSurfaces,
    std::string& error);

  /**
   * Builds the surface of a 2D height field: grid point (i, j) raised by heightScale × height
   * along the grid's third axis; normals point to that side.
   */
  bool SetHeightField(vtkImageData* input, vtkDataArray* heights, double heightScale,
    const double origin[3], std::string& error);

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Valid.size()); }
  const float* GetNormal(vtkIdType id) const;
  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Triangles.size() / 3);
  }

  /// The local origin: a point's coordinates are Points + Origin.
  double Origin[3] = { 0.0, 0.0, 0.0 };
  /// Local coordinates, 3 per point, plus one float of padding: Embree reads 16 bytes per vertex.
  std::vector<float> Points;
  /// Three point ids per triangle.
  std::vector<std::uint32_t> Triangles;
  /// Unit normals, one tuple per point; zero where undefined.
  vtkSmartPointer<vtkFloatArray> Normals;
  /// Whether Normals were computed (the input had none), and so belong in the output.
  bool NormalsComputed = false;
  /// 1 where the point belongs to a polygon or strip.
  std::vector<unsigned char> Receives;
  /// 1 where the point is finite and has a normal.
  std::vector<unsigned char> Valid;
  /// Mean length of the edges at each point (0 without edges).
  std::vector<float> EdgeLength;

  vtkIdType NonFinitePoints = 0;
  vtkIdType UndefinedNormals = 0;
  /// Given normals pointing against the winding of their triangles.
  vtkIdType FlippedNormals = 0;

private:
  void Allocate(vtkIdType numberOfPoints);
  // Mean edge lengths, and the sums of unit triangle normals at each point (their winding).
  void AccumulateTriangleData(std::vector<float>& windingNormals);
  // Whether no two triangles run along the same edge in the same direction.
  bool ConsistentlyWound() const;
  // Sets Normals (unit, zero where undefined), Valid and the counts from point normals.
  void SetNormals(vtkDataArray* normals, bool given, const std::vector<unsigned char>& finite,
    const std::vector<float>& winding);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSurface.h
