#pragma once
// Writing a graph in the one canonical form that `watergraph fmt` produces.
#include <string>

#include "core/graph.h"

namespace wg {

// The canonical text: fixed key order, 2-space indent, shortest round-trip numbers, a
// container on one line where it fits within 100 columns (core/graph_save.cpp),
// LF line endings, a final newline. saveGraph(parseGraph(saveGraph(g))) == saveGraph(g).
std::string saveGraph(const Graph& graph);

}  // namespace wg
