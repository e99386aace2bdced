/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkDynamicVisibilityDriver.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkDynamicVisibilityDriver
 * @brief   keeps a visibility matrix current in an interactive or animated view
 *
 * Attached to a renderer, the driver brings vtkOcclusionQueryVisibility (and the
 * vtkEnvironmentVisibilityLighting after it, when given) up to date before every frame of the
 * renderer's window, as Sattler et al. (2004, §4 and §6) do:
 *
 * - it watches the pipeline upstream of the visibility filter (a time step, a warp, an
 *   animation): when it changed, the frame is a moving one and visibility is recomputed;
 * - it watches the camera and the prop's matrix: with vertex filtering on, a new view sends the
 *   filter looking for triangles that come into view; a prop turned rigidly only turns the
 *   lighting's directions (vtkEnvironmentVisibilityLighting::SetObjectRotation());
 * - it watches the interactor style's StartInteractionEvent and EndInteractionEvent, and the
 *   interactor's mouse buttons;
 * - the adaptive lightsphere (§4.2): a moving frame with something to compute (new geometry, or
 *   a new view while vertex filtering is active) takes the moving level: the highest that kept
 *   such updates within TargetUpdateTime (one level down when one took longer, one up when it
 *   took under a quarter of it), between MinimumLevel and MaximumLevel, starting from
 *   MinimumLevel. A moving frame with nothing to compute keeps its level. Every idle frame raises
 *   the level by one up to MaximumLevel, and the interactor (when attached) is asked for those
 *   frames with a one-shot timer IdleDelay after the latest frame. Raising a level renders only
 *   its new directions.
 *
 * In a few lines:
 * @code
 * vtkNew<vtkDynamicVisibilityDriver> driver;
 * driver->SetVisibility(visibility);
 * driver->SetLighting(lighting);
 * driver->SetProp(actor);
 * driver->Attach(renderer, interactor); // interactor may be null
 * @endcode
 *
 * Without an interactor (scripts, animations), each Render() of the window is a frame; call
 * StartInteraction() and EndInteraction() to mark interaction by other means.
 *
 * @sa vtkOcclusionQueryVisibility vtkEnvironmentVisibilityLighting
 */

#ifndef vtkDynamicVisibilityDriver_h
#define vtkDynamicVisibilityDriver_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

#include <vector> // For std::vector

class vtkEnvironmentVisibilityLighting;
class vtkOcclusionQueryVisibility;
class vtkProp3D;
class vtkRenderWindow;
class vtkRenderWindowInteractor;
class vtkRenderer;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkDynamicVisibilityDriver : public vtkObject
{
public:
  static vtkDynamicVisibilityDriver* New();
  vtkTypeMacro(vtkDynamicVisibilityDriver, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The visibility filter kept current (required), and the lighting after it (optional: what
   * each frame updates when given).
   */
  void SetVisibility(vtkOcclusionQueryVisibility* visibility);
  vtkGetObjectMacro(Visibility, vtkOcclusionQueryVisibility);
  void SetLighting(vtkEnvironmentVisibilityLighting* lighting);
  vtkGetObjectMacro(Lighting, vtkEnvironmentVisibilityLighting);
  ///@}

  ///@{
  /**
   * The actor showing the object (optional). Its matrix places the object for vertex filtering
   * and its rotation turns the lighting's directions.
   */
  void SetProp(vtkProp3D* prop);
  vtkGetObjectMacro(Prop, vtkProp3D);
  ///@}

  /**
   * Updates before every frame of the renderer's window, follows its camera and, when an
   * interactor is given, its style's interaction and asks it for the refining frames. Attach
   * again to move; Detach() to stop.
   */
  void Attach(vtkRenderer* renderer, vtkRenderWindowInteractor* interactor = nullptr);
  void Detach();

  ///@{
  /**
   * The range of lightsphere levels (0 to 4: k = 6 to 1026). Defaults 0 and 3 (k = 258).
   */
  vtkSetClampMacro(MinimumLevel, int, 0, 4);
  vtkGetMacro(MinimumLevel, int);
  vtkSetClampMacro(MaximumLevel, int, 0, 4);
  vtkGetMacro(MaximumLevel, int);
  ///@}

  ///@{
  /**
   * Seconds an update may take while the scene moves; 0 keeps MinimumLevel while moving.
   * Default 0.05.
   */
  vtkSetClampMacro(TargetUpdateTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TargetUpdateTime, double);
  ///@}

  ///@{
  /**
   * Milliseconds the interactor waits, idle, before a refining frame. Default 100.
   */
  vtkSetClampMacro(IdleDelay, int, 1, 60000);
  vtkGetMacro(IdleDelay, int);
  ///@}

  ///@{
  /**
   * Marks interaction by means the driver does not see (the interactor style's events call
   * them too).
   */
  void StartInteraction();
  void EndInteraction();
  vtkGetMacro(Interacting, bool);
  ///@}

  /**
   * What every frame does before it renders: chooses the level, hands the filter the view and
   * the lighting the rotation, and updates them. Called by the window's StartEvent when
   * attached; call it yourself otherwise.
   */
  void Update();

  ///@{
  /**
   * The last update: whether it was a moving frame, the level it used, and how long it took
   * in seconds.
   */
  vtkGetMacro(Moving, bool);
  vtkGetMacro(Level, int);
  vtkGetMacro(LastUpdateTime, double);
  ///@}

  /**
   * Whether idle frames would still raise the level.
   */
  bool NeedsRefinement() const;

protected:
  vtkDynamicVisibilityDriver();
  ~vtkDynamicVisibilityDriver() override;

  vtkOcclusionQueryVisibility* Visibility = nullptr;
  vtkEnvironmentVisibilityLighting* Lighting = nullptr;
  vtkProp3D* Prop = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkRenderWindowInteractor* Interactor = nullptr;
  int MinimumLevel = 0;
  int MaximumLevel = 3;
  double TargetUpdateTime = 0.05;
  int IdleDelay = 100;
  bool Interacting = false;
  bool Moving = false;
  int Level = -1;
  double LastUpdateTime = 0.0;

private:
  vtkDynamicVisibilityDriver(const vtkDynamicVisibilityDriver&) = delete;
  void operator=(const vtkDynamicVisibilityDriver&) = delete;

  static void OnEvent(vtkObject* caller, unsigned long event, void* clientData, void* callData);
  // The largest pipeline modification time upstream of the visibility filter's inputs.
  vtkMTimeType UpstreamMTime();
  // Camera, viewport and prop matrix: what vertex filtering looks through.
  std::vector<double> ViewSignature();
  // Asks the interactor for a refining frame when one is due.
  void ScheduleRefinement();
  // Update()'s steps: the level of this frame (the moving level when a moving frame has work,
  // one finer on idle frames); the prop's rotation for the lighting; the moving level adapted to
  // the time the frame took.
  void ChooseLevel(int lowest, int highest, bool geometryChanged, bool viewChanged);
  void PassObjectRotation();
  void AdaptMovingLevel(int lowest, int highest);

  int MovingLevel = -1;
  vtkMTimeType LastUpstream = 0;
  std::vector<double> LastView;
  vtkWeakPointer<vtkRenderWindow> Window;
  unsigned long WindowObserver = 0;
  std::vector<unsigned long> ButtonObservers;
  unsigned long StyleObservers[2] = { 0, 0 };
  unsigned long TimerObserver = 0;
  int TimerId = -1;
  vtkObject* Style = nullptr;
};

#endif
