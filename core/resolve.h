#pragma once
// Graph -> Program: node types looked up, options checked and completed, references
// resolved, cycles found, types inferred and checked. Every problem becomes a
// diagnostic naming the node and port; the Program is returned only when there are none.
#include <map>
#include <optional>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags);

// One output of a node as the resolved program holds it: an op's output, or the value an
// expanded node's output stands for (an expression's `out`). Invalid type: the output
// does not exist for the node's input types (split.w of a vec3).
struct NodeOutputValue {
  std::string port;
  ValueRef value;
  Type type = Type::Invalid;
};
// By node id, every output of every node that resolved: what a probe of "node.port" reads.
// Indices are those of the program resolve returns, before any pass renumbers its ops.
using NodeOutputValues = std::map<std::string, std::vector<NodeOutputValue>, std::less<>>;

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags,
                                    NodeOutputValues& nodeOutputs);

}  // namespace wg
