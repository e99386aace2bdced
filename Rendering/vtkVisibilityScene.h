/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityScene.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVisibilityScene
 * @brief   vtkOcclusionQueryVisibility's scene on the GPU, and what its GL passes share (private)
 *
 * Holds the scene (points in local coordinates, triangles) in buffer objects of one window's
 * context and draws its depth through a matrix, pushed back by a polygon offset. Set() uploads
 * only what differs from what is on the GPU already: a deforming mesh re-uploads its points,
 * not its triangles.
 *
 * The passes built on it (vtkVisibilityMatrixPasses along light directions,
 * vtkVisibilityCameraPass from the camera) share its helpers: programs whose vertex shader takes
 * the scene's points, depth render targets, batched occlusion queries, and PassState, the GL
 * state of a depth pass, restored when it goes.
 *
 * The passes make their GL objects in the scene's window. The owner releases the passes'
 * resources, then the scene's (ReleaseGraphicsResources()), while the window's context exists,
 * and before the scene moves to another window; the destructors do it too.
 */

#ifndef vtkVisibilityScene_h
#define vtkVisibilityScene_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkOpenGLState.h"                     // For PassState's scoped state
#include "vtkSmartPointer.h"                    // For vtkSmartPointer
#include "vtkType.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkVisibilityScene
{
public:
  vtkVisibilityScene() = default;
  ~vtkVisibilityScene();
  vtkVisibilityScene(const vtkVisibilityScene&) = delete;
  vtkVisibilityScene& operator=(const vtkVisibilityScene&) = delete;

  /**
   * What the window's OpenGL lacks for a pass (storage: the shader storage buffers of
   * OpenGL 4.3; otherwise the GL_ANY_SAMPLES_PASSED queries of OpenGL 3.3); empty if nothing.
   * The window's context must be current.
   */
  static std::string Missing(bool storage);

  /**
   * Uploads a scene: points (x, y, z each) and triangles (three point ids each), drawn with
   * glPolygonOffset(factor, units). Points and triangles equal to those already uploaded are not
   * uploaded again. The owner releases the passes' and the scene's resources in the last window
   * before setting a scene in another.
   */
  bool Set(vtkOpenGLRenderWindow* window, const std::vector<float>& points,
    const std::vector<std::uint32_t>& triangles, float factor, float units, std::string& error);

  /**
   * The window the scene was last set in (nullptr once released).
   */
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }

  /**
   * For the passes: makes the scene's context current; false, with `error`, without a scene.
   */
  bool MakeCurrent(std::string& error);

  /**
   * The polygon offset of its depth.
   */
  float GetOffsetFactor() const { return this->OffsetFactor; }
  float GetOffsetUnits() const { return this->OffsetUnits; }

  /**
   * Bytes of points and triangles the last Set() uploaded.
   */
  vtkIdType GetUploadedBytes() const { return this->UploadedBytes; }

  /**
   * Clears the bound depth target and draws the scene's depth into it through `matrix`
   * (column-major, to clip space), pushed back by the polygon offset. The depth program and its
   * vertex array (GetDepthVAO()) stay current, to draw points or triangles against the depth.
   */
  void DrawDepth(const float matrix[16]);
  vtkOpenGLVertexArrayObject* GetDepthVAO() const;

  /**
   * Draws every triangle through `vao` (a vertex array of the current program).
   */
  void DrawTriangles(vtkOpenGLVertexArrayObject* vao);

  /**
   * The depth pass's vertex shader (the scene's points placed by the uniform clipMatrix) in GLSL
   * 4.30, for programs whose fragment shader needs that version.
   */
  static std::string PointsVS430();

  /**
   * Compiles a program whose vertex shader takes the scene's points as vertexMC, with its vertex
   * array, unless `program` is set already. Both are kept only once complete, so that a failure
   * is met again, not skipped, next time.
   */
  bool ReadyProgram(vtkSmartPointer<vtkShaderProgram>& program,
    vtkSmartPointer<vtkOpenGLVertexArrayObject>& vao, const char* vs, const char* fs,
    const char* what, std::string& error);

  /**
   * Makes `texture` a width x height float depth texture, the only attachment of `framebuffer`
   * (both created when missing), unless it already is; false with `error` otherwise, leaving no
   * texture, so that the next call tries again.
   */
  bool DepthTarget(vtkSmartPointer<vtkTextureObject>& texture,
    vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, int width, int height,
    const char* what, std::string& error);

  /**
   * Makes `framebuffer` (created when missing) with the attachments attach() adds while it is
   * bound; false with `error` when it is incomplete.
   */
  bool Attach(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
    const std::function<void(vtkOpenGLFramebufferObject*)>& attach, const char* what,
    std::string& error);

  /**
   * A new texture of the window in place of `texture` (whose resources are released): texels
   * read as they are (nearest, clamped).
   */
  void NewTexture(vtkSmartPointer<vtkTextureObject>& texture);

  /**
   * Issues one occlusion query per item (draw(i) draws item i), a batch ahead of the reads, and
   * calls passed(i) for those with samples passed.
   */
  void QueryEach(size_t count, const std::function<void(size_t)>& draw,
    const std::function<void(size_t)>& passed);

  /**
   * Storage buffers: `buffer` (made when 0) gets `bytes` bytes, from `data` (undefined when
   * null), and stays bound to GL_SHADER_STORAGE_BUFFER; ReadStorage() reads its first bytes.
   */
  static void ResizeStorage(unsigned int& buffer, size_t bytes, const void* data);
  static void ReadStorage(unsigned int buffer, size_t bytes, void* data);

  /**
   * The state of a depth pass (depth test, no culling, blending, scissors or colour), restored
   * with the polygon offset when the object goes.
   */
  struct PassState
  {
    explicit PassState(vtkOpenGLState* state);
    ~PassState();

    vtkOpenGLState::ScopedglViewport Viewport;
    vtkOpenGLState::ScopedglDepthMask DepthMask;
    vtkOpenGLState::ScopedglColorMask ColorMask;
    vtkOpenGLState::ScopedglDepthFunc DepthFunc;
    vtkOpenGLState::ScopedglEnableDisable DepthTest, CullFace, Blend, Scissor, Offset;
    float Factor = 0.0f, Units = 0.0f;
  };

  /**
   * Releases what was made in `window` (nothing for another window). GL objects die with a
   * context that is gone; only a live one is asked to delete them.
   */
  void ReleaseGraphicsResources(vtkWindow* window);

  /**
   * Makes the window's context current if it still has one; false when it is gone (and the GL
   * objects made in it with it).
   */
  static bool MakeCurrentIfLive(vtkOpenGLRenderWindow* window);

private:
  bool Upload(const std::vector<float>& points, const std::vector<std::uint32_t>& triangles,
    std::string& error);

  vtkOpenGLRenderWindow* Window = nullptr;
  bool Ready = false;
  vtkSmartPointer<vtkOpenGLBufferObject> Points;
  vtkSmartPointer<vtkOpenGLBufferObject> Triangles;
  vtkSmartPointer<vtkShaderProgram> DepthProgram;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> DepthVAO;
  // What is on the GPU, to upload only what changes.
  std::vector<float> UploadedPoints;
  std::vector<std::uint32_t> UploadedTriangles;
  vtkIdType UploadedBytes = 0;
  std::vector<unsigned int> Queries;
  float OffsetFactor = 1.0f;
  float OffsetUnits = 1.0f;
};

#endif
// VTK-HeaderTest-Exclude: vtkVisibilityScene.h
