#!/usr/bin/env bash
# docs/images/paraview-gui.png: ParaView's own window with the bunny under the Aperture Lighting
# representation. Needs `make paraview` and xwd, xwdtopnm, pnmtopng (x11-apps, netpbm):
#   Utilities/Pictures/paraview_gui.sh build-paraview docs/images/paraview-gui.png
# The scene is a state file written by pvpython (Utilities/Pictures/paraview_state.py), which the
# GUI loads with the plugin found through PV_PLUGIN_PATH, from a script that also selects the
# filter (so that its properties and the representation show); the screen is captured after it
# drew. The GUI's Python needs the unpacked ParaView modules first on sys.path, as pvpython does.
set -euo pipefail
build="$1"
out="$2"
work="$build/pictures"
mkdir -p "$work"
source "$build/env.sh"
here="$(cd "$(dirname "$0")" && pwd)"
cat > "$work/gui.py" <<PY
import sys
sys.path.insert(0, "$(realpath "$build")/python3-paraview/usr/lib/python3/dist-packages")
from paraview.simple import FindSource, LoadState, Render, SetActiveSource
LoadState("$(realpath "$work")/bunny.pvsm")
SetActiveSource(FindSource("AperturePrecompute1"))
Render()
PY
# One X server for both steps (back-to-back servers can race for the same display).
xvfb-run -a -s "-screen 0 1400x900x24 -noreset" bash -c "
  pvpython '$here/paraview_state.py' '$here/../../Testing/Data' '$work/bunny.pvsm'
  paraview --dr --script='$work/gui.py' > '$work/paraview.log' 2>&1 &
  sleep 30
  xwd -root -silent | xwdtopnm 2>/dev/null | pnmtopng > '$work/screen.png'
  kill %1"
/usr/bin/python3 - "$work/screen.png" "$out" <<'PY'
import sys
from PIL import Image
screen = Image.open(sys.argv[1]).convert("RGB")
screen.crop(screen.getbbox()).save(sys.argv[2])
PY

# docs/images/paraview-representation.png: the representation test's pictures side by side
# (Surface, Aperture Lighting exact, a 12 degree light, a sky, an HDR sky, coloured by
# ApertureRadius), after `make paraview-test`.
shots="$build/ParaView/Testing/Temporary/representation"
if [ -f "$shots/exact.png" ]; then
  /usr/bin/python3 - "$shots" "$(dirname "$out")/paraview-representation.png" <<'PY'
import sys
from PIL import Image
names = ["surface", "exact", "soft", "sky", "environment", "colored"]
shots = [Image.open(f"{sys.argv[1]}/{n}.png").convert("RGB").resize((240, 240)) for n in names]
montage = Image.new("RGB", (240 * len(shots), 240))
for i, shot in enumerate(shots):
    montage.paste(shot, (240 * i, 0))
montage.save(sys.argv[2])
PY
fi
