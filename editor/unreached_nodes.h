#pragma once
// Half-wired graphs: a node the graph's outputs do not reach is pruned by the compiler
// anyway, so the editor compiles the graph without it. Otherwise one node just added from
// the palette, whose required inputs are not wired yet, would make the whole graph WG023
// and freeze the preview and every thumbnail until it is. Its unconnected required inputs
// are warnings instead, drawn on the node; once an output reaches it, it is compiled and
// they are errors again.
#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/registry.h"

namespace wg::editor {

// Removes from `graph` every node that neither an output slot, an interface output nor one
// of `alsoKeep` (node ids: a thumbnail's node) reaches through links. Returns one WG023
// warning per required input left unconnected on a removed node, in node order. The
// graph's frames go too (compiling ignores them).
std::vector<Diagnostic> pruneUnreachedNodes(Graph& graph, const Registry& registry,
                                            const std::vector<std::string>& alsoKeep = {});

}  // namespace wg::editor
