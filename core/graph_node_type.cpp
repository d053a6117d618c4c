#include "core/graph_node_type.h"

#include "core/graph_imports.h"
#include "core/node_options.h"

namespace wg {

GraphNodeType nodeTypeOf(const Graph& graph, const Registry& registry, std::string_view type) {
  // An import named like a registered type is an error (WG076); the registry's type wins
  // meanwhile, as it does in resolve.
  if (const NodeSpec* spec = registry.find(type)) return {spec, nullptr};
  return {nullptr, graph.findImport(type)};
}

std::optional<NodePorts> portsOfGraphNode(const Graph& graph, const Registry& registry, const Node& node) {
  GraphNodeType t = nodeTypeOf(graph, registry, node.type);
  if (t.spec) {
    NodePorts ports = portsOfNode(*t.spec, writtenOptions(node));  // an expression's follow from its options
    // A derived input is the node's own (NodeSpec::derive): not a port the graph connects.
    std::erase_if(ports.inputs, [](const PortSpec& p) { return p.derived; });
    return ports;
  }
  if (t.import && t.import->graph) return interfacePorts(*t.import->graph);
  return std::nullopt;
}

}  // namespace wg
