#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/) and runs each for a while (docs/robustness.md).
#
#   scripts/fuzz.sh              # each target 60 s (texture and edit_ops half of it)
#   scripts/fuzz.sh 3600         # each target an hour (texture and edit_ops half an hour)
#   scripts/fuzz.sh 600 compile  # one target
#
# Environment:
#   BUILD_DIR  build folder (default build-fuzz: Clang, RelWithDebInfo, ASan + UBSan +
#              coverage, no tests, no runtime; what CI uses). build-asan works too:
#              scripts/sanitize.sh builds the fuzzers into it.
#   JOBS       build jobs (default 2).
#   FUZZ_LANES targets fuzzed side by side (default 1; CI uses 2, one per core), each
#              one libFuzzer process; the order of the list is kept within a lane.
#   FUZZ_ARGS  extra libFuzzer flags, e.g. "-jobs=8 -workers=8" for a long run.
# The working corpus grows in $BUILD_DIR/fuzz/corpus/<target>/ and is kept between runs;
# it starts from the minimised corpus kept in tests/fuzz/corpus/<target>/ and, for the JSON
# targets, graphs/, tests/bad/ and tests/fuzz/regressions/. A crash leaves its input
# in $BUILD_DIR/fuzz/crashes/<target>/ and makes the script exit 1: add the input to
# tests/fuzz/regressions/ (replayed by the test suite) and fix the cause.
# Prints one line per target: executions, corpus size, crashes.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
SECONDS_EACH=${1:-60}
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=(loader compile graphgen texture edit_ops formula imports function_file)
BUILD_DIR=${BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}

if [ ! -f "$BUILD_DIR/CMakeCache.txt" ] || ! grep -q '^WG_BUILD_FUZZERS:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
  scripts/setup.sh
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" -DWG_BUILD_FUZZERS=ON -DWG_BUILD_TESTS=OFF -DWG_BUILD_RUNTIME=OFF >/dev/null
fi
build_targets=(wg_fuzz_dict)
for t in "${TARGETS[@]}"; do build_targets+=("wg_fuzz_$t"); done
cmake --build "$BUILD_DIR" -j "$JOBS" --target "${build_targets[@]}"

FUZZ_DIR=$ROOT/$BUILD_DIR/fuzz
mkdir -p "$FUZZ_DIR"
"$BUILD_DIR/bin/wg_fuzz_dict" > "$FUZZ_DIR/graph.dict"
"$BUILD_DIR/bin/wg_fuzz_dict" --formula > "$FUZZ_DIR/formula.dict"

# Leaks are bugs here too (the fuzzers load no GL driver). UB aborts (the build makes it fatal).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

# One target's run; leaves its summary line in $FUZZ_DIR/.summary-<target> and, on a crash
# or a non-zero exit, the marker $FUZZ_DIR/.failed-<target>.
fuzz_one() {
  set +e  # a lane reports its failure through the marker, never by dying half-way
  local t=$1
  rm -f "$FUZZ_DIR/.summary-$t"
  local corpus=$FUZZ_DIR/corpus/$t
  local crashes=$FUZZ_DIR/crashes/$t
  mkdir -p "$corpus" "$crashes"
  rm -f "$FUZZ_DIR/.failed-$t"
  # Inputs over 64 KiB add little but time; the pipeline target validates with glslang
  # (tens of milliseconds per graph), so its time-out per input is generous.
  local limits
  case $t in
    loader) limits=(-max_len=65536 -timeout=10 -rss_limit_mb=4096) ;;
    compile) limits=(-max_len=16384 -timeout=30 -rss_limit_mb=4096) ;;
    graphgen) limits=(-max_len=2048 -len_control=0 -timeout=30 -rss_limit_mb=4096) ;;
    texture) limits=(-max_len=4096 -timeout=10 -rss_limit_mb=4096) ;;
    edit_ops) limits=(-max_len=1024 -timeout=10 -rss_limit_mb=4096) ;;
    formula) limits=(-max_len=4200 -timeout=30 -rss_limit_mb=4096) ;;
    imports) limits=(-max_len=16384 -timeout=30 -rss_limit_mb=4096) ;;
    function_file) limits=(-max_len=8192 -timeout=30 -rss_limit_mb=4096) ;;
  esac
  # The texture and edit-sequence targets check cheap properties over a small input space,
  # the importer one what the compile target already covers for each file: half the time.
  local seconds=$SECONDS_EACH
  case $t in texture|edit_ops|imports) seconds=$(( (SECONDS_EACH + 1) / 2 )) ;; esac
  local marker=$FUZZ_DIR/.start-$t
  touch "$marker"
  local log=$FUZZ_DIR/$t.log
  echo "fuzz: $t for ${seconds} s (log: $log)"
  # Run inside the corpus folder: relative texture paths in inputs resolve there.
  local seeds=("$ROOT/graphs" "$ROOT/tests/bad" "$ROOT/tests/fuzz/regressions")
  local dict=(-dict="$FUZZ_DIR/graph.dict")
  case $t in graphgen|texture|edit_ops|formula|function_file) seeds=() && dict=() ;; esac  # their inputs are not graph files
  [ "$t" = texture ] && dict=(-dict="$ROOT/tests/fuzz/texture.dict")
  [ "$t" = formula ] && dict=(-dict="$FUZZ_DIR/formula.dict")
  [ -d "$ROOT/tests/fuzz/corpus/$t" ] && seeds+=("$ROOT/tests/fuzz/corpus/$t")
  local rc
  (cd "$corpus" && "$ROOT/$BUILD_DIR/bin/wg_fuzz_$t" "$corpus" ${seeds[@]+"${seeds[@]}"} ${dict[@]+"${dict[@]}"} -max_total_time="$seconds" \
      -artifact_prefix="$crashes/" -print_final_stats=1 "${limits[@]}" ${FUZZ_ARGS:-}) >"$log" 2>&1
  rc=$?
  local execs found size compiled
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  found=$(find "$crashes" -type f -newer "$marker" | wc -l)  # this run's
  size=$(find "$corpus" -type f | wc -l)
  compiled=$(grep -o '[0-9]* compiled for every target' "$log" | tail -1 | grep -o '^[0-9]*' || true)
  printf '%-8s executions %-9s corpus %-6s crashes %s%s (exit %s)\n' "$t" "${execs:-?}" "$size" "$found" \
    "${compiled:+, compiled for every target $compiled}" "$rc" >"$FUZZ_DIR/.summary-$t"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    touch "$FUZZ_DIR/.failed-$t"
    tail -40 "$log" >&2
  fi
}

lanes=${FUZZ_LANES:-1}
for t in "${TARGETS[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$lanes" ]; do wait -n || true; done
  fuzz_one "$t" &
done
wait

status=0
summary=()
for t in "${TARGETS[@]}"; do
  summary+=("$(cat "$FUZZ_DIR/.summary-$t" 2>/dev/null || echo "$t did not finish")")
  if [ -e "$FUZZ_DIR/.failed-$t" ] || [ ! -e "$FUZZ_DIR/.summary-$t" ]; then status=1; fi
done
printf 'fuzz: %s\n' "${summary[@]}"
exit $status
