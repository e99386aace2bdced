/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkLightSphere.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkLightSphere
 * @brief   light directions from a subdivided octahedron, with their solid angles
 *
 * The lightsphere of Sattler, Sarlette and Klein (2004): the 6 vertices of an octahedron
 * (level 0); each further level splits every edge at its midpoint and projects the new vertices
 * onto the unit sphere, giving k = 4·4^level + 2 directions (6, 18, 66, 258, 1026, ...). New
 * directions are appended, so the directions of a level are a prefix of those of the next one,
 * and visibility computed for a coarser level stays valid when the level is raised.
 *
 * Each direction carries a weight: the solid angle of the directions closer to it than to any
 * other (its spherical Voronoi cell). The subdivided octahedron is a Delaunay triangulation of
 * its vertices, so each cell is the spherical polygon through the circumcentres of the triangles
 * around its direction, and its area is summed exactly from spherical triangles. The weights sum
 * to 4π. They are not equal: near the octahedron's vertices the grid is finer, and at level 4
 * the largest cell is twice the smallest. With these weights the clamped cosine max(n·l, 0)
 * integrates to π within 0.08% at level 4, against 1.6% with equal weights 4π/k.
 */

#ifndef vtkLightSphere_h
#define vtkLightSphere_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For std::vector

class vtkDoubleArray;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkLightSphere : public vtkObject
{
public:
  static vtkLightSphere* New();
  vtkTypeMacro(vtkLightSphere, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Highest subdivision level (k = 16386).
   */
  static constexpr int MaximumLevel = 6;

  ///@{
  /**
   * Subdivision level, clamped to [0, MaximumLevel]. Default 2 (k = 66).
   */
  vtkSetClampMacro(Level, int, 0, MaximumLevel);
  vtkGetMacro(Level, int);
  ///@}

  /**
   * Number of directions at a level: 4·4^level + 2.
   */
  static int GetNumberOfDirections(int level);

  /**
   * Number of directions at the current level.
   */
  int GetNumberOfDirections() { return GetNumberOfDirections(this->Level); }

  /**
   * Unit direction j (0 <= j < GetNumberOfDirections()); false when j is out of range.
   */
  bool GetDirection(int j, double direction[3]);

  /**
   * Solid angle (sr) of direction j's Voronoi cell; 0 when j is out of range.
   */
  double GetWeight(int j);

  /**
   * All directions (k tuples of 3) and weights (k values) of the current level, in new arrays
   * named "LightDirections" and "LightWeights" that the caller owns.
   */
  vtkDoubleArray* NewDirections();
  vtkDoubleArray* NewWeights();

protected:
  vtkLightSphere() = default;
  ~vtkLightSphere() override = default;

  // Generates directions and weights for the current level when it has changed.
  void Build();

  int Level = 2;
  int BuiltLevel = -1;
  std::vector<double> Directions; // 3 per direction
  std::vector<double> Weights;

private:
  vtkLightSphere(const vtkLightSphere&) = delete;
  void operator=(const vtkLightSphere&) = delete;
};

#endif
