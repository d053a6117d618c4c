#pragma once
// Places the nodes a graph file gives no canvas position ("editor": {x, y}): in columns by
// their distance from the graph's inputs, so data flows left to right, in file order
// within a column. Deterministic; nodes that have a position keep it.
#include "core/graph.h"

namespace wg::editor {

inline constexpr double kLayoutColumnWidth = 230;
inline constexpr double kLayoutRowHeight = 150;

// Returns the number of nodes placed.
int layoutUnplacedNodes(Graph& graph);

}  // namespace wg::editor
