/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityMatrixPasses.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVisibilityMatrixPasses
 * @brief   the visibility matrix of vtkOcclusionQueryVisibility by OpenGL (private)
 *
 * Tells, for one light direction at a time, which of the first NumberOfReceivers points of a
 * vtkVisibilityScene are visible from it (a row of the visibility matrix):
 *
 * - OcclusionQuery renders the scene's depth orthographically along the direction into a square
 *   depth texture, with polygon offset, then draws each receiver as a point inside its own
 *   GL_ANY_SAMPLES_PASSED query (Sattler et al. 2004), issuing a batch of queries before
 *   reading the previous batch;
 * - DepthCompare renders a direction and its opposite in one pass (the nearest and the farthest
 *   surface of each texel, by GL_MIN and GL_MAX blending, offset as glPolygonOffset would),
 *   then draws all receivers at once: the vertex shader projects each one, makes the occlusion
 *   pass's depth test against the texel it falls on, for both directions, and sets its bits in a
 *   shader storage buffer, which is read back once per batch of directions.
 *
 * Both can test a subset of the receivers (vertex filtering). GL state is changed through
 * vtkOpenGLState and restored.
 */

#ifndef vtkVisibilityMatrixPasses_h
#define vtkVisibilityMatrixPasses_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkSmartPointer.h"                    // For vtkSmartPointer
#include "vtkType.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkVisibilityScene;
class vtkWindow;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkVisibilityMatrixPasses
{
public:
  explicit vtkVisibilityMatrixPasses(vtkVisibilityScene& scene);
  ~vtkVisibilityMatrixPasses();
  vtkVisibilityMatrixPasses(const vtkVisibilityMatrixPasses&) = delete;
  vtkVisibilityMatrixPasses& operator=(const vtkVisibilityMatrixPasses&) = delete;

  /// One bit per receiver, 64 receivers per word.
  using Bits = std::vector<std::uint64_t>;

  /**
   * The receivers (the scene's first `receivers` points, all within `radius` of the origin) and
   * the light-view depth texture's side; the depth-pass count starts again.
   */
  bool SetReceivers(vtkIdType receivers, double radius, int resolution, std::string& error);

  /**
   * Visibility of the receivers from each direction (unit vectors toward the light), one bit set
   * of receivers per direction, by occlusion queries or by depth comparison in a shader.
   * DepthCompare reports the directions done after each batch to `progress`, and stops (false,
   * error "stopped") when it returns false. With `subset` (receiver ids), only those receivers
   * are tested; the others' bits stay 0.
   */
  bool OcclusionQuery(const std::vector<std::array<double, 3>>& directions,
    std::vector<Bits>& visible, std::string& error,
    const std::vector<std::uint32_t>* subset = nullptr);
  bool DepthCompare(const std::vector<std::array<double, 3>>& directions,
    std::vector<Bits>& visible, std::string& error,
    const std::function<bool(size_t done)>& progress = nullptr,
    const std::vector<std::uint32_t>* subset = nullptr);

  /**
   * Depth passes rendered since SetReceivers().
   */
  int GetNumberOfDepthPasses() const { return this->DepthPasses; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  // Shaders, textures and framebuffer of DepthCompare's paired depth pass.
  bool PreparePairs(std::string& error);
  // DepthCompare's steps: the storage buffer (`words` per slot) and the subset's indices; a
  // batch of direction pairs drawn and tested, each direction into a slot (returned with it);
  // the nearest and farthest surfaces along one direction; every receiver tested against them
  // into its slot and its opposite's; the slots read back into `results`.
  bool PrepareCompare(const std::vector<std::uint32_t>* subset, int words, std::string& error);
  std::vector<std::pair<size_t, int>> CompareBatchOfPairs(
    const std::vector<std::array<double, 3>>& directions,
    const std::vector<std::pair<size_t, long>>& batch, int words,
    const std::vector<std::uint32_t>* subset);
  void DrawNearestFarthest(const float matrix[16]);
  void CompareReceivers(const float matrix[16], int slot, int opposite, int words,
    const std::vector<std::uint32_t>* subset);
  void ReadSlots(
    const std::vector<std::pair<size_t, int>>& slotOf, int words, std::vector<Bits>& results);

  vtkVisibilityScene& Scene;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkOpenGLBufferObject> Subset;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> PairVAO;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> CompareVAO;
  vtkSmartPointer<vtkOpenGLFramebufferObject> PairFramebuffer;
  vtkSmartPointer<vtkTextureObject> Nearest;
  vtkSmartPointer<vtkTextureObject> Farthest;
  vtkSmartPointer<vtkShaderProgram> PairProgram;
  vtkSmartPointer<vtkShaderProgram> CompareProgram;
  unsigned int Storage = 0;
  vtkIdType NumberOfReceivers = 0;
  double Radius = 1.0;
  int Resolution = 1024;
  int DepthPasses = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkVisibilityMatrixPasses.h
