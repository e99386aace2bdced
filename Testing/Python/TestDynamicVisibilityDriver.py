"""vtkDynamicVisibilityDriver in a real event loop, from Python.

An interactor's event loop runs with the driver attached; an animation timer deforms a warped
sphere for a few frames, then stops. Without further input the driver must ask for its own
refining frames (one-shot timers) until MaximumLevel: the test checks that the last frames were
idle ones at MaximumLevel and that the moving frames used a coarser level. Also: the wrapped
filter settings, and the mouse buttons marking interaction.
"""

import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_INT
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkFiltersCore import vtkSimpleElevationFilter
from vtkmodules.vtkFiltersGeneral import vtkWarpScalar
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import vtkDynamicVisibilityDriver, vtkOcclusionQueryVisibility

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL", what, file=sys.stderr)


sphere = vtkSphereSource()
sphere.SetThetaResolution(32)
sphere.SetPhiResolution(16)
height = vtkSimpleElevationFilter()
height.SetInputConnection(sphere.GetOutputPort())
warp = vtkWarpScalar()
warp.SetInputConnection(height.GetOutputPort())
warp.SetScaleFactor(0.2)

window = vtkRenderWindow()
window.SetSize(200, 200)
renderer = vtkRenderer()
window.AddRenderer(renderer)
visibility = vtkOcclusionQueryVisibility()
visibility.SetInputConnection(warp.GetOutputPort())
visibility.SetRenderWindow(window)
visibility.SetFilteringThreshold(0.1)
check(abs(visibility.GetFilteringThreshold() - 0.1) < 1e-12, "FilteringThreshold is wrapped")
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(visibility.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
renderer.AddActor(actor)

interactor = vtkRenderWindowInteractor()
interactor.SetRenderWindow(window)
interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
interactor.Initialize()

driver = vtkDynamicVisibilityDriver()
driver.SetVisibility(visibility)
driver.SetMinimumLevel(0)
driver.SetMaximumLevel(2)
driver.SetTargetUpdateTime(0.0)
driver.SetIdleDelay(50)
driver.Attach(renderer, interactor)

frames = []
state = {"step": 0, "timer": -1, "ticks": 0}


def on_end(caller, event):
    # What each frame of the window used.
    frames.append((driver.GetMoving(), driver.GetLevel()))


@calldata_type(VTK_INT)
def on_timer(caller, event, timer):
    # The driver's one-shot timers come here too.
    if timer != state["timer"]:
        return
    state["ticks"] += 1
    if state["step"] < 4:
        state["step"] += 1
        warp.SetScaleFactor(0.2 + 0.1 * state["step"])
        window.Render()
    elif state["ticks"] > 40:
        interactor.TerminateApp()


window.AddObserver(vtkCommand.EndEvent, on_end)
interactor.AddObserver(vtkCommand.TimerEvent, on_timer)
window.Render()
state["timer"] = interactor.CreateRepeatingTimer(50)
interactor.Start()

print("frames (moving, level):", frames)
moving = [level for is_moving, level in frames if is_moving]
idle = [level for is_moving, level in frames if not is_moving]
check(len(moving) >= 4 and all(level == 0 for level in moving[1:]),
      "moving frames use the coarse level")
check(len(idle) >= 2 and idle[-1] == 2, "the driver's own timers refine to MaximumLevel")
check(not driver.NeedsRefinement(), "nothing is left to refine")

interactor.InvokeEvent(vtkCommand.LeftButtonPressEvent)
check(driver.GetInteracting(), "a mouse button pressed is interaction")
interactor.InvokeEvent(vtkCommand.LeftButtonReleaseEvent)
check(not driver.GetInteracting(), "released, it is over")
driver.Detach()

sys.exit(1 if failures else 0)
