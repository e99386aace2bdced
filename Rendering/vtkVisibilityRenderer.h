/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityRenderer.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVisibilityRenderer
 * @brief   OpenGL passes of vtkOcclusionQueryVisibility (private)
 *
 * Holds a scene (points in local coordinates, triangles) on the GPU and answers, for one light
 * direction at a time, which of the first NumberOfReceivers points are visible from it:
 *
 * - every direction starts with a depth pass: the triangles rendered orthographically along
 *   the direction into a square depth texture, with polygon offset;
 * - OcclusionQuery then draws each receiver as a point inside its own GL_ANY_SAMPLES_PASSED
 *   query (Sattler et al. 2004), issuing a batch of queries before reading the previous batch;
 * - DepthCompare renders a direction and its opposite in one pass (the nearest and the farthest
 *   surface of each texel, by GL_MIN and GL_MAX blending, offset as glPolygonOffset would),
 *   then draws all receivers at once: the vertex shader projects each one, makes the occlusion
 *   pass's depth test against the texel it falls on, for both directions, and sets its bits in a
 *   shader storage buffer, which is read back once per batch of directions.
 *
 * Both can test a subset of the receivers (vertex filtering). A third pass tells which of a list
 * of triangles a camera sees (Sattler et al. 2004, §4.1): the scene's depth from the camera, with
 * polygon offset, then the candidates drawn against it without writing depth, either each inside
 * its own occlusion query (the paper) or all at once with a fragment shader that marks
 * gl_PrimitiveID in a shader storage buffer after the early depth test.
 *
 * SetScene() uploads only what differs from the scene already on the GPU: a deforming mesh
 * re-uploads its points, not its triangles.
 *
 * GL state is changed through vtkOpenGLState and restored. The owner releases the resources
 * (ReleaseGraphicsResources()) while the window's context exists; the destructor does it too.
 */

#ifndef vtkVisibilityRenderer_h
#define vtkVisibilityRenderer_h

#include "vtkApertureLightingModule.h" // For export macro
#include "vtkSmartPointer.h"           // For vtkSmartPointer
#include "vtkType.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKAPERTURELIGHTING_EXPORT vtkVisibilityRenderer
{
public:
  vtkVisibilityRenderer();
  ~vtkVisibilityRenderer();
  vtkVisibilityRenderer(const vtkVisibilityRenderer&) = delete;
  vtkVisibilityRenderer& operator=(const vtkVisibilityRenderer&) = delete;

  /// One bit per receiver, 64 receivers per word.
  using Bits = std::vector<std::uint64_t>;

  /**
   * What the window's OpenGL lacks for a backend (depthCompare: the shader storage buffers of
   * OpenGL 4.3; otherwise the GL_ANY_SAMPLES_PASSED queries of OpenGL 3.3); empty if nothing.
   * The window's context must be current.
   */
  static std::string Missing(bool depthCompare);

  /**
   * Uploads a scene: points (x, y, z each; local coordinates within `radius` of the origin)
   * and triangles (three point ids each). The first `receivers` points are the ones tested.
   * The depth texture is resolution x resolution, rendered with glPolygonOffset(factor, units).
   * Points and triangles equal to those already uploaded are not uploaded again.
   */
  bool SetScene(vtkOpenGLRenderWindow* window, const std::vector<float>& points,
    const std::vector<std::uint32_t>& triangles, vtkIdType receivers, double radius, int resolution,
    float factor, float units, std::string& error);

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
   * Which of the `candidates` (three point ids each) a camera sees: `matrix` (column-major)
   * takes the scene's local coordinates to clip space, the view is width x height pixels, and
   * the whole scene hides what is behind it. `seen` gets one flag per candidate. With `queries`
   * each candidate is drawn in its own occlusion query (OpenGL 3.3), otherwise all are drawn
   * at once into a shader storage buffer (OpenGL 4.3).
   */
  bool ViewVisible(const float matrix[16], int width, int height,
    const std::vector<std::uint32_t>& candidates, bool queries, std::vector<char>& seen,
    std::string& error);

  /**
   * Depth passes rendered since the scene was set.
   */
  int GetNumberOfDepthPasses() const { return this->DepthPasses; }

  /**
   * Bytes of points and triangles the last SetScene() uploaded.
   */
  vtkIdType GetUploadedBytes() const { return this->UploadedBytes; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  // Renders the depth pass for a direction; `matrix` gets its column-major projection.
  void RenderDepth(const std::array<double, 3>& direction, float matrix[16]);
  // Clears the bound depth target and draws the scene's depth into it through `matrix`
  // (column-major, to clip space), pushed back by the polygon offset.
  void DrawSceneDepth(const float matrix[16]);
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
  // Program, depth texture and framebuffer of the camera pass.
  bool PrepareView(int width, int height, bool queries, std::string& error);
  // Compiles a program whose vertex shader takes the scene's points as vertexMC, with its vertex
  // array; unless `program` is set already.
  bool ReadyProgram(vtkSmartPointer<vtkShaderProgram>& program,
    vtkSmartPointer<vtkOpenGLVertexArrayObject>& vao, const char* vs, const char* fs,
    const char* what, std::string& error);
  // Issues one occlusion query per item (draw(i) draws item i), a batch ahead of the reads,
  // and calls passed(i) for those with samples passed.
  void QueryEach(size_t count, const std::function<void(size_t)>& draw,
    const std::function<void(size_t)>& passed);

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkSmartPointer<vtkOpenGLBufferObject> Points;
  vtkSmartPointer<vtkOpenGLBufferObject> Triangles;
  vtkSmartPointer<vtkOpenGLBufferObject> Subset;
  vtkSmartPointer<vtkOpenGLBufferObject> Candidates;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> ViewVAO;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ViewFramebuffer;
  vtkSmartPointer<vtkTextureObject> ViewDepth;
  vtkSmartPointer<vtkShaderProgram> ViewProgram;
  unsigned int ViewStorage = 0;
  // What is on the GPU, to upload only what changes.
  std::vector<float> UploadedPoints;
  std::vector<std::uint32_t> UploadedTriangles;
  vtkIdType UploadedBytes = 0;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> DepthVAO;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> PairVAO;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> CompareVAO;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> PairFramebuffer;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkTextureObject> Nearest;
  vtkSmartPointer<vtkTextureObject> Farthest;
  vtkSmartPointer<vtkShaderProgram> DepthProgram;
  vtkSmartPointer<vtkShaderProgram> PairProgram;
  vtkSmartPointer<vtkShaderProgram> CompareProgram;
  std::vector<unsigned int> Queries;
  unsigned int Storage = 0;
  vtkIdType NumberOfTriangles = 0;
  vtkIdType NumberOfReceivers = 0;
  double Radius = 1.0;
  int Resolution = 1024;
  float OffsetFactor = 1.0f;
  float OffsetUnits = 1.0f;
  int DepthPasses = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkVisibilityRenderer.h
