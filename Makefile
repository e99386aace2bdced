# ApertureLighting: `make demo` installs what is missing, builds and renders the default scene;
# `make test` installs, builds and runs every test; `make pictures` remakes the README's pictures.
# Variables: BUILD_DIR (build), BUILD_TYPE (Release), JOBS (all cores), CMAKE_ARGS.

BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
# The interpreter Debian's VTK Python modules are built for (not a pyenv python3 on PATH).
PYTHON ?= /usr/bin/python3
CMAKE_ARGS ?=

# Debian's VTK renders through X only: pictures are made on a virtual screen. Without -noreset
# the server resets whenever its last client leaves and refuses connections meanwhile, which
# failed a test now and then ("cannot open the X display", "bad X server connection").
XVFB = xvfb-run -a -s "-screen 0 1920x1080x24 -noreset"
RENDER = $(XVFB) $(BUILD_DIR)/bin/aperture-render

.PHONY: all deps configure build demo test pictures evaluation report fuzz sanitize install format \
  paraview paraview-test clean

all: build

deps:
	@Utilities/install-dependencies.sh

configure: deps
	@mkdir -p $(BUILD_DIR)
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) \
	  -DPython3_EXECUTABLE=$(PYTHON) $(CMAKE_ARGS) > $(BUILD_DIR)/configure.log 2>&1 \
	  || { cat $(BUILD_DIR)/configure.log; exit 1; }

build: configure
	@cmake --build $(BUILD_DIR) --parallel $(JOBS)

demo: build
	@mkdir -p $(BUILD_DIR)/demo
	@$(RENDER) -o $(BUILD_DIR)/demo/fuji.png --cache $(BUILD_DIR)/demo/fuji-apertures.vti
	@echo "Demo picture: $(abspath $(BUILD_DIR)/demo/fuji.png)"

test: build
	@cd $(BUILD_DIR) && $(XVFB) \
	  ctest --output-on-failure --parallel $(JOBS)

# The pictures in README.md and docs/: every shading mode on the Fuji terrain and on the bunny, the
# aperture radius as colours, HDR environments, dynamic scenes, real meshes, a 10,000² DEM and the
# head MR against the volume reference.
pictures: build
	@mkdir -p docs/images $(BUILD_DIR)/demo
	@$(RENDER) -o docs/images/fuji.png --size 1280x800 \
	  --cache $(BUILD_DIR)/demo/fuji-apertures.vti
	@$(RENDER) -o docs/images/fuji-modes.png --mode all --size 480x330 \
	  --cache $(BUILD_DIR)/demo/fuji-apertures.vti
	@$(RENDER) -o docs/images/fuji-low-sun.png --mode all --size 480x330 --sun 250,8 \
	  --cache $(BUILD_DIR)/demo/fuji-apertures.vti
	@$(RENDER) -o docs/images/fuji-apertures.png --show apertures --size 800x500 \
	  --cache $(BUILD_DIR)/demo/fuji-apertures.vti
	@$(RENDER) Testing/Data/stanford-bunny.obj -o docs/images/bunny-default.png --size 640x480 \
	  --cache $(BUILD_DIR)/demo/bunny-apertures.vtp > /dev/null
	@$(RENDER) Testing/Data/stanford-bunny.obj -o docs/images/bunny-modes.png --mode all \
	  --size 360x330 --sphere-light -0.15,0.22,0.14,0.03 \
	  --cache $(BUILD_DIR)/demo/bunny-apertures.vtp
	@$(XVFB) $(BUILD_DIR)/bin/BunnyEnvironment Testing/Data/stanford-bunny.obj \
	  docs/images/bunny-environment.png
	@$(RENDER) -o docs/images/fuji-sunrise.png --env Testing/Data/env/sunrise.exr --size 800x500 \
	  --cache $(BUILD_DIR)/demo/fuji-apertures.vti
	@$(XVFB) $(BUILD_DIR)/bin/DynamicScenes deform Testing/Data/env/forest.exr \
	  docs/images/dynamic-deform.png > /dev/null
	@$(XVFB) $(BUILD_DIR)/bin/DynamicScenes orbit Testing/Data/stanford-bunny.obj \
	  Testing/Data/env/forest.exr docs/images/dynamic-orbit.png > /dev/null
	@. $(BUILD_DIR)/env.sh && $(XVFB) $(PYTHON) Utilities/Pictures/real_meshes.py \
	  $(BUILD_DIR)/bin/aperture-render Testing/Data $(BUILD_DIR)/demo/real docs/images
	@. $(BUILD_DIR)/env.sh && $(XVFB) $(PYTHON) Utilities/Pictures/big_terrain.py \
	  $(BUILD_DIR)/bin/aperture-render Testing/Data $(BUILD_DIR)/demo/terrain docs/images
	@. $(BUILD_DIR)/env.sh && $(XVFB) $(PYTHON) Utilities/Pictures/volume_reference.py \
	  Testing/Data/volumes/head-t1-mr.nii.gz docs/images/volume-reference-mr.png --size 300x300

# The accuracy evaluation (docs/evaluation-tables.md, docs/images/evaluation-montage.png) and the
# performance report (docs/performance.md and its plots); REPORT_MAX_LEVEL limits Table 1.
REPORT_MAX_LEVEL ?= 3
evaluation: build
	@. $(BUILD_DIR)/env.sh && $(XVFB) $(PYTHON) Utilities/Evaluation/evaluate.py --out docs

report: build
	@. $(BUILD_DIR)/env.sh && $(XVFB) $(PYTHON) Utilities/Evaluation/performance.py \
	  --bin $(BUILD_DIR)/bin --out docs --max-level $(REPORT_MAX_LEVEL)

# libFuzzer on the EXR, the mesh and the volume reading paths, with AddressSanitizer and
# UndefinedBehaviorSanitizer, in a Clang build of its own, for FUZZ_SECONDS (60) each from random
# seed FUZZ_SEED (0: a new one each run); the corpora and any crash-* files stay in
# $(FUZZ_DIR)/corpus-<target> and $(FUZZ_DIR). The DEM target is run by hand
# (`make fuzz FUZZERS=FuzzGDALDEMReader`): it mostly fuzzes GDAL itself, whose hangs on damaged
# files would fail CI at random; ctest replays it on fixed mutations instead.
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_SEED ?= 0
FUZZERS = FuzzOpenEXRReader FuzzMeshReaders FuzzVolumeReaders
# A request for more memory than exists gets null, as glibc's malloc gives it in a release build
# (a damaged array in a file can ask VTK's readers for petabytes; they report it). Memory really
# used stays limited (rss_limit_mb). Leaks in the system's and VTK 9.1's own failure paths are
# suppressed as in `make sanitize`.
FUZZ_ENV = ASAN_OPTIONS=allocator_may_return_null=1 \
  LSAN_OPTIONS=suppressions=$(abspath Testing/Sanitizers/lsan.supp):print_suppressions=0
SANITIZE = -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
fuzz:
	@Utilities/install-dependencies.sh fuzz
	@mkdir -p $(FUZZ_DIR)
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DAPERTURELIGHTING_LIBFUZZER=ON -DPython3_EXECUTABLE=$(PYTHON) \
	  -DCMAKE_C_FLAGS="$(SANITIZE)" -DCMAKE_CXX_FLAGS="$(SANITIZE) -fsanitize=fuzzer-no-link" \
	  -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE)" -DCMAKE_SHARED_LINKER_FLAGS="$(SANITIZE)" \
	  > $(FUZZ_DIR)/configure.log 2>&1 || { cat $(FUZZ_DIR)/configure.log; exit 1; }
	@cmake --build $(FUZZ_DIR) --parallel $(JOBS) --target $(FUZZERS) $(FUZZERS:%=%Replay)
	@for f in $(FUZZERS); do \
	  mkdir -p $(FUZZ_DIR)/corpus-$$f && $(FUZZ_DIR)/bin/$${f}Replay --write-seeds $(FUZZ_DIR)/corpus-$$f && \
	  (cd $(FUZZ_DIR) && $(FUZZ_ENV) ./bin/$$f -max_total_time=$(FUZZ_SECONDS) -seed=$(FUZZ_SEED) \
	    -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1048577 -max_len=16384 \
	    -print_final_stats=1 corpus-$$f) || exit 1; \
	done

# The ParaView plugin in $(PARAVIEW_DIR): ParaView 5.11 installed without its Recommends (they
# would remove VTK 9.1's development packages), python3-paraview's pvpython unpacked there, the
# module built against ParaView's own VTK as ApertureLightingPlugin, and $(PARAVIEW_DIR)/env.sh,
# which puts pvpython and pvbatch with the plugin on PATH. paraview-test runs its tests (pvpython,
# a picture of the representation, mpirun -np 2 pvbatch) under one X server.
PARAVIEW_DIR ?= build-paraview
paraview:
	@Utilities/install-dependencies.sh paraview
	@mkdir -p $(PARAVIEW_DIR)
	@Utilities/ParaView/unpack-pvpython.sh $(PARAVIEW_DIR)
	@cmake -S . -B $(PARAVIEW_DIR) -DAPERTURELIGHTING_PARAVIEW_PLUGIN=ON \
	  -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) > $(PARAVIEW_DIR)/configure.log 2>&1 \
	  || { cat $(PARAVIEW_DIR)/configure.log; exit 1; }
	@cmake --build $(PARAVIEW_DIR) --parallel $(JOBS)
	@echo "ParaView plugin: $(abspath $(PARAVIEW_DIR))/lib/paraview-5.11/plugins/ApertureLightingPlugin"
	@echo "pvpython and pvbatch with it: source $(abspath $(PARAVIEW_DIR))/env.sh"

paraview-test: paraview
	@cd $(PARAVIEW_DIR) && $(XVFB) ctest --output-on-failure

# The whole ctest suite built with AddressSanitizer and UndefinedBehaviorSanitizer (Clang, one
# shared runtime), in $(SANITIZE_DIR). The Python tests run an interpreter that preloads the
# runtime (Testing/Sanitizers/python3-asan.in; without leak checks in the interpreter itself).
# Every process keeps its libraries loaded (Testing/Sanitizers/keep-loaded.c), and leaks reported
# in the system's OpenGL and X libraries, and in VTK 9.1's failure paths, are suppressed
# (Testing/Sanitizers/lsan.supp); any other report fails. A test that fails only because
# LeakSanitizer's own tracer crashed at exit runs twice more, then once without the leak check
# if that crash ends every run (Testing/Sanitizers/ctest_sanitized.py, which says so);
# the command-line tests, which run their tool a hundred times, rerun such a run of it instead
# (Examples/ApertureRender/Testing/tool_run.py).
# The shared libraries do not export their std template instances
# (Testing/Sanitizers/hide-std.map): a program built without the sanitizers loads the runtime
# after other libraries, whose static constructors would otherwise call those instrumented copies
# before the runtime has started.
SANITIZE_DIR ?= build-sanitize
SANITIZE_RUNTIME = $(shell clang -print-file-name=libclang_rt.asan-x86_64.so 2>/dev/null)
SANITIZE_PYTHON = $(abspath $(SANITIZE_DIR))/python3-asan
SANITIZE_KEEP = $(abspath $(SANITIZE_DIR))/libkeep-loaded.so
sanitize:
	@Utilities/install-dependencies.sh fuzz
	@mkdir -p $(SANITIZE_DIR)
	@clang -shared -fPIC -o $(SANITIZE_KEEP) Testing/Sanitizers/keep-loaded.c
	@sed -e 's|@KEEP@|$(SANITIZE_KEEP)|g; s|@RUNTIME@|$(SANITIZE_RUNTIME)|; s|@PYTHON@|$(PYTHON)|' \
	  -e 's|@SITE@|$(abspath Testing/Sanitizers)|' Testing/Sanitizers/python3-asan.in \
	  > $(SANITIZE_PYTHON) && chmod +x $(SANITIZE_PYTHON)
	@CC=clang CXX=clang++ cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DPython3_EXECUTABLE=$(SANITIZE_PYTHON) \
	  -DCMAKE_C_FLAGS="$(SANITIZE) -shared-libasan -fno-sanitize=vptr" \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE) -shared-libasan -fno-sanitize=vptr" \
	  -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE) -shared-libasan -Wl,-rpath,$(dir $(SANITIZE_RUNTIME))" \
	  -DCMAKE_SHARED_LINKER_FLAGS="$(SANITIZE) -shared-libasan -Wl,-rpath,$(dir $(SANITIZE_RUNTIME)) -Wl,--version-script=$(abspath Testing/Sanitizers/hide-std.map)" \
	  -DCMAKE_MODULE_LINKER_FLAGS="$(SANITIZE) -shared-libasan -Wl,-rpath,$(dir $(SANITIZE_RUNTIME))" \
	  > $(SANITIZE_DIR)/configure.log 2>&1 || { cat $(SANITIZE_DIR)/configure.log; exit 1; }
	@cmake --build $(SANITIZE_DIR) --parallel $(JOBS)
	@cd $(SANITIZE_DIR) && $(SANITIZER_ENV) $(XVFB) $(PYTHON) \
	  $(abspath Testing/Sanitizers/ctest_sanitized.py) \
	  --output-on-failure --parallel $(JOBS) --timeout 1500 $(SANITIZE_CTEST_ARGS)
ASAN_SETTINGS = detect_leaks=1:abort_on_error=1:detect_odr_violation=0:allocator_may_return_null=1:$\
  verify_asan_link_order=0
SANITIZER_ENV = LD_PRELOAD=$(SANITIZE_KEEP) ASAN_OPTIONS=$(ASAN_SETTINGS) \
  LSAN_OPTIONS=suppressions=$(abspath Testing/Sanitizers/lsan.supp):print_suppressions=0 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

install: build
	@cmake --install $(BUILD_DIR)

format:
	@find Core IO Rendering Volume ParaView Testing Examples -name '*.h' -o -name '*.cxx' 2>/dev/null \
	  | xargs clang-format -i --style=file

clean:
	@rm -rf $(BUILD_DIR) $(FUZZ_DIR) $(SANITIZE_DIR)
