#pragma once
// The graph behind a node's preview thumbnail (the editor's) and a function graph's preview:
// the same graph with one node output routed to the fragment colour (alpha 1), converted to
// vec3 by nodes the compiler already has:
// a float splats, a vec2 becomes (x, y, 0) through split + combine, a vec4 keeps .xyz.
// The vertex outputs stay, so a displaced surface previews displaced.
#include <optional>
#include <string>

#include "core/graph.h"
#include "core/registry.h"

namespace wg {

// Empty, with *why set, when the output cannot be shown as a colour (a matrix, a sampler,
// an unknown node or port) or the graph does not resolve. The node may be a subgraph
// instance, and the graph a function graph that connects no outputs.
std::optional<Graph> nodeOutputGraph(const Graph& graph, const Registry& registry, const std::string& nodeId,
                                     const std::string& port, std::string* why);

// A function graph that connects no output slots (it needs none to be used as a node
// type) previewed through its interface output number `output` (the first by default),
// the same way; empty, with *why set, for any other graph or an output it does not have.
// One rule for the editor's preview and for validate, compile, render and check of such a
// file (docs/graph-format.md, "A function graph").
std::optional<Graph> interfaceOutputGraph(const Graph& graph, std::string* why, size_t output = 0);

}  // namespace wg
