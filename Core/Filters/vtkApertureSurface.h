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
 * What Embree and the per-point ray loops need of the polygons and strips of a vtkPolyData, or
 * of a vtkImageData height field, the same for every caster. This class holds the data; one
 * class for each job fills or reads it:
 *
 * - vtkApertureMeshSurface builds it from a polydata, vtkApertureGridSurface from a height
 *   field, vtkApertureSceneSurfaces the receivers and occluders of a scene around one origin;
 * - vtkApertureRayOffsets sets where each point's rays start;
 * - vtkApertureSurfaceOutput writes the output (points split at creases) and its arrays.
 *
 * A polydata becomes a surface in five steps:
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
 *    as vtkPolyDataNormals does (vtkApertureSurfaceOutput).
 *
 * Geometry is stored relative to a local origin in single precision, so that large coordinates
 * keep their precision. Triangles with a non-finite vertex are left out.
 *
 * @sa vtkApertureMeshSurface vtkApertureGridSurface vtkApertureSceneSurfaces
 */

#ifndef vtkApertureSurface_h
#define vtkApertureSurface_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkDataSet;
class vtkFloatArray;
class vtkPoints;
class vtkPolyData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureSurface
{
public:
  ///@{
  /**
   * Grows bounds (xmin, xmax, ymin, ymax, zmin, zmax), which InitializeBounds() makes empty, by
   * the finite points of a polydata, so that all surfaces of a scene can share one local origin
   * (vtkApertureGridSurface::ExpandBounds() for height fields).
   */
  static void InitializeBounds(double bounds[6]);
  static void ExpandBounds(vtkPolyData* input, double bounds[6]);
  ///@}

  /**
   * The points' coordinates (3 each), read in their own type (float, double, integers) through
   * vtkArrayDispatch; empty without points.
   */
  static void WorldPoints(vtkPoints* points, std::vector<double>& world);

  /**
   * The local origin of a scene: the centre of its bounds rounded to a sixteenth of the power of
   * two at or below their largest side (0 for empty bounds), so that a surface that moves a
   * little keeps its local coordinates, and with them its unmoved rays (vtkApertureHistory).
   */
  static void OriginOf(const double bounds[6], double origin[3]);

  /**
   * The point normals of a dataset when they have 3 components and one tuple per point (the
   * surface then keeps them), else nullptr.
   */
  static vtkDataArray* GivenNormals(vtkDataSet* input);

  /**
   * The key of a receiving point: its world position (+0 and -0 alike) and its side's ordinal.
   */
  static std::uint64_t PointKey(const double p[3], unsigned int side);

  /**
   * The key of a receiving point by the id of its vertex's first input point (or that point's
   * global id) and its side's ordinal: it stays with the point when the point moves.
   */
  static std::uint64_t IdKey(vtkIdType id, unsigned int side);
  /**
   * Keys every receiving point by IdKey(): the global id of its vertex's first input point
   * (`globalIds`, one value per input point), or that point's index when `globalIds` is nullptr.
   */
  void KeyByPointIds(vtkDataArray* globalIds);
  /**
   * Points whose coordinates go beyond this, or are not finite, cannot be traced: Embree takes
   * ray origins within ±1.8e18, and a ray starts a few edge lengths from its point.
   */
  static constexpr double LargestCoordinate = 1e16;
  /// Whether a point's three coordinates are finite and within ±LargestCoordinate.
  static bool IsUsable(const double p[3]);

  /// More than this many points, or a third as many triangle corners, cannot be numbered.
  static constexpr std::uint32_t NoVertex = 0xFFFFFFFFu;

  /**
   * Empties the surface for an input of `inputPoints` points (all NotOnSurface).
   */
  void Reset(vtkIdType inputPoints);
  /// Room for `points` receiving points, so that adding them copies nothing.
  void Reserve(vtkIdType points);

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
  /// get the same). vtkApertureRayOffsets sets where their rays start: Start (3 local
  /// coordinates each), Offset above the point, and how far from where they are traced hits are
  /// near (Near).
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

  ///@{
  /// Counts for the callers' warnings: receiving input points not usable (IsUsable()), without a
  /// defined normal, with a given normal against their triangles' winding; input points split.
  vtkIdType UnusablePoints = 0;
  vtkIdType UndefinedNormals = 0;
  vtkIdType FlippedNormals = 0;
  vtkIdType SplitPoints = 0;
  ///@}

  /**
   * Sets SplitPoints: the input points with a split corner (PolySplits, StripSplits).
   */
  void CountSplitPoints();

  /// Whether a crease runs across a strip (the output then makes the strips triangles).
  bool BreakStrips = false;

  /// A corner of an input cell whose receiving point is not its input point's (InputPoints):
  /// its index in the cell array's connectivity, its input point, its receiving point.
  struct SplitCorner
  {
    vtkIdType Corner;
    vtkIdType InputPoint;
    vtkIdType Point;
  };

  ///@{
  /// For vtkApertureSurfaceOutput: the split corners of the input's polygons and of its strips,
  /// in connectivity order (only these, so that a large surface with a few creases does not keep
  /// a receiving point for every corner); and when strips break, their triangles (strip, then
  /// input point and receiving point of each corner: 7 values each).
  std::vector<SplitCorner> PolySplits, StripSplits;
  std::vector<vtkIdType> StripTriangles;
  ///@}

  /**
   * Per receiving point (of the first `points`), the sum of the unit normals of its triangles
   * (3 each).
   */
  std::vector<double> WindingNormals(vtkIdType points) const;

  /**
   * Sets FlippedNormals: given normals against their triangles' winding.
   */
  void CountFlippedNormals();

  /**
   * After a polydata of `input` followed by more points and cells (another piece's ghost cells:
   * its points after the input's, its polygons after the input's polygons, its strips after its
   * strips) was built: maps only `input`'s points and corners to receiving points, and counts
   * only its points. The other receiving points stay, with their rays.
   */
  void KeepInputs(vtkPolyData* input);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSurface.h
