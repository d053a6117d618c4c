#pragma once
// What the canvas's add-node palette lists: every node type a graph can add, by family,
// the graph's imported subgraphs first (under "subgraphs"), then the registry's types.
#include <string>
#include <string_view>
#include <vector>

#include "core/graph.h"
#include "core/registry.h"

namespace wg::editor {

inline constexpr const char* kSubgraphFamily = "subgraphs";

struct PaletteEntry {
  std::string type;     // what addNode takes: a registered type or an import's name
  std::string family;   // the heading it is listed under
  std::string summary;  // the tooltip: the node's summary, or the subgraph's description and file
};

// The entries whose type name contains `filter`, grouped by family: subgraphs first (in the
// file's order), then the registry's families and types in name order.
std::vector<PaletteEntry> paletteEntries(const Graph& graph, const Registry& registry, std::string_view filter);

}  // namespace wg::editor
