/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkRayCastVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkRayCastVisibility.h"

#include "vtkApertureRayPacket.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSMP.h"
#include "vtkApertureSurface.h"
#include "vtkMortonOrder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace
{
using Bits = vtkRayCastVisibility::Bits;
constexpr int Lanes = vtkApertureRayPacket::Lanes;

// Directions handled between two progress events.
constexpr size_t Chunk = 8;

// The points in Morton order of their positions: neighbours together.
std::vector<std::uint32_t> MortonOrder(
  const vtkApertureSurface& surface, const std::vector<std::uint32_t>& points)
{
  std::vector<float> positions(3 * points.size());
  for (size_t i = 0; i < points.size(); ++i)
  {
    std::copy_n(surface.GetPosition(points[i]), 3, &positions[3 * i]);
  }
  std::vector<std::uint32_t> order = vtkMortonOrder::Order(positions.data(), points.size());
  for (std::uint32_t& i : order)
  {
    i = points[i];
  }
  return order;
}

// Casts, for blocks of 64 ordered points, one ray per point and direction; bit i of a block's
// word is the visibility of the block's i-th point.
class CastDirections
{
public:
  CastDirections(const vtkApertureSurface& surface, const std::vector<std::uint32_t>& order,
    const vtkApertureRayScene& scene, const std::vector<std::array<double, 3>>& directions,
    std::vector<Bits>& visible)
    : Surface(surface)
    , Order(order)
    , Scene(scene)
    , Directions(directions)
    , Visible(visible)
  {
  }

  void operator()(vtkIdType beginBlock, vtkIdType endBlock) const
  {
    // A packet is 16 neighbouring points looking the same way.
    vtkApertureRayPacket packet(this->Scene, this->Surface, true);
    const vtkIdType n = static_cast<vtkIdType>(this->Order.size());
    const float infinity = std::numeric_limits<float>::infinity();
    for (vtkIdType block = beginBlock; block < endBlock; ++block)
    {
      for (size_t j = 0; j < this->Directions.size(); ++j)
      {
        const float l[3] = { static_cast<float>(this->Directions[j][0]),
          static_cast<float>(this->Directions[j][1]), static_cast<float>(this->Directions[j][2]) };
        std::uint64_t word = 0;
        for (vtkIdType first = 64 * block; first < std::min(n, 64 * block + 64); first += Lanes)
        {
          for (int lane = 0; lane < Lanes; ++lane)
          {
            // Directions below a point's tangent plane are hidden by its own surface.
            const vtkIdType id =
              first + lane < n ? static_cast<vtkIdType>(this->Order[first + lane]) : -1;
            const float* nrm = id >= 0 ? this->Surface.GetNormal(id) : nullptr;
            if (id >= 0 && this->Surface.Valid[id] &&
              nrm[0] * l[0] + nrm[1] * l[1] + nrm[2] * l[2] > 0.0f)
            {
              packet.Set(lane, id, l, infinity);
            }
            else
            {
              packet.Clear(lane);
            }
          }
          packet.Trace();
          for (int lane = 0; lane < Lanes; ++lane)
          {
            word |= packet.Visible(lane) ? std::uint64_t(1) << ((first + lane) % 64) : 0;
          }
        }
        this->Visible[j][block] = word;
      }
    }
  }

private:
  const vtkApertureSurface& Surface;
  const std::vector<std::uint32_t>& Order;
  const vtkApertureRayScene& Scene;
  const std::vector<std::array<double, 3>>& Directions;
  std::vector<Bits>& Visible;
};
}

//------------------------------------------------------------------------------
vtkRayCastVisibility::vtkRayCastVisibility() = default;

//------------------------------------------------------------------------------
vtkRayCastVisibility::~vtkRayCastVisibility() = default;

//------------------------------------------------------------------------------
bool vtkRayCastVisibility::SetScene(const vtkApertureSurface& receivers,
  const std::vector<vtkApertureSurface>& occluders, std::string& error)
{
  this->Receivers = &receivers;
  this->Scene.reset(new vtkApertureRayScene);
  if (!this->Scene->Build(receivers, occluders))
  {
    error = "Embree failed: " + this->Scene->GetError();
    this->Scene.reset();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRayCastVisibility::ReleaseScene()
{
  this->Scene.reset();
  this->Receivers = nullptr;
}

//------------------------------------------------------------------------------
bool vtkRayCastVisibility::Cast(const std::vector<std::array<double, 3>>& directions,
  const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
  const std::function<bool(size_t done)>& progress, std::string& error)
{
  const vtkApertureSurface& receivers = *this->Receivers;
  const size_t words = (receivers.GetNumberOfPoints() + 63) / 64;
  visible.assign(directions.size(), Bits(words, 0));
  const std::vector<std::uint32_t> order = MortonOrder(receivers, points);
  const vtkIdType blocks = (static_cast<vtkIdType>(order.size()) + 63) / 64;
  for (size_t begin = 0; begin < directions.size(); begin += Chunk)
  {
    const std::vector<std::array<double, 3>> chunk(
      directions.begin() + begin, directions.begin() + std::min(directions.size(), begin + Chunk));
    std::vector<Bits> ordered(chunk.size(), Bits(blocks, 0));
    vtkApertureSMP::For(
      0, blocks, 4, CastDirections(receivers, order, *this->Scene, chunk, ordered));
    // From Morton order back to receiving points.
    for (size_t j = 0; j < chunk.size(); ++j)
    {
      for (size_t i = 0; i < order.size(); ++i)
      {
        if ((ordered[j][i / 64] >> (i % 64)) & 1u)
        {
          visible[begin + j][order[i] / 64] |= std::uint64_t(1) << (order[i] % 64);
        }
      }
    }
    if (progress && !progress(begin + chunk.size()))
    {
      break;
    }
  }
  error = this->Scene->GetError();
  if (!error.empty())
  {
    error = "Embree failed while tracing: " + error;
    return false;
  }
  return true;
}
