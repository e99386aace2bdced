/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkDynamicVisibilityDriver.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkDynamicVisibilityDriver.h"

#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkOcclusionQueryVisibility.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInteractorObserver.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProp3D.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"

#include <algorithm>

vtkStandardNewMacro(vtkDynamicVisibilityDriver);
vtkCxxSetObjectMacro(vtkDynamicVisibilityDriver, Visibility, vtkOcclusionQueryVisibility);
vtkCxxSetObjectMacro(vtkDynamicVisibilityDriver, Lighting, vtkEnvironmentVisibilityLighting);
vtkCxxSetObjectMacro(vtkDynamicVisibilityDriver, Prop, vtkProp3D);

//------------------------------------------------------------------------------
vtkDynamicVisibilityDriver::vtkDynamicVisibilityDriver() = default;

//------------------------------------------------------------------------------
vtkDynamicVisibilityDriver::~vtkDynamicVisibilityDriver()
{
  this->Detach();
  this->SetVisibility(nullptr);
  this->SetLighting(nullptr);
  this->SetProp(nullptr);
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::Attach(
  vtkRenderer* renderer, vtkRenderWindowInteractor* interactor)
{
  this->Detach();
  if (!renderer || !renderer->GetRenderWindow())
  {
    vtkErrorMacro("Attach() needs a renderer that is in a render window.");
    return;
  }
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&vtkDynamicVisibilityDriver::OnEvent);
  command->SetClientData(this);
  this->Renderer = renderer;
  this->Renderer->Register(this);
  this->Window = renderer->GetRenderWindow();
  this->WindowObserver = this->Window->AddObserver(vtkCommand::StartEvent, command);
  if (interactor)
  {
    this->Interactor = interactor;
    this->Interactor->Register(this);
    this->TimerObserver = interactor->AddObserver(vtkCommand::TimerEvent, command);
    // Mouse buttons held down are interaction whatever the style (vtkInteractorStyleSwitch does
    // not pass its styles' interaction events on); the style's events cover the rest.
    for (unsigned long event :
      { vtkCommand::LeftButtonPressEvent, vtkCommand::MiddleButtonPressEvent,
        vtkCommand::RightButtonPressEvent, vtkCommand::LeftButtonReleaseEvent,
        vtkCommand::MiddleButtonReleaseEvent, vtkCommand::RightButtonReleaseEvent })
    {
      this->ButtonObservers.push_back(interactor->AddObserver(event, command));
    }
    this->Style = interactor->GetInteractorStyle();
    if (this->Style)
    {
      this->Style->Register(this);
      this->StyleObservers[0] =
        this->Style->AddObserver(vtkCommand::StartInteractionEvent, command);
      this->StyleObservers[1] = this->Style->AddObserver(vtkCommand::EndInteractionEvent, command);
    }
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::Detach()
{
  // The window attached to, wherever the renderer has gone since.
  if (this->Window)
  {
    this->Window->RemoveObserver(this->WindowObserver);
    this->Window = nullptr;
  }
  if (this->Renderer)
  {
    this->Renderer->UnRegister(this);
    this->Renderer = nullptr;
  }
  if (this->Style)
  {
    this->Style->RemoveObserver(this->StyleObservers[0]);
    this->Style->RemoveObserver(this->StyleObservers[1]);
    this->Style->UnRegister(this);
    this->Style = nullptr;
  }
  if (this->Interactor)
  {
    if (this->TimerId >= 0)
    {
      this->Interactor->DestroyTimer(this->TimerId);
    }
    this->Interactor->RemoveObserver(this->TimerObserver);
    for (unsigned long tag : this->ButtonObservers)
    {
      this->Interactor->RemoveObserver(tag);
    }
    this->Interactor->UnRegister(this);
    this->Interactor = nullptr;
  }
  this->ButtonObservers.clear();
  this->TimerId = -1;
  this->Interacting = false;
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::OnEvent(
  vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<vtkDynamicVisibilityDriver*>(clientData);
  switch (event)
  {
    case vtkCommand::StartEvent:
      self->Update();
      break;
    case vtkCommand::StartInteractionEvent:
    case vtkCommand::LeftButtonPressEvent:
    case vtkCommand::MiddleButtonPressEvent:
    case vtkCommand::RightButtonPressEvent:
      self->StartInteraction();
      break;
    case vtkCommand::EndInteractionEvent:
    case vtkCommand::LeftButtonReleaseEvent:
    case vtkCommand::MiddleButtonReleaseEvent:
    case vtkCommand::RightButtonReleaseEvent:
      self->EndInteraction();
      break;
    case vtkCommand::TimerEvent:
      // Only our own timer: the refining frame.
      if (callData && *static_cast<int*>(callData) == self->TimerId)
      {
        self->TimerId = -1;
        if (self->Window && self->NeedsRefinement())
        {
          self->Window->Render();
        }
      }
      break;
    default:
      break;
  }
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::StartInteraction()
{
  this->Interacting = true;
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::EndInteraction()
{
  this->Interacting = false;
  this->ScheduleRefinement();
}

//------------------------------------------------------------------------------
bool vtkDynamicVisibilityDriver::NeedsRefinement() const
{
  return this->Visibility && this->Level < this->MaximumLevel;
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::ScheduleRefinement()
{
  if (!this->Interactor || this->Interacting || !this->NeedsRefinement())
  {
    return;
  }
  // IdleDelay after the latest frame: an animation's frames keep pushing it back.
  if (this->TimerId >= 0)
  {
    this->Interactor->DestroyTimer(this->TimerId);
  }
  this->TimerId = this->Interactor->CreateOneShotTimer(this->IdleDelay);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkDynamicVisibilityDriver::UpstreamMTime()
{
  vtkMTimeType latest = 0;
  for (int port = 0; port < this->Visibility->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < this->Visibility->GetNumberOfInputConnections(port); ++c)
    {
      vtkAlgorithm* producer = this->Visibility->GetInputAlgorithm(port, c);
      auto* executive =
        producer ? vtkDemandDrivenPipeline::SafeDownCast(producer->GetExecutive()) : nullptr;
      if (executive)
      {
        executive->UpdatePipelineMTime();
        latest = std::max(latest, executive->GetPipelineMTime());
      }
    }
  }
  return latest;
}

//------------------------------------------------------------------------------
std::vector<double> vtkDynamicVisibilityDriver::ViewSignature()
{
  std::vector<double> view;
  if (this->Renderer)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    vtkMatrix4x4* matrix = camera->GetViewTransformMatrix();
    view.insert(view.end(), &matrix->Element[0][0], &matrix->Element[0][0] + 16);
    view.push_back(camera->GetViewAngle());
    view.push_back(camera->GetParallelScale());
    view.push_back(camera->GetParallelProjection());
    view.push_back(this->Renderer->GetSize()[0]);
    view.push_back(this->Renderer->GetSize()[1]);
  }
  if (this->Prop)
  {
    vtkMatrix4x4* matrix = this->Prop->GetMatrix();
    view.insert(view.end(), &matrix->Element[0][0], &matrix->Element[0][0] + 16);
  }
  return view;
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::Update()
{
  if (!this->Visibility)
  {
    vtkErrorMacro("No visibility filter: SetVisibility() first.");
    return;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  const int lowest = std::min(this->MinimumLevel, this->MaximumLevel);
  const int highest = std::max(this->MinimumLevel, this->MaximumLevel);
  // 1. What changed since the last frame.
  const vtkMTimeType upstream = this->UpstreamMTime();
  const std::vector<double> view = this->ViewSignature();
  const bool geometryChanged = upstream != this->LastUpstream;
  const bool viewChanged = view != this->LastView;
  this->LastUpstream = upstream;
  this->LastView = view;
  this->Moving = this->Interacting || geometryChanged || viewChanged;
  // 2. The level, the view and the prop's rotation; the update.
  this->ChooseLevel(lowest, highest, geometryChanged, viewChanged);
  if (this->Renderer)
  {
    this->Visibility->SetViewRenderer(this->Renderer);
  }
  this->Visibility->SetViewProp(this->Prop);
  if (viewChanged && this->Visibility->GetVertexFiltering() &&
    this->Visibility->GetFilteringActive())
  {
    this->Visibility->Modified();
  }
  this->PassObjectRotation();
  if (this->Lighting)
  {
    this->Lighting->Update();
  }
  else
  {
    this->Visibility->Update();
  }
  this->LastUpdateTime = vtkTimerLog::GetUniversalTime() - start;
  // 3. The next moving frames' level, and a refining frame when one is due.
  this->AdaptMovingLevel(lowest, highest);
  this->ScheduleRefinement();
}

//------------------------------------------------------------------------------
// The adaptive lightsphere: the moving level follows the update times, idle frames refine.
void vtkDynamicVisibilityDriver::ChooseLevel(
  int lowest, int highest, bool geometryChanged, bool viewChanged)
{
  if (this->MovingLevel < 0)
  {
    // Climbing from the coarsest level is cheap; falling from the finest is not.
    this->MovingLevel = lowest;
  }
  this->MovingLevel = std::min(std::max(this->MovingLevel, lowest), highest);
  if (this->TargetUpdateTime <= 0.0)
  {
    this->MovingLevel = lowest;
  }
  // Moving frames that have something to compute take the moving level; a camera turning
  // round a mesh whose visibility is all there keeps its level (coarser would save nothing).
  const bool filtering =
    this->Visibility->GetVertexFiltering() && this->Visibility->GetFilteringActive();
  const bool work = geometryChanged || (filtering && (viewChanged || this->Interacting));
  if (this->Level < 0 || (this->Moving && work))
  {
    this->Level = this->MovingLevel;
  }
  else if (!this->Moving)
  {
    this->Level = std::min(std::max(this->Level + 1, lowest), highest);
  }
  this->Visibility->SetLevel(this->Level);
}

//------------------------------------------------------------------------------
// The prop's rotation, without its scale, turns the lighting's directions.
void vtkDynamicVisibilityDriver::PassObjectRotation()
{
  if (!this->Lighting || !this->Prop)
  {
    return;
  }
  double a[3][3], r[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      a[i][j] = this->Prop->GetMatrix()->GetElement(i, j);
    }
  }
  vtkMath::Orthogonalize3x3(a, r);
  this->Lighting->SetObjectRotation(&r[0][0]);
}

//------------------------------------------------------------------------------
// Only frames that computed something tell what a level costs; the next level costs about four
// times as much (four times the directions).
void vtkDynamicVisibilityDriver::AdaptMovingLevel(int lowest, int highest)
{
  if (!this->Moving || this->TargetUpdateTime <= 0.0 ||
    this->Visibility->GetNumberOfComputedPoints() == 0)
  {
    return;
  }
  if (this->LastUpdateTime > this->TargetUpdateTime && this->MovingLevel > lowest)
  {
    --this->MovingLevel;
  }
  else if (4.0 * this->LastUpdateTime < this->TargetUpdateTime && this->MovingLevel < highest)
  {
    ++this->MovingLevel;
  }
}

//------------------------------------------------------------------------------
void vtkDynamicVisibilityDriver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Visibility: " << this->Visibility << "\n";
  os << indent << "Lighting: " << this->Lighting << "\n";
  os << indent << "Prop: " << this->Prop << "\n";
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Interactor: " << this->Interactor << "\n";
  os << indent << "MinimumLevel: " << this->MinimumLevel << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "TargetUpdateTime: " << this->TargetUpdateTime << "\n";
  os << indent << "IdleDelay: " << this->IdleDelay << "\n";
  os << indent << "Interacting: " << (this->Interacting ? "Yes" : "No") << "\n";
  os << indent << "Moving: " << (this->Moving ? "Yes" : "No") << "\n";
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "LastUpdateTime: " << this->LastUpdateTime << "\n";
}
