#!/usr/bin/env bash
# The screenshots in docs/editor.md, made by the editor's own script mode under a virtual X
# server (xvfb-run): the canvas framed with a half-wired node and a box selection, the
# palette filtered with Enter's entry highlighted, the blackboard, the palette opened on a
# link, an expression's input list, the texture picker and frames. 1600x900 windows, the preview at 640x360.
#   scripts/editor_screenshots.sh [build-dir] [out-dir]   (defaults: build, docs/images)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-docs/images}
editor=$build/bin/watergraph-editor
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export MESA_SHADER_CACHE_DISABLE=true
cp graphs/lake.json "$work/lake.json"

shoot() {  # name steps-json
  printf '%s\n' "$2" > "$work/steps.json"
  cp graphs/lake.json "$work/lake.json"
  cp graphs/lagoon_ripples.png "$work/lagoon_ripples.png"
  xvfb-run -a -s '-screen 0 1600x1024x24' "$editor" "$work/lake.json" --size 1600x900 --time 3.5 \
    --script "$work/steps.json" --screenshot "$out/$1.png" > /dev/null
  echo "wrote $out/$1.png"
}

# The canvas: everything framed (Home), a haze node added and not wired yet (its required
# inputs in orange, the preview live), three nodes box-selected, the minimap in the corner.
shoot editor-canvas '[
  {"op": "add_node", "type": "haze", "id": "haze", "x": 700, "y": 330},
  {"op": "frames", "count": 1},
  {"op": "hover", "widget": "canvas"},
  {"op": "key", "key": "home"},
  {"op": "frames", "count": 1},
  {"op": "drag", "widget": "canvas", "from": [0.25, 0.2], "to": [0.62, 0.45]},
  {"op": "frames", "count": 2}
]'

# The palette, opened on the background, filtered by "mix", Down pressed once.
shoot editor-palette '[
  {"op": "frames", "count": 1},
  {"op": "click", "widget": "canvas", "at": [0.55, 0.75], "button": "right"},
  {"op": "type", "text": "mix"},
  {"op": "key", "key": "down"},
  {"op": "frames", "count": 2}
]'

# The blackboard: a parameter added, a preset saved, and max_depth's right-click menu with a
# clashing name refused in place.
shoot editor-blackboard '[
  {"op": "add_parameter", "name": "glint", "type": "float", "default": 0.02, "min": 0, "max": 1},
  {"op": "create_preset", "name": "glassy"},
  {"op": "frames", "count": 1},
  {"op": "click", "widget": "parameter max_depth", "button": "right"},
  {"op": "frames", "count": 1},
  {"op": "click", "widget": "blackboard field"},
  {"op": "type", "text": "deep"},
  {"op": "click", "widget": "blackboard button"},
  {"op": "frames", "count": 2}
]'

# Insert into a link: right-click the link from radius to shore, type part of a name; Enter
# would put the highlighted node into the link.
shoot editor-insert-link '[
  {"op": "frames", "count": 1},
  {"op": "hover", "widget": "canvas"},
  {"op": "key", "key": "home"},
  {"op": "frames", "count": 1},
  {"op": "click", "widget": "link shore.x", "button": "right"},
  {"op": "type", "text": "satur"},
  {"op": "frames", "count": 2}
]'

# An expression's inputs as a list (t renamed t_mix: the formula followed).
shoot editor-expression-inputs '[
  {"op": "add_node", "type": "expression", "id": "blend", "x": 700, "y": 330},
  {"op": "set_option", "node": "blend", "name": "formula", "value": "mix(a, b, t)"},
  {"op": "set_option", "node": "blend", "name": "inputs", "value": {"a": "vec3", "b": "vec3", "t": "float"}},
  {"op": "rename_input", "node": "blend", "name": "t", "to": "t_mix"},
  {"op": "select", "node": "blend"},
  {"op": "frames", "count": 2}
]'

# The texture picker of a texture_sample node, open over the graph folder's PNG files.
shoot editor-texture-picker '[
  {"op": "add_node", "type": "texture_sample", "id": "ripples", "x": 700, "y": 330},
  {"op": "choose_texture", "node": "ripples", "option": "texture", "path": "lagoon_ripples.png"},
  {"op": "select", "node": "ripples"},
  {"op": "frames", "count": 2},
  {"op": "click", "widget": "texture picker texture"},
  {"op": "frames", "count": 2}
]'

# Frames: "Shore" around the nodes that make the shore mask, with a two-line comment, and
# "Colour", its nodes selected; one zoom step in about the frames.
shoot editor-frames '[
  {"op": "add_frame", "id": "shore", "title": "Shore", "comment": "distance from the centre, as a depth:\nshallow near the rim", "nodes": ["from_centre", "radius", "shore"]},
  {"op": "add_frame", "id": "colour", "title": "Colour", "comment": "the depth tints the water from shallow to deep", "nodes": ["depth", "tint"]},
  {"op": "frames", "count": 1},
  {"op": "hover", "widget": "canvas"},
  {"op": "key", "key": "home"},
  {"op": "frames", "count": 1},
  {"op": "hover", "widget": "node shore"},
  {"op": "key", "key": "="},
  {"op": "frames", "count": 1},
  {"op": "click", "widget": "frame colour"},
  {"op": "frames", "count": 2}
]'
