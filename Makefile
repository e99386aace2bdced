# ApertureLighting: `make test` installs what is missing, builds and runs every test.
# Variables: BUILD_DIR (build), BUILD_TYPE (Release), JOBS (all cores), CMAKE_ARGS.

BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
# The interpreter Debian's VTK Python modules are built for (not a pyenv python3 on PATH).
PYTHON ?= /usr/bin/python3
CMAKE_ARGS ?=

.PHONY: all deps configure build test install format clean

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

test: build
	@cd $(BUILD_DIR) && xvfb-run -a -s "-screen 0 1920x1080x24" \
	  ctest --output-on-failure --parallel $(JOBS)

install: build
	@cmake --install $(BUILD_DIR)

format:
	@find Common Filters IO Rendering Testing Examples -name '*.h' -o -name '*.cxx' 2>/dev/null \
	  | xargs clang-format -i --style=file

clean:
	@rm -rf $(BUILD_DIR)
