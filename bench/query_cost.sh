#!/usr/bin/env bash
# Surface-query cost (issue 42): compiles GRAPH's query header (compile --target query-c),
# builds bench/query_bench.c against it with CC -O2 and prints height and displace queries
# per second on one core; for a spectral ocean (open_ocean) also the state's init and update.
#   bench/query_cost.sh [build-dir] [graph] [queries] [cc]
set -euo pipefail
cd "$(dirname "$0")/.."
wg=${1:-build}/bin/watergraph
graph=${2:-graphs/ocean.json}
n=${3:-2000000}
cc=${4:-cc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$wg" compile "$graph" -o "$tmp" --target glsl330,query-c -q
name=$(basename "$graph" .json)
prefix=$(sed -n 's/^static inline double \(wg_[A-Za-z0-9_]*\)_height(.*/\1/p' "$tmp/$name.query.h")
ocean=$(grep -q "^static inline void ${prefix}_ocean_init(" "$tmp/$name.query.h" && echo -DQUERY_OCEAN || true)
"$cc" -std=gnu99 -O2 -I"$tmp" -DQUERY_HEADER="\"$name.query.h\"" -D"QUERY(f)=${prefix}_##f" $ocean \
  bench/query_bench.c -o "$tmp/query_bench" -lm
echo "$graph ($("$cc" --version | head -1), -O2, $n queries each):"
taskset -c 0 "$tmp/query_bench" "$n" 2>/dev/null || "$tmp/query_bench" "$n"
