#include "editor/node_palette.h"

#include <map>

#include "core/graph_node_type.h"

namespace wg::editor {

std::vector<PaletteEntry> paletteEntries(const Graph& graph, const Registry& registry, std::string_view filter) {
  std::vector<PaletteEntry> out;
  for (const Import& im : graph.imports) {
    // An import named like a registered type is that type here (and WG076): not listed twice.
    if (im.name.find(filter) == std::string::npos || !nodeTypeOf(graph, registry, im.name).isInstance()) continue;
    std::string about = "did not load (see the errors)";
    if (im.graph) about = im.graph->interface && !im.graph->interface->description.empty() ? im.graph->interface->description : "a subgraph";
    out.push_back({im.name, kSubgraphFamily, about + "\n" + im.path});
  }
  std::map<std::string, std::vector<const NodeSpec*>> families;
  for (const NodeSpec* spec : registry.all())
    if (spec->type.find(filter) != std::string::npos) families[spec->family].push_back(spec);
  for (const auto& [family, specs] : families)
    for (const NodeSpec* spec : specs) out.push_back({spec->type, family, spec->summary});
  return out;
}

}  // namespace wg::editor
