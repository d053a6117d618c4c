#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer
# (docs/robustness.md). Configures build-asan (RelWithDebInfo, Clang), builds, runs ctest.
#
#   scripts/sanitize.sh            # the suite less tests/sanitizer_excluded.txt (says why)
#   SANITIZE_ALL=1 scripts/sanitize.sh   # every test
#   scripts/sanitize.sh -R Loader  # ctest arguments pass through (here: only the loader's)
#
# Environment: BUILD_DIR (default build-asan), JOBS (default 2), SANITIZE_ALL.
# With Clang the same build also holds the fuzz targets (WG_BUILD_FUZZERS=ON adds coverage
# instrumentation), so `BUILD_DIR=build-asan scripts/fuzz.sh` reuses it instead of a
# second instrumented build. Without Clang it falls back to GCC's sanitizers, no fuzzers.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build-asan}
JOBS=${JOBS:-2}

scripts/setup.sh
# The benchmarks are not tests: they are left out of the instrumented build.
cmake_args=(-S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWG_SANITIZE=ON -DWG_BUILD_BENCH=OFF)
# RelWithDebInfo with line tables only: all a sanitizer report needs (file:line in every
# frame), and a much cheaper compile and link than full -g (CI has 2 cores).
if command -v clang++ >/dev/null; then
  cmake_args+=(-DCMAKE_CXX_COMPILER=clang++ -DWG_BUILD_FUZZERS=ON
               "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG")
else
  cmake_args+=("-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
fi
cmake "${cmake_args[@]}" >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"

# Leaks: on, except inside the GL driver stack (tests/robustness/lsan.supp says why).
# intercept_tls_get_addr=0: the runtime's __tls_get_addr interceptor in Debian 12's
# compiler-rt (LLVM 14) takes a dynamic TLS block that lands 16 bytes into a page for a
# pre-2.25 glibc header and reads the words before it; Mesa's driver allocates such blocks,
# and by chance LeakSanitizer's tracer then segfaults at exit ("Tracer caught signal 11")
# in a test that passed (CI, 2026-11-24). LLVM 17 dropped the guess; here it is turned off.
# UBSan: print a stack and fail the test (the build already makes UB fatal).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:intercept_tls_get_addr=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/robustness/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# The tests keep Mesa's shader cache in the build tree (tests/test_support.cpp): emptied
# here, so this run depends only on itself.
rm -rf "$BUILD_DIR/mesa-shader-cache"
cd "$BUILD_DIR"
excluded=()
if [ -z "${SANITIZE_ALL:-}" ]; then
  # One alternation of the file's expressions (comments and blank lines skipped).
  regex=$(grep -v -e '^#' -e '^[[:space:]]*$' ../tests/sanitizer_excluded.txt | paste -sd '|')
  [ -n "$regex" ] && excluded=(-E "$regex")
fi
ctest --output-on-failure -j "$JOBS" --timeout 600 ${excluded[@]+"${excluded[@]}"} "$@"
