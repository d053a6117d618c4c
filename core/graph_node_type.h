#pragma once
// What a node of a graph is as a node type: a type of the registry, or an instance of a
// function graph the graph imports (docs/graph-format.md, "Subgraphs"). Resolve, the edit
// model and the editor's canvas, inspector and palette all look a node's type up here, so
// they agree on which name means what: the registry first, then the graph's imports.
#include <optional>
#include <string_view>

#include "core/graph.h"
#include "core/node_spec.h"
#include "core/registry.h"

namespace wg {

struct GraphNodeType {
  const NodeSpec* spec = nullptr;  // a registered type
  const Import* import = nullptr;  // else an import of that name (its graph null when it did not load)
  bool isInstance() const { return import != nullptr; }
  explicit operator bool() const { return spec || import; }
};

GraphNodeType nodeTypeOf(const Graph& graph, const Registry& registry, std::string_view type);

// The node's ports: a registered type's (an expression's follow from its options), or an
// instance's, from the imported graph's interface (interfacePorts). Empty when the type
// is unknown or its import did not load: nothing is known about its ports then.
std::optional<NodePorts> portsOfGraphNode(const Graph& graph, const Registry& registry, const Node& node);

}  // namespace wg
