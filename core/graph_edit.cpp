#include "core/graph_edit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/graph_node_type.h"
#include "core/load_limits.h"
#include "core/node_options.h"
#include "core/number_format.h"
#include "core/preset.h"

namespace wg {
namespace {

std::string describe(const InputTarget& t) {
  return t.node.empty() ? "output '" + t.port + "'" : "input '" + t.port + "' of node '" + t.node + "'";
}

// What the loader accepts of a number: finite in float32 (a double that is not would be
// saved, and the saved file refused with WG010).
bool allFitFloat32(const std::vector<double>& v) { return std::all_of(v.begin(), v.end(), fitsFloat32); }

bool positionFits(const std::array<double, 2>& p) { return fitsFloat32(p[0]) && fitsFloat32(p[1]); }

}  // namespace

GraphEditor::GraphEditor(Graph graph, const Registry* registry) : graph_(std::move(graph)), registry_(registry) {}

void GraphEditor::record(const std::string& label, const std::string& mergeKey) {
  bool merge = !mergeKey.empty() && mergeKey == mergeKey_ && !undo_.empty() && redo_.empty();
  if (!merge) undo_.push_back({graph_, revision_, label});
  redo_.clear();
  mergeKey_ = mergeKey;
  revision_ = nextRevision_++;
}

Node* GraphEditor::findNode(const std::string& id) {
  for (auto& n : graph_.nodes)
    if (n.id == id) return &n;
  return nullptr;
}

std::string GraphEditor::checkTarget(const InputTarget& target) const {
  if (target.node.empty()) {
    if (!parseOutputSlot(target.port)) {
      std::string slots;
      for (const auto& row : outputSlotTable()) slots.append(slots.empty() ? "" : ", ").append(row.name);
      return "no output slot '" + target.port + "' (" + slots + ")";
    }
    return "";
  }
  const Node* n = graph_.findNode(target.node);
  if (!n) return "no node '" + target.node + "'";
  if (!isIdentifier(target.port)) return "'" + target.port + "' is not an input name";
  // A file node's ports come from its file (a glsl_function's .glsl), which the edit model
  // does not read: compiling checks them, at the node and port.
  if (registry_ && !registry_->fileNodeType(n->type))
    if (auto ports = portsOfGraphNode(graph_, *registry_, *n); ports && ports->inputIndex(target.port) < 0)
      return "node '" + target.node + "' (" + n->type + ") has no input '" + target.port + "'";
  return "";
}

void GraphEditor::setSource(const InputTarget& target, InputSource source) {
  source.where.file = graph_.file;
  if (target.node.empty()) {
    OutputSlot slot = *parseOutputSlot(target.port);
    for (auto& o : graph_.outputs)
      if (o.slot == slot) {
        o.source = std::move(source);
        return;
      }
    GraphOutput o;
    o.slot = slot;
    o.source = std::move(source);
    o.keyWhere.file = graph_.file;
    graph_.outputs.push_back(std::move(o));
    return;
  }
  Node* n = findNode(target.node);
  for (auto& in : n->inputs)
    if (in.port == target.port) {
      in.source = std::move(source);
      return;
    }
  NodeInput in;
  in.port = target.port;
  in.source = std::move(source);
  in.keyWhere.file = graph_.file;
  n->inputs.push_back(std::move(in));
}

std::string GraphEditor::setParameterDefault(const std::string& name, const std::vector<double>& value) {
  auto it = std::find_if(graph_.parameters.begin(), graph_.parameters.end(),
                         [&](const Parameter& p) { return p.name == name; });
  if (it == graph_.parameters.end()) return "no parameter '" + name + "'";
  size_t n = static_cast<size_t>(componentCount(it->type));
  if (value.size() != n)
    return "parameter '" + name + "' is a " + std::string(typeName(it->type)) + ": it takes " + std::to_string(n) +
           " number(s), not " + std::to_string(value.size());
  if (!allFitFloat32(value)) return "parameter '" + name + "': values must be finite in float32 range";
  for (double x : value) {
    if (it->min && x < *it->min) return "parameter '" + name + "': " + formatNumber(x) + " is below its min " + formatNumber(*it->min);
    if (it->max && x > *it->max) return "parameter '" + name + "': " + formatNumber(x) + " is above its max " + formatNumber(*it->max);
  }
  if (it->defaultValue == value) return "";
  record("set parameter '" + name + "'", "param:" + name);
  it = std::find_if(graph_.parameters.begin(), graph_.parameters.end(), [&](const Parameter& p) { return p.name == name; });
  it->defaultValue = value;
  return "";
}

std::string GraphEditor::applyPreset(const std::string& name) {
  auto preset = std::find_if(graph_.presets.begin(), graph_.presets.end(), [&](const Preset& p) { return p.name == name; });
  if (preset == graph_.presets.end()) return "no preset '" + name + "'";
  Graph next = graph_;
  for (const PresetValue& v : preset->values) {
    if (v.isOption()) {
      // A node inside a subgraph instance ("foam/edge") lies in the instance's file: only the
      // instance is this graph's; the option goes to Graph::instanceOptions (the preview
      // applies it; the file keeps it in the preset, the subgraph's file stays as written).
      std::string node = v.node.substr(0, v.node.find('/'));
      if (!next.findNode(node)) return "preset '" + name + "' names no node '" + node + "'";
      continue;
    }
    auto p = std::find_if(next.parameters.begin(), next.parameters.end(), [&](const Parameter& q) { return q.name == v.parameter; });
    if (p == next.parameters.end()) return "preset '" + name + "' names no parameter '" + v.parameter + "'";
    if (v.value.size() != p->defaultValue.size())
      return "preset '" + name + "': parameter '" + v.parameter + "' takes " + std::to_string(p->defaultValue.size()) + " number(s)";
  }
  writePresetInto(next, *preset);
  record("apply preset '" + name + "'", "");
  graph_ = std::move(next);
  return "";
}

std::string GraphEditor::setInputConstant(const InputTarget& target, const std::vector<double>& value) {
  if (std::string why = checkTarget(target); !why.empty()) return why;
  if (value.empty() || value.size() > 4) return describe(target) + ": a constant has 1 to 4 numbers";
  if (!allFitFloat32(value)) return describe(target) + ": values must be finite in float32 range";
  InputSource s;
  s.kind = InputSource::Kind::Literal;
  s.literal = value;
  record("set " + describe(target), "const:" + target.node + "." + target.port);
  setSource(target, std::move(s));
  return "";
}

std::string GraphEditor::setInputParameter(const InputTarget& target, const std::string& parameter) {
  if (std::string why = checkTarget(target); !why.empty()) return why;
  if (!graph_.findParameter(parameter)) return "no parameter '" + parameter + "'";
  InputSource s;
  s.kind = InputSource::Kind::Parameter;
  s.name = parameter;
  record("feed " + describe(target) + " from $" + parameter, "");
  setSource(target, std::move(s));
  return "";
}

std::string GraphEditor::setOption(const std::string& node, const std::string& name, const nlohmann::json& value) {
  const Node* n = graph_.findNode(node);
  if (!n) return "no node '" + node + "'";
  std::string what = "option '" + name + "' of node '" + node + "'";
  // The option's name is a key of the file, its value a value of it: both keep its limits.
  if (name.size() > kMaxStringBytes) return "an option name is longer than " + std::to_string(kMaxStringBytes) + " bytes";
  if (std::string why = checkJsonLimits(value, kOptionValueDepth); !why.empty()) return what + ": " + why;
  if (registry_) {
    GraphNodeType type = nodeTypeOf(graph_, *registry_, n->type);
    if (type.isInstance())
      return "node '" + node + "' is an instance of the subgraph '" + type.import->path + "', which has no options";
    if (const NodeSpec* spec = type.spec) {
      int index = spec->optionIndex(name);
      if (index < 0) return "node '" + node + "' (" + n->type + ") has no option '" + name + "'";
      const OptionSpec& o = spec->options[static_cast<size_t>(index)];
      switch (o.kind) {
        case OptionSpec::Kind::Enum:
          if (!value.is_string() || std::find(o.choices.begin(), o.choices.end(), value.get<std::string>()) == o.choices.end())
            return what + " must be one of its choices";
          break;
        case OptionSpec::Kind::Bool:
          if (!value.is_boolean()) return what + " must be true or false";
          break;
        case OptionSpec::Kind::Number:
        case OptionSpec::Kind::Integer: {
          if (!value.is_number() || !fitsFloat32(value.get<double>())) return what + " must be a finite number";
          double x = value.get<double>();
          if (o.kind == OptionSpec::Kind::Integer && std::floor(x) != x) return what + " must be a whole number";
          if ((o.min && x < *o.min) || (o.max && x > *o.max)) return what + " is out of its range";
          break;
        }
        case OptionSpec::Kind::Text:
          if (!value.is_string()) return what + " must be a string";
          break;
        case OptionSpec::Kind::Texture:
        case OptionSpec::Kind::Json: break;
      }
    }
  }
  for (const auto& o : n->options)
    if (o.name == name && o.value == value) return "";
  record("set " + what, "option:" + node + "." + name);
  Node* m = findNode(node);
  for (auto& o : m->options)
    if (o.name == name) {
      o.value = value;
      return "";
    }
  NodeOption o;
  o.name = name;
  o.value = value;
  o.where.file = o.keyWhere.file = graph_.file;
  m->options.push_back(std::move(o));
  return "";
}

std::string GraphEditor::connect(const std::string& fromNode, const std::string& fromPort, const InputTarget& target) {
  if (std::string why = checkTarget(target); !why.empty()) return why;
  const Node* from = graph_.findNode(fromNode);
  if (!from) return "no node '" + fromNode + "'";
  if (!isIdentifier(fromPort)) return "'" + fromPort + "' is not an output name";
  if (registry_ && !registry_->fileNodeType(from->type))  // a file node's outputs: as for its inputs
    if (auto ports = portsOfGraphNode(graph_, *registry_, *from); ports && ports->outputIndex(fromPort) < 0)
      return "node '" + fromNode + "' (" + from->type + ") has no output '" + fromPort + "'";
  if (!target.node.empty()) {
    // A cycle: the target node is already upstream of (or is) the source node.
    std::vector<std::string> stack{fromNode};
    std::set<std::string> seen;
    while (!stack.empty()) {
      std::string id = stack.back();
      stack.pop_back();
      if (id == target.node) return "connecting " + fromNode + "." + fromPort + " to " + describe(target) + " would make a cycle";
      if (!seen.insert(id).second) continue;
      if (const Node* n = graph_.findNode(id))
        for (const auto& in : n->inputs)
          if (in.source.kind == InputSource::Kind::NodeOutput) stack.push_back(in.source.name);
    }
  }
  InputSource s;
  s.kind = InputSource::Kind::NodeOutput;
  s.name = fromNode;
  s.port = fromPort;
  record("connect " + fromNode + "." + fromPort + " to " + describe(target), "");
  setSource(target, std::move(s));
  return "";
}

std::string GraphEditor::disconnect(const InputTarget& target) {
  if (std::string why = checkTarget(target); !why.empty()) return why;
  if (target.node.empty()) {
    OutputSlot slot = *parseOutputSlot(target.port);
    auto it = std::find_if(graph_.outputs.begin(), graph_.outputs.end(), [&](const GraphOutput& o) { return o.slot == slot; });
    if (it == graph_.outputs.end()) return describe(target) + " is not set";
    record("disconnect " + describe(target), "");
    graph_.outputs.erase(std::find_if(graph_.outputs.begin(), graph_.outputs.end(),
                                      [&](const GraphOutput& o) { return o.slot == slot; }));
    return "";
  }
  const Node* n = graph_.findNode(target.node);
  auto has = std::any_of(n->inputs.begin(), n->inputs.end(), [&](const NodeInput& in) { return in.port == target.port; });
  if (!has) return describe(target) + " is not set";
  record("disconnect " + describe(target), "");
  auto& ins = findNode(target.node)->inputs;
  ins.erase(std::find_if(ins.begin(), ins.end(), [&](const NodeInput& in) { return in.port == target.port; }));
  return "";
}

std::string GraphEditor::addNode(const std::string& type, const std::string& id, std::array<double, 2> position,
                                 std::string* usedId) {
  if (registry_ && !nodeTypeOf(graph_, *registry_, type) && !registry_->fileNodeType(type)) return "no node type '" + type + "'";
  if (!isIdentifier(type)) return "'" + type + "' is not a node type name";
  std::string newId = id;
  if (newId.empty()) {
    for (int k = 1;; ++k) {
      newId = type + "_" + std::to_string(k);
      if (newId.size() > 64) newId = "node_" + std::to_string(k);
      if (!graph_.findNode(newId)) break;
    }
  }
  if (!isIdentifier(newId)) return "'" + newId + "' is not a valid node id ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  if (graph_.findNode(newId)) return "a node '" + newId + "' already exists";
  if (!positionFits(position)) return "a node position must be finite in float32 range";
  if (graph_.nodes.size() >= kMaxNodes) return "a graph has at most " + std::to_string(kMaxNodes) + " nodes";
  record("add node '" + newId + "'", "");
  Node n;
  n.id = newId;
  n.type = type;
  n.editorPosition = position;
  n.where.file = n.idWhere.file = n.typeWhere.file = graph_.file;
  graph_.nodes.push_back(std::move(n));
  if (usedId) *usedId = newId;
  return "";
}

std::string GraphEditor::deleteNode(const std::string& id) {
  if (!graph_.findNode(id)) return "no node '" + id + "'";
  record("delete node '" + id + "'", "");
  auto reads = [&](const InputSource& s) { return s.kind == InputSource::Kind::NodeOutput && s.name == id; };
  std::erase_if(graph_.nodes, [&](const Node& n) { return n.id == id; });
  for (auto& n : graph_.nodes) std::erase_if(n.inputs, [&](const NodeInput& in) { return reads(in.source); });
  std::erase_if(graph_.outputs, [&](const GraphOutput& o) { return reads(o.source); });
  dropFromFrames({id});
  return "";
}

std::string GraphEditor::moveNode(const std::string& id, std::array<double, 2> position) {
  if (!graph_.findNode(id)) return "no node '" + id + "'";
  if (!positionFits(position)) return "a node position must be finite in float32 range";
  if (graph_.findNode(id)->editorPosition == position) return "";
  record("move node '" + id + "'", "move:" + id);
  findNode(id)->editorPosition = position;
  return "";
}

std::string GraphEditor::moveNodes(const std::vector<std::pair<std::string, std::array<double, 2>>>& positions) {
  std::string key = "move:";
  bool changes = false;
  for (const auto& [id, position] : positions) {
    const Node* n = graph_.findNode(id);
    if (!n) return "no node '" + id + "'";
    if (!positionFits(position)) return "a node position must be finite in float32 range";
    changes |= n->editorPosition != position;
    key += id + ",";
  }
  if (!changes) return "";
  if (positions.size() == 1) return moveNode(positions[0].first, positions[0].second);
  record("move " + std::to_string(positions.size()) + " nodes", key);
  for (const auto& [id, position] : positions) findNode(id)->editorPosition = position;
  return "";
}

std::string GraphEditor::deleteNodes(const std::vector<std::string>& ids) {
  for (const auto& id : ids)
    if (!graph_.findNode(id)) return "no node '" + id + "'";
  if (ids.empty()) return "";
  if (ids.size() == 1) return deleteNode(ids[0]);
  record("delete " + std::to_string(ids.size()) + " nodes", "");
  std::set<std::string> gone(ids.begin(), ids.end());
  auto reads = [&](const InputSource& s) { return s.kind == InputSource::Kind::NodeOutput && gone.count(s.name); };
  std::erase_if(graph_.nodes, [&](const Node& n) { return gone.count(n.id) > 0; });
  for (auto& n : graph_.nodes) std::erase_if(n.inputs, [&](const NodeInput& in) { return reads(in.source); });
  std::erase_if(graph_.outputs, [&](const GraphOutput& o) { return reads(o.source); });
  dropFromFrames(gone);
  return "";
}

std::string GraphEditor::insertNodes(std::vector<Node> nodes) {
  if (nodes.empty()) return "";
  if (graph_.nodes.size() + nodes.size() > kMaxNodes) return "a graph has at most " + std::to_string(kMaxNodes) + " nodes";
  std::map<std::string, const Node*> added;
  for (const Node& n : nodes) {
    if (!isIdentifier(n.id)) return "'" + n.id + "' is not a valid node id ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
    if (graph_.findNode(n.id)) return "a node '" + n.id + "' already exists";
    if (!added.emplace(n.id, &n).second) return "node id '" + n.id + "' is given twice";
    if (registry_ && !nodeTypeOf(graph_, *registry_, n.type) && !registry_->fileNodeType(n.type)) return "no node type '" + n.type + "' (node '" + n.id + "')";
    if (n.editorPosition && !positionFits(*n.editorPosition)) return "a node position must be finite in float32 range";
  }
  for (const Node& n : nodes)
    for (const NodeInput& in : n.inputs)
      if (in.source.kind == InputSource::Kind::NodeOutput && !added.count(in.source.name) && !graph_.findNode(in.source.name))
        return "input '" + in.port + "' of node '" + n.id + "' reads node '" + in.source.name + "', which is not there";
  // Existing nodes do not read the new ones, so a cycle can only lie among them: peel off
  // the nodes that read none of the new ones still left (Kahn's order, no recursion: a paste
  // may be a long chain); what cannot be peeled lies on or behind a cycle.
  std::map<std::string, size_t> unread;  // per new node: links to new nodes not yet peeled
  std::map<std::string, std::vector<std::string>> readers;
  for (const Node& n : nodes)
    for (const NodeInput& in : n.inputs)
      if (in.source.kind == InputSource::Kind::NodeOutput && added.count(in.source.name))
        ++unread[n.id], readers[in.source.name].push_back(n.id);
  std::vector<std::string> ready;
  for (const Node& n : nodes)
    if (!unread[n.id]) ready.push_back(n.id);
  size_t peeled = 0;
  while (!ready.empty()) {
    std::string id = std::move(ready.back());
    ready.pop_back();
    ++peeled;
    for (const std::string& r : readers[id])
      if (--unread[r] == 0) ready.push_back(r);
  }
  if (peeled != nodes.size()) {
    for (const Node& n : nodes)
      if (unread[n.id]) return "the links among the nodes close a cycle (through node '" + n.id + "')";
  }
  record(nodes.size() == 1 ? "paste node '" + nodes[0].id + "'" : "paste " + std::to_string(nodes.size()) + " nodes", "");
  for (Node& n : nodes) graph_.nodes.push_back(std::move(n));
  return "";
}

void GraphEditor::adoptImports(const Graph& loaded) {
  auto adopt = [&](Graph& g) {
    for (Import& im : g.imports)
      if (const Import* now = loaded.findImport(im.name); now && now->path == im.path && now->graph) im.graph = now->graph;
  };
  adopt(graph_);
  for (Step& s : undo_) adopt(s.graph);
  for (Step& s : redo_) adopt(s.graph);
}

void GraphEditor::replace(Graph graph, const std::string& label) {
  record(label, "");
  graph_ = std::move(graph);
}

bool GraphEditor::undo() {
  if (undo_.empty()) return false;
  Step s = std::move(undo_.back());
  undo_.pop_back();
  redo_.push_back({std::move(graph_), revision_, s.label});
  graph_ = std::move(s.graph);
  revision_ = s.revision;
  mergeKey_.clear();
  return true;
}

bool GraphEditor::redo() {
  if (redo_.empty()) return false;
  Step s = std::move(redo_.back());
  redo_.pop_back();
  undo_.push_back({std::move(graph_), revision_, s.label});
  graph_ = std::move(s.graph);
  revision_ = s.revision;
  mergeKey_.clear();
  return true;
}

}  // namespace wg
