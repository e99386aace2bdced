# Loaded first by `make sanitize`'s Python (python3-asan.in). The programs the tests start (CMake,
# compilers, aperture-render, which links the sanitizer runtime itself) must not inherit the
# interpreter's preloaded runtime nor its leak settings; a Python they start is this one again.
import os
import sys

os.environ["LD_PRELOAD"] = os.environ.pop("APERTURE_SANITIZE_CHILD_PRELOAD", "")
os.environ["ASAN_OPTIONS"] = os.environ.pop("APERTURE_SANITIZE_CHILD_ASAN_OPTIONS", "")
sys.executable = os.environ.get("APERTURE_SANITIZE_PYTHON", sys.executable)
