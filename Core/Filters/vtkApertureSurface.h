/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurface.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSurface
 * @brief   a surface as the ray casters see it: welded, consistently wound, split at creases
 *          (private)
 *
 * Turns the polygons and strips of a vtkPolyData, or a vtkImageData height field, into what
 * Embree and the per-point ray loops need, the same way for every caster:
 *
 * 1. point ids are checked before anything reads through them;
 * 2. points at the same position are welded into one *vertex* (an OBJ file with texture seams
 *    gives every face corner its own point: they are one surface point);
 * 3. triangles are wound consistently across the welded surface, so that each has a front;
 * 4. the triangles around each vertex are grouped into *sides*: across an edge sharper than the
 *    feature angle (or, with given normals, between normals further apart) a crease separates
 *    them. Each vertex and side is one *receiving point*, with its own normal and its own rays;
 * 5. each input point is mapped to its receiving point. An input point that a crease runs
 *    through (a CAD mesh sharing a point between faces) maps to several: the output splits it,
 *    as vtkPolyDataNormals does (MakeOutput()).
 *
 * Geometry is stored relative to a local origin in single precision, so that large coordinates
 * keep their precision. Triangles with a non-finite vertex are left out.
 */

#ifndef vtkApertureSurface_h
#define vtkApertureSurface_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkFloatArray;
class vtkImageData;
class vtkPointData;
class vtkPoints;
class vtkPolyData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureSurface
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
   * The local origin of a scene: the centre of its bounds (0 for empty bounds).
   */
  static void OriginOf(const double bounds[6], double origin[3]);

  /**
   * Builds the surface from the polygons and strips of a polydata. Normals are the input's when
   * it has a usable normals array, else the normalised sums of the unit normals of each side's
   * triangles. Creases are edges whose faces' normals differ by more than featureAngle degrees
   * (0 to 180; 180 keeps every vertex in one piece). Returns false with one sentence in `error`
   * when the input is unusable: a cell with a point id outside the points (named), or 2^32
   * points or more.
   */
  bool SetPolyData(
    vtkPolyData* input, const double origin[3], double featureAngle, std::string& error);

  /**
   * Builds the surface of a 2D height field: grid point (i, j) raised by heightScale × height
   * along the grid's third axis, normals to that side. One receiving point per grid point (a
   * texel cannot be split).
   */
  bool SetHeightField(vtkImageData* input, vtkDataArray* heights, double heightScale,
    const double origin[3], std::string& error);

  /**
   * Builds the surfaces of a scene of one polydata receiver and its occluders around one local
   * origin, with ray offsets. Returns false with one sentence in `error` when one of them is
   * unusable or none has a polygon or strip (then nothing casts shadows).
   */
  static bool SetScene(vtkPolyData* input, const std::vector<vtkPolyData*>& occluders,
    double featureAngle, double rayOffset, vtkApertureSurface& receivers,
    std::vector<vtkApertureSurface>& occluderSurfaces, std::string& error);

  /**
   * Writes in `output` the input with the points that creases split duplicated (their point
   * data copied) and the cells that use them renumbered; `outputPoints` gets each output point's
   * receiving point (or NotOnSurface, Invalid). When a crease runs across a triangle strip, the
   * strips become triangles (after the polygons, each with its strip's cell data), as
   * vtkPolyDataNormals does. Without splits the output is a shallow copy.
   */
  void MakeOutput(
    vtkPolyData* input, vtkPolyData* output, std::vector<vtkIdType>& outputPoints) const;

  /**
   * Per-receiving-point values (`components` floats each, from `begin`) as an array over
   * output points (MakeOutput()'s `outputPoints`): `open` for points on no polygon or strip,
   * `closed` for invalid ones.
   */
  static vtkSmartPointer<vtkFloatArray> Scatter(const std::string& name, int components,
    const float* begin, const float* end, const std::vector<vtkIdType>& outputPoints,
    const float* open, const float* closed);

  /**
   * When the normals were computed here (the input had none: NormalsComputed), sets them as
   * `pd`'s Normals over MakeOutput()'s `outputPoints`, (0, 0, 0) where a point has none.
   */
  void AddComputedNormals(vtkPointData* pd, const std::vector<vtkIdType>& outputPoints) const;

  /**
   * How a polygon or strip becomes triangles, for every caster and for refinement: appends to
   * `triangles` three local corner indices (0 .. npts - 1) per triangle. Strips alternate their
   * winding; polygons of more than 3 points are ear-cut, or fanned where that fails or a point
   * is not finite (`finite` per point id; nullptr: all are). Without `points`, fans.
   */
  static void Triangulate(vtkIdType npts, const vtkIdType* ids, bool strip, vtkPoints* points,
    const unsigned char* finite, std::vector<vtkIdType>& triangles);

  /// What an input point maps to when it has no receiving point of its own.
  enum PointState : vtkIdType
  {
    NotOnSurface = -1, ///< used by no polygon or strip: open
    Invalid = -2       ///< not finite, or without a defined normal: closed
  };

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->PointVertex.size()); }
  vtkIdType GetNumberOfVertices() const
  {
    return static_cast<vtkIdType>(this->Vertices.size() / 3);
  }
  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Triangles.size() / 3);
  }
  const float* GetNormal(vtkIdType point) const;
  const float* GetPosition(vtkIdType point) const
  {
    return &this->Vertices[3 * size_t(this->PointVertex[point])];
  }

  /// The local origin: a vertex's coordinates are Vertices + Origin.
  double Origin[3] = { 0.0, 0.0, 0.0 };

  ///@{
  /// Geometry. Vertices: 3 local coordinates each, plus one float of padding (Embree reads
  /// 16 bytes per vertex). Triangles: 3 vertex ids each, consistently wound, no repeated id.
  std::vector<float> Vertices;
  std::vector<std::uint32_t> Triangles;
  ///@}

  ///@{
  /// Receiving points: their vertex, unit normal (zero where undefined), whether the normal is
  /// defined, and a key from the vertex's world position and the side, on which their rays
  /// depend (so that welded and unwelded copies of a mesh, or a leaf run alone or in a scene,
  /// get the same). SetRayOffset() sets where their rays start: Start (3 local coordinates
  /// each), Offset above the point, and how far from where they are traced hits are near (Near,
  /// see vtkApertureRayScene).
  std::vector<std::uint32_t> PointVertex;
  vtkSmartPointer<vtkFloatArray> Normals;
  std::vector<unsigned char> Valid;
  std::vector<std::uint64_t> Key;
  std::vector<float> Offset;
  std::vector<float> Start;
  std::vector<float> Near;
  ///@}

  /// The receiving point of each corner of Triangles (3 per triangle).
  std::vector<std::uint32_t> CornerPoints;

  /// The receiving point of each input point, or NotOnSurface, Invalid.
  std::vector<vtkIdType> InputPoints;

  /// Whether Normals were computed (the input had none), and so belong in the output.
  bool NormalsComputed = false;

  /**
   * Sets where rays start: Offset = rayOffset × (mean length of the vertex's edges) above the
   * point along its normal, at least far enough to clear single-precision rounding; and moved
   * along the surface toward the middle of its side's triangles by up to Offset, so that a
   * point on a crease or a corner does not start its rays on the planes of the faces beyond it
   * (Start). Points inside a regular fan are not moved along the surface.
   */
  void SetRayOffset(double rayOffset);

  ///@{
  /// Counts for the callers' warnings: receiving input points that are not finite, without a
  /// defined normal, with a given normal against their triangles' winding; input points split.
  vtkIdType NonFinitePoints = 0;
  vtkIdType UndefinedNormals = 0;
  vtkIdType FlippedNormals = 0;
  vtkIdType SplitPoints = 0;
  ///@}

  /// Whether a crease runs across a strip (MakeOutput() then makes the strips triangles).
  bool BreakStrips = false;

private:
  struct Build;
  friend struct Build;

  void Allocate(vtkIdType inputPoints);
  // SetHeightField()'s receiving points, one per grid point (`world`: 3 each).
  void SetGridPoints(vtkImageData* input, const std::vector<double>& world,
    const std::vector<unsigned char>& finite);
  // Mean edge lengths of the vertices (the scale of the ray offsets).
  std::vector<float> EdgeLengths() const;
  // Per receiving point (of `points`), the sum of the unit normals of its triangles (3 each).
  std::vector<double> WindingNormals(vtkIdType points) const;
  // FlippedNormals: given normals against their triangles' winding.
  void CountFlippedNormals();

  // Cell data of MakeOutput() when strips become triangles.
  void BrokenStripData(vtkPolyData* input, vtkPolyData* output) const;

  // For MakeOutput(), when points are split: the receiving point of each corner of the input's
  // polygons and of its strips, in connectivity order; and when strips break, their triangles
  // (strip, then input point and receiving point of each corner: 7 values each).
  std::vector<vtkIdType> PolyCorners, StripCorners, StripTriangles;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSurface.h
