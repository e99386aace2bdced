/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkMortonOrder.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkMortonOrder
 * @brief   Morton (Z-order) codes: sorting by them puts neighbours together (private)
 *
 * Used where work on neighbours together pays: rays of a packet that start close together
 * (vtkRayCastVisibility), triangles drawn together that share vertices and screen tiles (the
 * OpenGL visibility passes).
 */

#ifndef vtkMortonOrder_h
#define vtkMortonOrder_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include <cstddef>
#include <cstdint>
#include <vector>

class VTKAPERTURELIGHTINGCORE_EXPORT vtkMortonOrder
{
public:
  /**
   * 30-bit codes of `count` positions (3 floats each) within the bounds lo, hi (positions
   * outside, or not finite, are clamped to them).
   */
  static std::vector<std::uint32_t> Codes(
    const float* positions, size_t count, const float lo[3], const float hi[3]);

  /**
   * The bounds of the finite ones of `count` positions.
   */
  static void Bounds(const float* positions, size_t count, float lo[3], float hi[3]);

  /**
   * The permutation that sorts `count` positions by their codes within their own bounds.
   */
  static std::vector<std::uint32_t> Order(const float* positions, size_t count);
};

#endif
// VTK-HeaderTest-Exclude: vtkMortonOrder.h
