#!/bin/sh
# The hard-case suite through the CLI, per target: every node type with
# tests/hardcases/suite.json, its option variants and its own hard cases
# (`watergraph probe --node TYPE --variants --json`, as tests/accuracy runs the suite),
# summed into one line: case runs, failures, NaN/Inf, the largest error on the scale of the
# tolerance (|gpu - ref| / max(1, |ref|), of the component closest to its bound) and the
# largest error/bound. vk450 runs under the Khronos validation layer. The figures in
# docs/accuracy.md ("The hard-case suite"). Not part of CI (the gtests run the suite).
# Usage, from the repository root:
#   scripts/hard_case_figures.sh [path/to/watergraph [TARGET...]]
#       (default build/bin/watergraph; targets glsl330 es300 vk450)
set -eu
wg=${1:-build/bin/watergraph}
[ $# -gt 0 ] && shift
targets=${*:-glsl330 es300 vk450}
nodes=$("$wg" nodes --json | python3 -c 'import json, sys; print(" ".join(n["type"] for n in json.load(sys.stdin)))')
for target in $targets; do
  validation=""
  [ "$target" = vk450 ] && validation=--vk-validation
  for node in $nodes; do
    # Exit 1 is a failure, which the JSON carries; the sum below counts it.
    "$wg" probe --node "$node" --cases tests/hardcases/suite.json --variants --json --target "$target" $validation \
      2>/dev/null || true
  done | python3 -c '
import json, math, sys
text, at, runs = sys.stdin.read(), 0, []
decoder = json.JSONDecoder()
while True:
    while at < len(text) and text[at].isspace():
        at += 1
    if at == len(text):
        break
    value, at = decoder.raw_decode(text, at)
    runs += value
def num(x):
    return float(x) if not isinstance(x, str) else float("inf")
cases = [c for r in runs for c in r["cases"]]
failed = sum(not c["passed"] for c in cases)
naninf = sum(c["gpu_nan_inf"] or c["reference_nan_inf"] for c in cases)
finite = [c for c in cases if not (c["gpu_nan_inf"] or c["reference_nan_inf"])]
# |gpu - ref| / max(1, |ref|): the absolute error below 1, the relative error above.
worst_scaled = max((min(num(c["abs_error"]), num(c["rel_error"])) for c in finite), default=0)
worst_ratio = max((num(c["abs_error"]) / num(c["bound"]) if num(c["bound"]) > 0 else (0 if num(c["abs_error"]) == 0 else math.inf)
                   for c in finite), default=0)
print("%-8s %5d probe runs %6d case runs %3d failed %3d NaN/Inf  max error %.3g  worst error/bound %.3g"
      % (sys.argv[1], len(runs), len(cases), failed, naninf, worst_scaled, worst_ratio))
' "$target"
done
