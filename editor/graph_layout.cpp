#include "editor/graph_layout.h"

#include <map>
#include <string>

namespace wg::editor {

int layoutUnplacedNodes(Graph& graph) {
  // Column = longest chain of node inputs behind a node. Relaxed |nodes| times at most, so
  // a cycle (which compiling reports) cannot loop forever.
  std::map<std::string, int> column;
  for (const auto& n : graph.nodes) column[n.id] = 0;
  for (size_t pass = 0; pass < graph.nodes.size(); ++pass) {
    bool moved = false;
    for (const auto& n : graph.nodes)
      for (const auto& in : n.inputs) {
        if (in.source.kind != InputSource::Kind::NodeOutput || !column.count(in.source.name)) continue;
        int want = column[in.source.name] + 1;
        if (want > column[n.id] && want <= static_cast<int>(graph.nodes.size())) column[n.id] = want, moved = true;
      }
    if (!moved) break;
  }
  std::map<int, int> rows;
  int placed = 0;
  for (auto& n : graph.nodes) {
    int c = column[n.id];
    int row = rows[c]++;
    if (n.editorPosition) continue;
    n.editorPosition = std::array<double, 2>{c * kLayoutColumnWidth, row * kLayoutRowHeight};
    ++placed;
  }
  return placed;
}

}  // namespace wg::editor
