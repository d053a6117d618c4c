#!/usr/bin/env bash
# Seed 004 asks that crest foam, ripples and colour variation cost no noticeable frame
# time. This renders graphs/topdown.json with them (its defaults, = the moderate preset)
# and without (--preset plain, which compiles them out) side by side: ROUNDS interleaved
# rounds of FRAMES timed frames each at 1280x720 from the top-down camera, and prints the
# median of each round's median frame time and their ratio as a markdown table.
#   bench/topdown_cost.sh [build-dir] [rounds] [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
wg=${1:-build}/bin/watergraph
rounds=${2:-7}
frames=${3:-10}
export MESA_SHADER_CACHE_DISABLE=true
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
median_ms() {  # args to render; prints the median frame time in ms
  "$wg" render graphs/topdown.json -o "$tmp/f.png" --size 1280x720 --camera topdown --frames "$frames" --stats "$@" |
    sed -n 's/^frame time: median \([0-9.]*\) ms.*/\1/p'
}
full=() plain=()
for ((i = 0; i < rounds; i++)); do
  full+=("$(median_ms)")
  plain+=("$(median_ms --preset plain)")
done
python3 - "${full[*]}" "${plain[*]}" "$rounds" "$frames" <<'PY'
import statistics, sys
full = [float(x) for x in sys.argv[1].split()]
plain = [float(x) for x in sys.argv[2].split()]
f, p = statistics.median(full), statistics.median(plain)
print(f"| topdown (1280x720, camera topdown, {sys.argv[3]} rounds x {sys.argv[4]} frames) | median ms/frame |")
print("|---|---|")
print(f"| with foam, ripples, colour variation (defaults) | {f:.1f} |")
print(f"| without (--preset plain) | {p:.1f} |")
print(f"| ratio with / without | {f / p:.2f} |")
PY
