/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkRayCastVisibility.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkRayCastVisibility
 * @brief   the rays of vtkLightSphereVisibility (private)
 *
 * One occlusion ray per receiving point and lightsphere direction, cast with the shared
 * ray-casting core (vtkApertureRayPacket: offsets, contact and self-hit rules), for the
 * directions above the point's tangent plane. Points are traced in Morton order, 16 neighbours
 * to a packet looking the same way, in blocks of 64 so that no two threads share a word of the
 * bit sets. The Embree scene lasts until SetScene() is called again, so that vertex filtering's
 * later updates reuse it.
 */

#ifndef vtkRayCastVisibility_h
#define vtkRayCastVisibility_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkType.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkApertureRayScene;
class vtkApertureSurface;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkRayCastVisibility
{
public:
  vtkRayCastVisibility();
  ~vtkRayCastVisibility();
  vtkRayCastVisibility(const vtkRayCastVisibility&) = delete;
  vtkRayCastVisibility& operator=(const vtkRayCastVisibility&) = delete;

  /// One bit per receiving point, 64 to a word.
  using Bits = std::vector<std::uint64_t>;

  /**
   * Builds the Embree scene of the receivers and occluders (which must outlive it).
   */
  bool SetScene(const vtkApertureSurface& receivers,
    const std::vector<vtkApertureSurface>& occluders, std::string& error);

  /**
   * Forgets the scene (the geometry changed).
   */
  void ReleaseScene();

  /**
   * Whether a scene is set.
   */
  bool HasScene() const { return this->Scene != nullptr; }

  /**
   * Visibility of the receiving points `points` from each direction (unit vectors toward the
   * light): one bit set over all receiving points per direction, bits of other points 0.
   * `progress(done)` is called between chunks of directions; returning false stops (the
   * result then holds only the directions done). False with an error if Embree failed.
   */
  bool Cast(const std::vector<std::array<double, 3>>& directions,
    const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
    const std::function<bool(size_t done)>& progress, std::string& error);

private:
  const vtkApertureSurface* Receivers = nullptr;
  std::unique_ptr<vtkApertureRayScene> Scene;
};

#endif
// VTK-HeaderTest-Exclude: vtkRayCastVisibility.h
