# A thin layer over CMake. `make demo` and `make test` each do all set-up on a fresh
# Debian 12 machine (missing packages, configure, Release build) and then their job.
BUILD_DIR ?= build
JOBS      ?= $(shell nproc)
WG        := $(BUILD_DIR)/bin/watergraph
GRAPHS    := $(sort $(wildcard graphs/*.json))

.PHONY: all setup configure build demo test clean sanitize fuzz

all: build

setup:
	@scripts/setup.sh

configure: setup
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Compile every example graph for every target into out/<graph>/, validate each
# shader with glslang and print a summary table; then render each graph's preview
# (1280x720, camera above, headless on llvmpipe) into out/<graph>.png, and the README's
# gallery (scripts/gallery.sh) into out/gallery/.
demo: build
	@$(WG) compile $(GRAPHS) -o out --subdirs --summary
	@for g in $(GRAPHS); do n=$$(basename $$g .json); \
	  MESA_SHADER_CACHE_DISABLE=true $(WG) render $$g -o out/$$n.png --stats || exit $$?; \
	  echo "wrote out/$$n.png"; done
	@scripts/gallery.sh $(BUILD_DIR) out/gallery

test: build
	@rm -rf $(BUILD_DIR)/mesa-shader-cache  # the tests' shader cache (tests/test_support.cpp): a run depends only on itself
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The whole test suite under ASan + UBSan in build-asan (docs/robustness.md).
sanitize:
	@scripts/sanitize.sh

# Each libFuzzer target for FUZZ_SECONDS (default 60) in build-fuzz (docs/robustness.md).
FUZZ_SECONDS ?= 60
fuzz:
	@scripts/fuzz.sh $(FUZZ_SECONDS)

clean:
	@rm -rf $(BUILD_DIR) out
