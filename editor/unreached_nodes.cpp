#include "editor/unreached_nodes.h"

#include <algorithm>
#include <set>

#include "core/graph_node_type.h"
#include "editor/function_node_ports.h"

namespace wg::editor {

std::vector<Diagnostic> pruneUnreachedNodes(Graph& graph, const Registry& registry,
                                            const std::vector<std::string>& alsoKeep) {
  std::set<std::string> reached;
  std::vector<std::string> pending(alsoKeep.begin(), alsoKeep.end());
  auto follow = [&](const InputSource& s) {
    if (s.kind == InputSource::Kind::NodeOutput) pending.push_back(s.name);
  };
  for (const GraphOutput& o : graph.outputs) follow(o.source);
  if (graph.interface)
    for (const InterfaceOutput& o : graph.interface->outputs) follow(o.source);
  // Walk upstream. A node id may be written twice (resolve reports it): every node of a
  // reached id stays, so that the compiler still sees and reports the duplicate.
  while (!pending.empty()) {
    std::string id = std::move(pending.back());
    pending.pop_back();
    if (!reached.insert(id).second) continue;
    for (const Node& n : graph.nodes)
      if (n.id == id)
        for (const NodeInput& in : n.inputs) follow(in.source);
  }

  std::vector<Diagnostic> warnings;
  for (const Node& n : graph.nodes) {
    if (reached.count(n.id)) continue;
    // An unknown type or an import that did not load: nothing is known of its ports.
    std::optional<NodePorts> ports = editorPortsOf(graph, registry, n);
    if (!ports) continue;
    for (const PortSpec& port : ports->inputs) {
      if (!port.required()) continue;
      bool given = std::any_of(n.inputs.begin(), n.inputs.end(), [&](const NodeInput& in) { return in.port == port.name; });
      if (given) continue;
      Diagnostic d;
      d.code = DiagCode::MissingInput;
      d.severity = Severity::Warning;
      d.where = n.where;
      d.node = n.id;
      d.port = "input '" + port.name + "'";
      d.message = "required input '" + port.name + "' of " + n.type +
                  " is not connected; no output reaches the node yet, so it is not compiled";
      warnings.push_back(std::move(d));
    }
  }
  std::erase_if(graph.nodes, [&](const Node& n) { return !reached.count(n.id); });
  // What is compiled has no layout: a frame may hold a node just removed, and the text of
  // this graph must still load.
  graph.frames.clear();
  return warnings;
}

}  // namespace wg::editor
