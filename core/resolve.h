#pragma once
// Graph -> Program: node types looked up, options checked and completed, references
// resolved, cycles found, types inferred and checked. Every problem becomes a
// diagnostic naming the node and port; the Program is returned only when there are none.
#include <map>
#include <optional>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/node_output_values.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags);

// The same, listing what every node of the graph resolved to (core/node_output_values.h).
std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags,
                                    NodeOutputValues& nodeOutputs);

}  // namespace wg
