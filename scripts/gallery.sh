#!/usr/bin/env bash
# Renders the gallery (640x360, time 3.5 s, glsl330 on llvmpipe): every example graph from
# above and from a second camera that shows what it is for, and the top-down graph's
# weather presets and debug view from the top-down camera; the buoys float on the graphs
# that move their water. `make demo` writes it to
# out/gallery/; the README shows the copy in docs/images/.
#   scripts/gallery.sh [build-dir] [out-dir] [--tonemap NAME] [--exposure EV]
# (defaults: build, docs/images, each graph's own "view"); the view flags go to every render.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
out=docs/images
view=()
positional=0
while (($#)); do
  case $1 in
    --tonemap | --exposure)
      (($# >= 2)) || { echo "gallery.sh: $1 needs a value" >&2; exit 2; }
      view+=("$1" "$2")
      shift 2 ;;
    *)
      if ((positional == 0)); then build=$1; else out=$1; fi
      positional=$((positional + 1))
      shift ;;
  esac
done
wg=$build/bin/watergraph
mkdir -p "$out"
export MESA_SHADER_CACHE_DISABLE=true
# The graphs whose vertex stage moves the water float the scene's buoys (docs/queries.md).
floating=" ocean open_ocean stylized tutorial_pbr "
render() {  # graph camera [preset]
  local graph=$1 camera=$2 preset=${3:-}
  local name=$graph-$camera${preset:+-$preset}
  local buoys=()
  [[ $floating == *" $graph "* ]] && buoys=(--buoys)
  "$wg" render "graphs/$graph.json" -o "$out/$name.png" --size 640x360 --camera "$camera" --time 3.5 \
    ${preset:+--preset "$preset"} ${buoys[@]+"${buoys[@]}"} ${view[@]+"${view[@]}"}
  echo "wrote $out/$name.png"
}
for g in lake shelf classic_webgl tutorial_pbr stylized ocean pool river lagoon caustic_pool open_ocean; do
  render "$g" above
  render "$g" grazing
done
render deferred_underwater above
render deferred_underwater underwater
render open_ocean grazing storm
for p in calm moderate choppy debug; do render topdown topdown "$p"; done
