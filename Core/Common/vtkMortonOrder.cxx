/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkMortonOrder.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkMortonOrder.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numeric>

namespace
{
// Spreads 10 bits to every third bit.
std::uint32_t Spread(std::uint32_t v)
{
  v = (v | (v << 16)) & 0x030000FF;
  v = (v | (v << 8)) & 0x0300F00F;
  v = (v | (v << 4)) & 0x030C30C3;
  return (v | (v << 2)) & 0x09249249;
}
}

//------------------------------------------------------------------------------
void vtkMortonOrder::Bounds(const float* positions, size_t count, float lo[3], float hi[3])
{
  for (int c = 0; c < 3; ++c)
  {
    lo[c] = FLT_MAX;
    hi[c] = -FLT_MAX;
  }
  for (size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const float x = positions[3 * i + c];
      if (std::isfinite(x))
      {
        lo[c] = std::min(lo[c], x);
        hi[c] = std::max(hi[c], x);
      }
    }
  }
}

//------------------------------------------------------------------------------
std::vector<std::uint32_t> vtkMortonOrder::Codes(
  const float* positions, size_t count, const float lo[3], const float hi[3])
{
  std::vector<std::uint32_t> codes(count, 0);
  for (size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      // In double: the span of finite floats can overflow a float (then unit is inf/inf).
      const double x = positions[3 * i + c];
      const double span = static_cast<double>(hi[c]) - lo[c];
      const double unit = span > 0.0 && std::isfinite(x) ? (x - lo[c]) / span : 0.0;
      const double clamped = unit > 0.0 ? std::min(unit, 1.0) : 0.0;
      codes[i] |= Spread(static_cast<std::uint32_t>(clamped * 1023.0)) << c;
    }
  }
  return codes;
}

//------------------------------------------------------------------------------
std::vector<std::uint32_t> vtkMortonOrder::Order(const float* positions, size_t count)
{
  float lo[3], hi[3];
  Bounds(positions, count, lo, hi);
  const std::vector<std::uint32_t> codes = Codes(positions, count, lo, hi);
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
    [&codes](std::uint32_t a, std::uint32_t b) { return codes[a] < codes[b]; });
  return order;
}
