#include "editor/node_preview_graph.h"

#include <algorithm>

#include "core/resolve.h"

namespace wg::editor {
namespace {

InputSource fromNode(const std::string& node, const std::string& port) {
  InputSource s;
  s.kind = InputSource::Kind::NodeOutput;
  s.node = node;
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

}  // namespace

std::optional<Graph> nodeOutputGraph(const Graph& graph, const Registry& registry, const std::string& nodeId,
                                     const std::string& port, std::string* why) {
  Diagnostics diags;
  auto program = resolveGraph(graph, registry, diags);
  if (!program) {
    *why = "the graph does not compile";
    return std::nullopt;
  }
  auto op = std::find_if(program->ops.begin(), program->ops.end(), [&](const Op& o) { return o.nodeId == nodeId; });
  if (op == program->ops.end()) {
    *why = "no node '" + nodeId + "'";
    return std::nullopt;
  }
  int index = op->spec->outputIndex(port);
  if (index < 0) {
    *why = "node '" + nodeId + "' has no output '" + port + "'";
    return std::nullopt;
  }
  Type type = op->outputTypes[static_cast<size_t>(index)];
  Graph g = graph;
  InputSource color = fromNode(nodeId, port);
  if (type == Type::Vec2) {
    Node split, combine;
    split.id = freeId(g, "wg_preview_split");
    split.type = "split";
    split.inputs.push_back({"v", fromNode(nodeId, port), {}});
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
    swizzle.inputs.push_back({"x", fromNode(nodeId, port), {}});
    color = fromNode(swizzle.id, "out");
    g.nodes.push_back(std::move(swizzle));
  } else if (type != Type::Float && type != Type::Vec3) {
    *why = "a " + std::string(typeName(type)) + " output has no colour to show";
    return std::nullopt;
  }
  setOutput(g, OutputSlot::FragmentColor, std::move(color));
  InputSource one;
  one.kind = InputSource::Kind::Literal;
  one.literal = {1.0};
  setOutput(g, OutputSlot::FragmentAlpha, std::move(one));
  return g;
}

}  // namespace wg::editor
