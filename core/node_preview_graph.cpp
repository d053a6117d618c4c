#include "core/node_preview_graph.h"

#include <algorithm>

#include "core/resolve.h"

namespace wg {
namespace {

InputSource fromNode(const std::string& node, const std::string& port) {
  InputSource s;
  s.kind = InputSource::Kind::NodeOutput;
  s.name = node;
  s.port = port;
  return s;
}

std::string freeId(const Graph& g, const std::string& base) {
  std::string id = base;
  for (int k = 2; g.findNode(id); ++k) id = base + "_" + std::to_string(k);
  return id;
}

void setOutput(Graph& g, OutputSlot slot, InputSource source) {
  std::erase_if(g.outputs, [&](const GraphOutput& o) { return o.slot == slot; });
  GraphOutput o;
  o.slot = slot;
  o.source = std::move(source);
  g.outputs.push_back(std::move(o));
}

void setOpaque(Graph& g) {
  InputSource one;
  one.kind = InputSource::Kind::Literal;
  one.literal = {1.0};
  setOutput(g, OutputSlot::FragmentAlpha, std::move(one));
}

// Routes `value` (of `type`) to the fragment colour of `g`, converted to vec3.
bool routeToColour(Graph& g, InputSource value, Type type, std::string* why) {
  InputSource color = value;
  if (type == Type::Vec2) {
    Node split, combine;
    split.id = freeId(g, "wg_preview_split");
    split.type = "split";
    split.inputs.push_back({"v", value, {}});
    combine.id = freeId(g, "wg_preview_combine");
    combine.type = "combine";
    combine.inputs.push_back({"x", fromNode(split.id, "x"), {}});
    combine.inputs.push_back({"y", fromNode(split.id, "y"), {}});
    color = fromNode(combine.id, "out");
    g.nodes.push_back(std::move(split));
    g.nodes.push_back(std::move(combine));
  } else if (type == Type::Vec4) {
    Node swizzle;
    swizzle.id = freeId(g, "wg_preview_xyz");
    swizzle.type = "swizzle";
    swizzle.options.push_back({"mask", "xyz", {}, {}});
    swizzle.inputs.push_back({"x", value, {}});
    color = fromNode(swizzle.id, "out");
    g.nodes.push_back(std::move(swizzle));
  } else if (type != Type::Float && type != Type::Vec3) {
    *why = "a " + std::string(typeName(type)) + " output has no colour to show";
    return false;
  }
  setOutput(g, OutputSlot::FragmentColor, std::move(color));
  return true;
}

}  // namespace

std::optional<Graph> nodeOutputGraph(const Graph& graph, const Registry& registry, const std::string& nodeId,
                                     const std::string& port, std::string* why) {
  // Opaque first: the preview is, and a function graph that connects no outputs then
  // resolves too.
  Graph g = graph;
  setOpaque(g);
  Diagnostics diags;
  NodeOutputValues outputs;  // every node's, an instance's and an expression's included
  if (!resolveGraph(g, registry, diags, outputs)) {
    *why = "the graph does not compile";
    return std::nullopt;
  }
  auto node = outputs.find(nodeId);
  if (node == outputs.end()) {
    *why = "no node '" + nodeId + "'";
    return std::nullopt;
  }
  auto value = std::find_if(node->second.begin(), node->second.end(), [&](const NodeOutputValue& v) { return v.port == port; });
  if (value == node->second.end()) {
    *why = "node '" + nodeId + "' has no output '" + port + "'";
    return std::nullopt;
  }
  if (!routeToColour(g, fromNode(nodeId, port), value->type, why)) return std::nullopt;
  return g;
}

std::optional<Graph> interfaceOutputGraph(const Graph& graph, std::string* why, size_t output) {
  if (!graph.interface || graph.interface->outputs.size() <= output || !graph.outputs.empty()) {
    *why = "not a function graph without output slots";
    return std::nullopt;
  }
  const InterfaceOutput& first = graph.interface->outputs[output];
  Graph g = graph;
  setOpaque(g);
  if (!routeToColour(g, first.source, first.type, why)) return std::nullopt;
  return g;
}

}  // namespace wg
