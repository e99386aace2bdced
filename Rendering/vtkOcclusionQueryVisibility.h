/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkOcclusionQueryVisibility.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkOcclusionQueryVisibility
 * @brief   per-vertex visibility of a lightsphere of directions (Sattler et al. 2004)
 *
 * For each direction l_j of a vtkLightSphere (level 0 to 4: k = 6 to 1026) and each point i of
 * the input, whether the point sees the far-away sky in that direction: the direction is above
 * the point's tangent plane (n_i · l_j > 0) and nothing blocks it. The result is the paper's
 * visibility matrix, stored as point data:
 *
 * - `Visibility` (float, k components): M_ij = max(n_i · l_j, 0) when point i sees direction j,
 *   else 0, so that the irradiance from an environment of radiance L_j is Σ_j M_ij L_j w_j;
 * - `VisibilityBits` (optional, a vtkBitArray of k components): the raw visibility, 32 times
 *   smaller than `Visibility`;
 * - `VisibilityComputed` (unsigned char, with vertex filtering only): 1 where the point has its
 *   visibility, 0 where no triangle of it has been seen yet;
 * - field data `LightDirections` (k × 3) and `LightWeights` (k solid angles, summing to 4π).
 *
 * The output is the input with these arrays added (and `Normals` when the input had none); the
 * input is never modified. The surface is taken as vtkAperturePrecompute takes it: points at the
 * same position welded, creases above FeatureAngle splitting normals (and the output's points,
 * where the input shares one across a crease), and for RAY_CAST its contact and self-hit rules.
 * Input port 1 takes occluders (repeatable): polydata that cast shadows but get no output. The
 * settings and outputs shared with the ray-cast filter of the core, vtkLightSphereVisibility,
 * are its superclass's.
 *
 * Backends:
 * - OCCLUSION_QUERY, the paper's method: per direction, an orthographic depth render with
 *   polygon offset, then every point drawn inside its own GL_ANY_SAMPLES_PASSED occlusion query,
 *   queries issued in batches and read asynchronously;
 * - DEPTH_COMPARE (default), the fast path: one render for a direction and its opposite (the
 *   nearest and the farthest surface of each texel, offset as the polygon offset would), then one
 *   draw of all points whose vertex shader makes the same depth test for both and sets each
 *   point's bits in a shader storage buffer (OpenGL 4.3);
 * - RAY_CAST: Embree rays from each point (offset along its normal by RayOffset times its mean
 *   edge length, as vtkAperturePrecompute casts them), for machines without OpenGL and as the
 *   reference: vtkLightSphereVisibility's computation, which needs neither OpenGL nor this
 *   module.
 *
 * The OpenGL backends use the render window given to SetRenderWindow() (sharing its context),
 * or else their own off-screen window. The directions of a level are a prefix of those of the
 * next level, so raising the level on an input already computed only renders the new directions
 * (GetNumberOfDepthPasses() counts what the last update rendered).
 *
 * Dynamic scenes (Sattler et al. 2004, §4 and §6):
 * - when the input or an occluder changes (a deforming mesh, objects moving relative to each
 *   other), the next update recomputes; the GPU gets only what changed (a deforming mesh's
 *   points, not its triangles: GetUploadedBytes());
 * - vertex filtering (VertexFilteringOn() with SetViewRenderer()): the filter keeps the list U
 *   of receiver triangles the camera has not seen yet. Each update renders the scene's depth from
 *   the renderer's camera and tests every triangle of U against it; those now seen leave U, and
 *   their three points get their visibility (triangles, not points, so that no visible triangle
 *   has a corner without visibility). Points of triangles never seen have zero visibility. When
 *   U is smaller than FilteringThreshold of all triangles, the rest is computed and filtering
 *   stops until the geometry changes. A camera move alone does not modify this filter: call
 *   Modified() when the view changes (vtkDynamicVisibilityDriver does);
 * - rigid motion of a single object needs no new visibility: give its rotation to
 *   vtkEnvironmentVisibilityLighting::SetObjectRotation() and its actor to SetViewProp();
 * - level changes reuse what is computed (the adaptive lightsphere of §4.2): each point
 *   remembers how many directions it has, so raising the level renders only the new ones, for
 *   the points that need them.
 *
 * Progress events fire between directions and an abort stops the computation there. A missing
 * OpenGL feature, or no OpenGL context at all, is an error that names what is missing; RAY_CAST
 * still works.
 *
 * @sa vtkLightSphereVisibility vtkLightSphere vtkAperturePrecompute vtkDynamicVisibilityDriver
 */

#ifndef vtkOcclusionQueryVisibility_h
#define vtkOcclusionQueryVisibility_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkLightSphereVisibility.h"

#include <array>      // For std::array
#include <cstdint>    // For std::uint64_t
#include <functional> // For std::function
#include <memory>     // For std::unique_ptr
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkOpenGLRenderWindow;
class vtkProp3D;
class vtkRenderWindow;
class vtkRenderer;
class vtkWindow;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkOcclusionQueryVisibility
  : public vtkLightSphereVisibility
{
public:
  static vtkOcclusionQueryVisibility* New();
  vtkTypeMacro(vtkOcclusionQueryVisibility, vtkLightSphereVisibility);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Backends
  {
    OCCLUSION_QUERY = 0,
    DEPTH_COMPARE = 1,
    RAY_CAST = 2
  };

  ///@{
  /**
   * How visibility is computed. Default DEPTH_COMPARE.
   */
  vtkSetClampMacro(Backend, int, OCCLUSION_QUERY, RAY_CAST);
  vtkGetMacro(Backend, int);
  void SetBackendToOcclusionQuery() { this->SetBackend(OCCLUSION_QUERY); }
  void SetBackendToDepthCompare() { this->SetBackend(DEPTH_COMPARE); }
  void SetBackendToRayCast() { this->SetBackend(RAY_CAST); }
  const char* GetBackendAsString();
  ///@}

  ///@{
  /**
   * Side of the square depth texture of the OpenGL backends, clamped to [16, 8192]. The scene's
   * bounding sphere spans it, so a texel covers 2R/n. Default 1024.
   */
  vtkSetClampMacro(DepthResolution, int, 16, 8192);
  vtkGetMacro(DepthResolution, int);
  ///@}

  ///@{
  /**
   * glPolygonOffset(factor, units) of the depth pass, which keeps a surface from hiding its own
   * vertices. Default (1, 1), as in the paper.
   */
  vtkSetMacro(PolygonOffsetFactor, float);
  vtkGetMacro(PolygonOffsetFactor, float);
  vtkSetMacro(PolygonOffsetUnits, float);
  vtkGetMacro(PolygonOffsetUnits, float);
  ///@}

  ///@{
  /**
   * A render window whose OpenGL context the OpenGL backends share. Without one they open
   * their own off-screen window. The filter does not keep the window alive (it usually renders
   * the filter's output); once the window is gone, the filter opens its own.
   */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow();
  ///@}

  ///@{
  /**
   * Vertex filtering: compute visibility only for the points of triangles the view renderer's
   * camera has seen. Off by default; needs SetViewRenderer() and OpenGL (whatever the backend).
   */
  vtkSetMacro(VertexFiltering, bool);
  vtkGetMacro(VertexFiltering, bool);
  vtkBooleanMacro(VertexFiltering, bool);
  ///@}

  ///@{
  /**
   * When fewer than this fraction of the receiver triangles remain unseen, filtering stops and
   * computes them all: testing them costs more than it saves. Clamped to [0, 1]. Default 0.05.
   */
  vtkSetClampMacro(FilteringThreshold, double, 0.0, 1.0);
  vtkGetMacro(FilteringThreshold, double);
  ///@}

  ///@{
  /**
   * The renderer whose camera and viewport vertex filtering follows, and the prop (actor) that
   * places the input in its world (optional: identity). Held weakly, so that an actor showing
   * this filter's output makes no reference loop.
   */
  void SetViewRenderer(vtkRenderer* renderer);
  vtkRenderer* GetViewRenderer();
  void SetViewProp(vtkProp3D* prop);
  vtkProp3D* GetViewProp();
  ///@}

  /**
   * Depth passes (OpenGL backends; DEPTH_COMPARE renders a direction and its opposite in one
   * pass) or directions cast (RAY_CAST) in the last update; directions reused from an earlier
   * update are not counted.
   */
  vtkGetMacro(NumberOfDepthPasses, int);

  /**
   * Receiver triangles the camera has not seen yet (vertex filtering), and whether filtering is
   * still going on (it stops below FilteringThreshold).
   */
  vtkIdType GetNumberOfUnseenTriangles();
  bool GetFilteringActive();

  /**
   * Bytes of points and triangles the last update uploaded to the GPU.
   */
  vtkGetMacro(UploadedBytes, vtkIdType);

  /**
   * Releases the OpenGL resources held in the window's context.
   */
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkOcclusionQueryVisibility();
  ~vtkOcclusionQueryVisibility() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /**
   * The backends and vertex filtering on vtkLightSphereVisibility's computation.
   */
  bool CheckSettings(std::string& error) override;
  void AppendCacheKey(std::vector<vtkMTimeType>& key) override;
  void SurfacesChanged() override;
  bool SelectPoints(std::string& error) override;
  bool ComputeDirections(const Directions& directions, const std::vector<std::uint32_t>& points,
    std::vector<Bits>& visible, const std::function<bool(size_t done)>& progress,
    std::string& error) override;
  bool LeavesPointsOut() override;
  ///@}

  int Backend = DEPTH_COMPARE;
  int DepthResolution = 1024;
  float PolygonOffsetFactor = 1.0f;
  float PolygonOffsetUnits = 1.0f;
  bool VertexFiltering = false;
  double FilteringThreshold = 0.05;
  int NumberOfDepthPasses = 0;
  vtkIdType UploadedBytes = 0;

private:
  vtkOcclusionQueryVisibility(const vtkOcclusionQueryVisibility&) = delete;
  void operator=(const vtkOcclusionQueryVisibility&) = delete;

  bool RenderOpenGL(const Directions& directions, const std::vector<std::uint32_t>& points,
    std::vector<Bits>& visible, const std::function<bool(size_t)>& progress, std::string& error);
  // The OpenGL window and the scene on it; false with an error when there is none.
  bool PrepareOpenGL(bool needStorage, std::string& error);
  // The window whose context the passes use (current), the caller's or one of our own, with
  // what the passes need; nullptr with an error otherwise.
  vtkOpenGLRenderWindow* OpenGLWindow(bool needStorage, std::string& error);
  // The points, vertices and triangles the OpenGL passes draw.
  void BuildOpenGLScene();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
  vtkRenderWindow* OwnWindow = nullptr;
};

#endif
