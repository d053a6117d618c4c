#include "editor/dissolve_nodes.h"

#include <optional>
#include <set>

#include "core/graph_node_type.h"
#include "editor/function_node_ports.h"

namespace wg::editor {
namespace {

bool isLinked(const InputSource& s) {
  return s.kind == InputSource::Kind::NodeOutput || s.kind == InputSource::Kind::Parameter;
}

const InputSource* writtenSource(const Node& n, const std::string& port) {
  for (const NodeInput& in : n.inputs)
    if (in.port == port) return &in.source;
  return nullptr;
}

// A reader (node input, output slot, interface output) of a removed node: the source the
// chain of removed pass-throughs leads to, or nothing when it is broken somewhere.
std::optional<InputSource> followThroughRemoved(const Graph& g, const Registry& registry, const std::set<std::string>& gone,
                                                InputSource source) {
  // Each step moves to a node upstream; a graph is acyclic, so at most |gone| steps.
  for (size_t step = 0; step <= gone.size(); ++step) {
    if (source.kind != InputSource::Kind::NodeOutput || !gone.count(source.name)) return source;
    std::optional<InputSource> up = passThroughSource(g, registry, source.name, source.port);
    if (!up) return std::nullopt;
    source = *up;
  }
  return std::nullopt;
}

}  // namespace

std::optional<InputSource> passThroughSource(const Graph& graph, const Registry& registry, const std::string& id,
                                             const std::string& port) {
  const Node* n = graph.findNode(id);
  if (!n) return std::nullopt;
  std::optional<NodePorts> ports = editorPortsOf(graph, registry, *n);
  if (!ports) return std::nullopt;
  const PortSpec* out = nullptr;
  for (const PortSpec& p : ports->outputs)
    if (p.name == port) out = &p;
  if (!out || out->kind == PortKind::Custom) return std::nullopt;
  const InputSource* found = nullptr;
  int matches = 0;
  for (const PortSpec& in : ports->inputs) {
    if (in.kind != out->kind || (in.kind == PortKind::Fixed && in.type != out->type)) continue;
    const InputSource* s = writtenSource(*n, in.name);
    if (s && isLinked(*s)) {
      found = s, ++matches;
    } else if (s && out->kind == PortKind::Gen && s->literal.size() > 1) {
      return std::nullopt;  // a vector constant on a generic input decides the output's width
    }
  }
  if (matches != 1) return std::nullopt;
  InputSource copy = *found;
  copy.where = {};
  return copy;
}

std::string dissolveNodes(GraphEditor& editor, const Registry& registry, const std::vector<std::string>& ids,
                          int* reconnected) {
  const Graph& before = editor.graph();
  for (const auto& id : ids)
    if (!before.findNode(id)) return "no node '" + id + "'";
  if (ids.empty()) return "nothing selected to delete";
  std::set<std::string> gone(ids.begin(), ids.end());
  Graph after = before;
  int count = 0;
  auto reconnect = [&](InputSource& s) {
    if (s.kind != InputSource::Kind::NodeOutput || !gone.count(s.name)) return;
    if (std::optional<InputSource> up = followThroughRemoved(before, registry, gone, s)) {
      up->where = s.where;
      s = std::move(*up);
      ++count;
    }
  };
  for (Node& n : after.nodes) {
    if (gone.count(n.id)) continue;
    for (NodeInput& in : n.inputs) reconnect(in.source);
  }
  for (GraphOutput& o : after.outputs) reconnect(o.source);
  if (after.interface)
    for (InterfaceOutput& o : after.interface->outputs) reconnect(o.source);
  // What is still not reconnected goes as plain Delete takes it (core/graph_edit.h).
  GraphEditor removal(std::move(after), &registry);
  if (std::string why = removal.deleteNodes(ids); !why.empty()) return why;
  std::string label = ids.size() == 1 ? "delete node '" + ids[0] + "' with reconnection"
                                      : "delete " + std::to_string(ids.size()) + " nodes with reconnection";
  editor.replace(removal.graph(), label);
  if (reconnected) *reconnected = count;
  return "";
}

}  // namespace wg::editor
