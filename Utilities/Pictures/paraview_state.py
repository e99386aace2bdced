"""The scene of docs/images/paraview-gui.png: the bunny under the Aperture Lighting representation,
saved as a ParaView state file (pvpython paraview_state.py <Testing/Data> <out.pvsm>)."""
import os, sys
import paraview.simple as pvs
data = sys.argv[1]
bunny = pvs.OpenDataFile(os.path.join(data, "stanford-bunny.obj"))
pvs.RenameSource("stanford-bunny.obj", bunny)
apertures = pvs.AperturePrecompute(Input=bunny, NumberOfRays=256)
view = pvs.GetActiveViewOrCreate("RenderView")
display = pvs.Show(apertures, view)
display.SetRepresentationType("Aperture Lighting")
display.ApertureLightSize = 3.0
display.ApertureSkyIntensity = 0.25
display.ColorArrayName = ["POINTS", ""]
pvs.SetActiveSource(apertures)
view.CameraPosition = [-0.02, 0.11, 0.45]
view.CameraFocalPoint = [-0.02, 0.11, 0.0]
view.CameraViewUp = [0, 1, 0]
pvs.ResetCamera(view)
pvs.SaveState(sys.argv[2])
