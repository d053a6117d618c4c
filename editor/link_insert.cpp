#include "editor/link_insert.h"

#include <optional>

#include "core/graph_node_type.h"
#include "editor/function_node_ports.h"

namespace wg::editor {
namespace {

// What feeds `target` in `g`, when it is a node output.
std::optional<InputSource> linkSource(const Graph& g, const InputTarget& target) {
  const InputSource* s = nullptr;
  if (target.node.empty()) {
    if (auto slot = parseOutputSlot(target.port))
      for (const GraphOutput& o : g.outputs)
        if (o.slot == *slot) s = &o.source;
  } else if (const Node* n = g.findNode(target.node)) {
    for (const NodeInput& in : n->inputs)
      if (in.port == target.port) s = &in.source;
  }
  if (!s || s->kind != InputSource::Kind::NodeOutput) return std::nullopt;
  return *s;
}

// The port of the node's output `port`, when its type is known without compiling.
std::optional<PortSpec> outputSpec(const Graph& g, const Registry& registry, const std::string& node, const std::string& port) {
  const Node* n = g.findNode(node);
  std::optional<NodePorts> ports = n ? editorPortsOf(g, registry, *n) : std::nullopt;
  if (ports)
    for (const PortSpec& p : ports->outputs)
      if (p.name == port) return p;
  return std::nullopt;
}

}  // namespace

std::string insertNodeOnLink(GraphEditor& editor, const Registry& registry, const std::string& type, const InputTarget& target,
                             std::array<double, 2> position, std::string* usedId) {
  std::optional<InputSource> source = linkSource(editor.graph(), target);
  if (!source) return "no link feeds " + (target.node.empty() ? "output '" + target.port + "'" : "input '" + target.node + "." + target.port + "'");
  // The three edits on a scratch editor, then one undo step on the real one.
  GraphEditor scratch(editor.graph(), &registry);
  std::string id;
  if (std::string why = scratch.addNode(type, "", position, &id); !why.empty()) return why;
  std::optional<NodePorts> ports = editorPortsOf(scratch.graph(), registry, *scratch.graph().findNode(id));
  if (!ports || ports->inputs.empty() || ports->outputs.empty()) return "a '" + type + "' node has no input or no output to put in a link";
  std::optional<PortSpec> from = outputSpec(editor.graph(), registry, source->name, source->port);
  const PortSpec* in = nullptr;
  if (from && from->kind == PortKind::Fixed)
    for (const PortSpec& p : ports->inputs)
      if (!in && p.kind == PortKind::Fixed && p.type == from->type) in = &p;
  for (const PortSpec& p : ports->inputs)
    if (!in && p.kind == PortKind::Gen) in = &p;
  if (!in) in = &ports->inputs.front();
  if (std::string why = scratch.connect(source->name, source->port, {id, in->name}); !why.empty()) return why;
  if (std::string why = scratch.connect(id, ports->outputs.front().name, target); !why.empty()) return why;
  editor.replace(scratch.graph(), "insert a " + type + " node '" + id + "' into a link");
  if (usedId) *usedId = id;
  return "";
}

}  // namespace wg::editor
