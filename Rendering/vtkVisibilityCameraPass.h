/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityCameraPass.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVisibilityCameraPass
 * @brief   which triangles of a vtkVisibilityScene a camera sees, by OpenGL (private)
 *
 * The camera pass of vertex filtering (Sattler et al. 2004, §4.1): the scene's depth from the
 * camera, with polygon offset, then the candidate triangles drawn against it without writing
 * depth, either each inside its own occlusion query (the paper) or all at once with a fragment
 * shader that marks gl_PrimitiveID in a shader storage buffer after the early depth test.
 * GL state is changed through vtkOpenGLState and restored.
 */

#ifndef vtkVisibilityCameraPass_h
#define vtkVisibilityCameraPass_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkSmartPointer.h"                    // For vtkSmartPointer

#include <cstdint>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkVisibilityScene;
class vtkWindow;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkVisibilityCameraPass
{
public:
  explicit vtkVisibilityCameraPass(vtkVisibilityScene& scene);
  ~vtkVisibilityCameraPass();
  vtkVisibilityCameraPass(const vtkVisibilityCameraPass&) = delete;
  vtkVisibilityCameraPass& operator=(const vtkVisibilityCameraPass&) = delete;

  /**
   * Which of the `candidates` (three point ids each) a camera sees: `matrix` (column-major)
   * takes the scene's local coordinates to clip space, the view is width x height pixels, and
   * the whole scene hides what is behind it. `seen` gets one flag per candidate. With `queries`
   * each candidate is drawn in its own occlusion query (OpenGL 3.3), otherwise all are drawn
   * at once into a shader storage buffer (OpenGL 4.3).
   */
  bool Visible(const float matrix[16], int width, int height,
    const std::vector<std::uint32_t>& candidates, bool queries, std::vector<char>& seen,
    std::string& error);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  // Program, depth texture and framebuffer of the pass, and the candidates uploaded.
  bool Prepare(int width, int height, const std::vector<std::uint32_t>& candidates, bool queries,
    std::string& error);
  // The candidates drawn against the scene's depth: in a query each, or all into the storage
  // buffer.
  void QueryCandidates(std::vector<char>& seen);
  void MarkCandidates(const float matrix[16], std::vector<char>& seen);

  vtkVisibilityScene& Scene;
  vtkSmartPointer<vtkOpenGLBufferObject> Candidates;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkShaderProgram> Program;
  unsigned int Storage = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkVisibilityCameraPass.h
