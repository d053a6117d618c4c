#include "editor/graph_template.h"

#include "core/diagnostic.h"
#include "core/graph_io.h"
#include "core/load_limits.h"

namespace wg::editor {
namespace {

constexpr const char* kNewGraphTemplate = R"({
  "version": 1,
  "name": "new_graph",
  "description": "A new graph: a water colour, and the sky reflected by Fresnel-Schlick.",
  "parameters": {
    "water": {"type": "vec3", "default": [0.05, 0.35, 0.4], "min": 0, "max": 1, "hint": "color", "description": "colour of the water"},
    "sky": {"type": "vec3", "default": [0.55, 0.7, 0.9], "min": 0, "max": 1, "hint": "color", "description": "reflected sky colour"}
  },
  "nodes": [
    {"id": "fresnel", "type": "fresnel", "options": {"model": "schlick"}, "inputs": {"f0": 0.02}, "editor": {"x": 0, "y": 0}},
    {"id": "color", "type": "mix", "inputs": {"a": "$water", "b": "$sky", "t": "fresnel.reflectance"}, "editor": {"x": 260, "y": 0}}
  ],
  "outputs": {"fragment": {"color": "color.out", "alpha": 1}}
})";

}  // namespace

std::string newGraphText(const std::string& name) {
  Diagnostics d;
  auto g = parseGraph(std::string(kNewGraphTemplate), "new_graph.json", d);
  if (!g) return "";  // the template is tested to parse (tests/editor)
  if (!name.empty() && name.size() <= kMaxStringBytes) g->name = name;
  return saveGraph(*g);
}

}  // namespace wg::editor
