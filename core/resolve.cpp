// resolveGraph (core/resolve.h): the steps in order, for a graph or a subgraph instance:
// parameters collected, nodes indexed and typed (resolve_node_types.cpp), presets checked
// (resolve_presets.cpp), put in data-flow order (resolve_order.cpp), made into ops
// (resolve_ops.cpp, resolve_instances.cpp); then the output slots and interface outputs.
#include "core/resolve.h"

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/color_parameters.h"
#include "core/graph_imports.h"
#include "core/instance_options.h"
#include "core/interface_tables.h"
#include "core/resolver.h"

namespace wg {
namespace resolving {

std::optional<Program> Resolver::run(NodeOutputValues* nodeOutputs) {
  size_t errorsBefore = diags_.errorCount();
  program_.graphName = graph_.name;
  program_.description = graph_.description;
  program_.view = graph_.view.value_or(ViewTransform{});
  program_.file = graph_.file;
  program_.directory = std::filesystem::path(graph_.file).parent_path().string();
  program_.totalNodes = static_cast<int>(graph_.nodes.size());
  shared_.topDirectory = program_.directory;
  std::vector<std::string> files = graphFilesRead(graph_);
  for (size_t k = 1; k < files.size(); ++k) {
    namespace fs = std::filesystem;
    fs::path top(program_.folder());
    program_.importedFiles.push_back(fs::path(files[k]).lexically_normal().lexically_relative(top.lexically_normal()).generic_string());
  }
  shared_.nodeOutputs = nodeOutputs;
  shared_.instanceOptions = &graph_.instanceOptions;
  collectParameters();
  if (graph_.interface && !graph_.interface->options.empty()) bindOwnOptions();
  resolveBody();
  if (diags_.errorCount() > errorsBefore) return std::nullopt;
  resolveOutputs();
  // A function graph compiled on its own keeps its interface's promises too.
  std::vector<ValueRef> interfaceValues;
  if (graph_.interface) resolveInterfaceOutputs(interfaceValues);
  if (diags_.errorCount() > errorsBefore) return std::nullopt;
  if (nodeOutputs) listNodeOutputs(*nodeOutputs);
  return std::move(program_);
}

// A subgraph instance: its ops go into the shared program. False after reporting.
bool Resolver::runInstance() {
  size_t errorsBefore = diags_.errorCount();
  program_.totalNodes += static_cast<int>(graph_.nodes.size());
  for (const auto& p : graph_.parameters) paramValue_.emplace(p.name, scope_->inputs.at(p.name));
  useOptions(scope_->options);
  resolveBody();
  if (diags_.errorCount() > errorsBefore) return false;
  resolveInterfaceOutputs(scope_->outputs);
  if (diags_.errorCount() > errorsBefore) return false;
  if (shared_.nodeOutputs) listNodeOutputs(*shared_.nodeOutputs);
  return true;
}

void Resolver::resolveBody() {
  size_t errorsBefore = diags_.errorCount();
  directory_ = std::filesystem::path(graph_.file).parent_path().string();
  checkImportNames();
  indexNodes();
  lookUpSpecs();
  if (!scope_) checkPresetOptions();
  std::vector<int> order = topologicalOrder();
  if (diags_.errorCount() > errorsBefore) return;
  buildOps(order);
}

// A function graph compiled on its own: its options take their defaults.
void Resolver::bindOwnOptions() {
  InstanceOptionRequest request{*graph_.interface, graph_.file};
  request.topDirectory = shared_.topDirectory;
  request.accept = [this](const TextureFile& t) { return acceptedTexture(t); };
  if (auto bound = bindInstanceOptions(request, diags_)) {
    ownOptions_ = std::move(*bound);
    useOptions(ownOptions_);
  }
}

// The options' static values are read as `$name`, folded like a literal input.
void Resolver::useOptions(const InstanceBindings& bound) {
  options_ = &bound;
  for (const auto& [name, value] : bound.statics)
    paramValue_.emplace(name, ValueRef::constant_(shared_.constants.intern(Value::scalar(value))));
}

void Resolver::collectParameters() {
  for (const auto& p : graph_.parameters) {
    ProgramParameter pp;
    pp.name = p.name;
    pp.type = p.type;
    pp.defaultValue = literalValue(p.defaultValue);
    if (pp.defaultValue.type != p.type) pp.defaultValue = Value::ofType(p.type, p.defaultValue.empty() ? 0 : p.defaultValue[0]);
    pp.min = p.min;
    pp.max = p.max;
    pp.hint = p.hint;
    pp.description = p.description;
    pp.isStatic = p.isStatic;
    pp.where = p.where;
    paramValue_[p.name] = ValueRef::param(static_cast<int>(program_.parameters.size()));
    program_.parameters.push_back(std::move(pp));
  }
}

void Resolver::indexNodes() {
  nodeIndex_.reserve(graph_.nodes.size());
  for (size_t i = 0; i < graph_.nodes.size(); ++i) {
    const Node& n = graph_.nodes[i];
    auto [firstIndex, inserted] = nodeIndex_.emplace(n.id, static_cast<int>(i));
    if (!inserted) {
      const Node& first = graph_.nodes[static_cast<size_t>(firstIndex)];
      auto& d = diags_.error(DiagCode::DuplicateNodeId, n.idWhere, "duplicate node id '" + n.id + "'", n.id);
      d.notes.push_back("first defined at " + std::to_string(first.idWhere.line) + ":" +
                        std::to_string(first.idWhere.col));
    }
  }
}

// An import's name becomes a node type here, so it may not be one already.
void Resolver::checkImportNames() {
  for (const auto& im : graph_.imports)
    if (registry_.find(im.name))
      diags_.error(DiagCode::ImportShadowsNode, im.where,
                   "import name '" + im.name + "' is already a node type; choose another name for '" + im.path + "'");
}

// The type a source provides, or Invalid after reporting. `node`: the node index of a
// NodeOutput source when already known (-1: look it up by id).
std::optional<ValueRef> Resolver::sourceRef(const InputSource& s, int node, int port) {
  switch (s.kind) {
    case InputSource::Kind::Literal: return ValueRef::constant_(shared_.constants.intern(literalValue(s.literal)));
    case InputSource::Kind::Parameter: {
      auto it = paramValue_.find(s.name);
      if (it == paramValue_.end()) return std::nullopt;
      // A colour parameter is read linearised, through one op made at its first read.
      if (it->second.kind == ValueRef::Kind::Param && isColorHint(program_.parameters[static_cast<size_t>(it->second.index)].hint))
        it->second = appendParameterLinearisation(program_, registry_, it->second.index);
      return it->second;
    }
    case InputSource::Kind::NodeOutput: {
      if (node < 0) {
        node = nodeIndex_.find(s.name);
        if (node < 0) return std::nullopt;
      }
      // `port` (when known) indexes outputsOf(node): the expanded values, and the op's own
      // outputs unless the node's options gave it ports other than its type's.
      if (const auto& values = expandedOutputs_[static_cast<size_t>(node)]; !values.empty()) {
        if (port < 0) port = portIndex(outputsOf(static_cast<size_t>(node)), s.port);
        if (port < 0) return std::nullopt;
        return values[static_cast<size_t>(port)];
      }
      int opIndex = opOfNode_[static_cast<size_t>(node)];
      if (opIndex < 0) return std::nullopt;
      if (port < 0 || ports_[static_cast<size_t>(node)])
        port = program_.ops[static_cast<size_t>(opIndex)].spec->outputIndex(s.port);
      if (port < 0) return std::nullopt;
      return ValueRef::op(opIndex, port);
    }
  }
  return std::nullopt;
}

void Resolver::listNodeOutputs(NodeOutputValues& out) const {
  for (size_t i = 0; i < graph_.nodes.size(); ++i) {
    if (!specs_[i]) continue;
    const std::vector<PortSpec>& ports = outputsOf(i);
    std::vector<NodeOutputValue> values;
    if (!expandedOutputs_[i].empty()) {
      for (size_t p = 0; p < ports.size(); ++p)
        values.push_back({ports[p].name, expandedOutputs_[i][p], program_.typeOf(expandedOutputs_[i][p])});
    } else if (int op = opOfNode_[i]; op >= 0) {
      const Op& o = program_.ops[static_cast<size_t>(op)];
      for (size_t p = 0; p < ports.size(); ++p)
        values.push_back({ports[p].name, ValueRef::op(op, static_cast<int>(p)), o.outputTypes[p]});
    } else {
      continue;
    }
    out[idOf(graph_.nodes[i])] = std::move(values);
  }
}

// A subgraph's interface outputs: each the value of its source, of its declared type.
void Resolver::resolveInterfaceOutputs(std::vector<ValueRef>& values) {
  for (const auto& out : graph_.interface->outputs) {
    std::string label = "interface output '" + out.name + "'";
    if (out.source.kind == InputSource::Kind::NodeOutput) {
      if (referencedNode(out.source, "", [&] { return label; }) < 0) continue;
    } else if (out.source.kind == InputSource::Kind::Parameter && !paramValue_.count(out.source.name)) {
      diags_.error(DiagCode::UnknownParameter, out.source.where, "no parameter named '" + out.source.name + "'",
                   "", label);
      continue;
    }
    auto ref = sourceRef(out.source);
    if (!ref) continue;  // the node itself failed and was reported
    if (!existsForItsInputs(*ref, out.source, "", [&] { return label; })) continue;
    Type got = program_.typeOf(*ref);
    if (got != out.type) {
      diags_.error(DiagCode::InterfaceMismatch, out.source.where,
                   label + " is declared " + std::string(typeName(out.type)) + ", but " + describeSource(out.source) +
                       " is " + std::string(typeName(got)),
                   out.source.kind == InputSource::Kind::NodeOutput ? prefixed(out.source.name) : "", label);
      continue;
    }
    values.push_back(*ref);
  }
}

void Resolver::resolveOutputs() {
  if (graph_.outputs.empty())
    diags_.error(DiagCode::NoOutputs, graph_.outputsWhere, "the graph connects no outputs");
  for (const auto& out : graph_.outputs) {
    std::string label = "output '" + std::string(outputSlotName(out.slot)) + "'";
    if (out.source.kind == InputSource::Kind::NodeOutput) {
      if (referencedNode(out.source, "", [&] { return label; }) < 0) continue;
    } else if (out.source.kind == InputSource::Kind::Parameter && !paramValue_.count(out.source.name)) {
      diags_.error(DiagCode::UnknownParameter, out.source.where,
                   "no parameter named '" + out.source.name + "'", "", label);
      continue;
    }
    auto ref = sourceRef(out.source);
    if (!ref) continue;  // the node itself failed and was reported
    if (!existsForItsInputs(*ref, out.source, "", [&] { return label; })) continue;
    Type want = outputSlotRow(out.slot).type;
    Type got = program_.typeOf(*ref);
    if (!implicitlyConvertible(got, want)) {
      diags_.error(DiagCode::TypeMismatch, out.source.where,
                   label + " expects " + std::string(typeName(want)) + ", but " + describeSource(out.source) +
                       " is " + std::string(typeName(got)),
                   out.source.kind == InputSource::Kind::NodeOutput ? out.source.name : "", label);
      continue;
    }
    // A colour written as a literal into the colour slot is sRGB-authored, as on a colour port.
    bool colorLiteral = out.slot == OutputSlot::FragmentColor && out.source.kind == InputSource::Kind::Literal;
    program_.outputs.push_back({out.slot, colorLiteral ? linearised(*ref) : *ref, want, out.source.where});
  }
  std::sort(program_.outputs.begin(), program_.outputs.end(),
            [](const ProgramOutput& a, const ProgramOutput& b) { return a.slot < b.slot; });
}

}  // namespace resolving

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags) {
  return resolving::Resolver(graph, registry, diags).run();
}

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags,
                                    NodeOutputValues& nodeOutputs) {
  return resolving::Resolver(graph, registry, diags).run(&nodeOutputs);
}

}  // namespace wg
