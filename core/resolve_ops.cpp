// Resolving, step 4: one op per node in data-flow order, its inputs wired and typed (a
// derived input computed, an expanding node's ops made), within the inlined-size budget.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/derive.h"
#include "core/expand.h"
#include "core/interface_tables.h"
#include "core/json_string_columns.h"
#include "core/load_limits.h"
#include "core/node_options.h"
#include "core/port_typing.h"
#include "core/resolver.h"
#include "core/text_lines.h"

namespace wg::resolving {

void Resolver::buildOps(const std::vector<int>& order) {
  opOfNode_.assign(graph_.nodes.size(), -1);
  expandedOutputs_.assign(graph_.nodes.size(), {});
  // One op per node, and (the top-level graph) one per colour parameter, its linearisation
  // made at its first read. Reserving for the nodes alone, the first linearisation doubled
  // the array: at 10,000 nodes 2 MiB of ops moved into 4 MiB, both held at once, the
  // compile's peak heap. (Nodes that expand or derive add more, and the array grows.)
  std::size_t colourParameters = 0;
  if (!scope_)
    for (const ProgramParameter& p : program_.parameters) colourParameters += isColorHint(p.hint) ? 1 : 0;
  program_.ops.reserve(order.size() + colourParameters);
  const Node* previous = nullptr;  // the node whose ops the budget check measures
  for (int ni : order) {
    const Node& node = graph_.nodes[static_cast<size_t>(ni)];
    const NodeSpec* spec = specs_[static_cast<size_t>(ni)];
    if (previous && !withinInlinedBudget(*previous)) return;
    previous = &node;
    if (!spec) continue;
    Op op;
    op.spec = spec;
    op.nodeId = idOf(node);
    op.where = node.where;
    if (scope_) op.instanceChain = scope_->chain;
    // A node that declares no options takes its type's defaults, completed and parsed once
    // per type. Inside an instance too: texture defaults are builtin names, which
    // retargetTexturePaths leaves as they are (Registry::add checks that).
    if (node.options.empty()) {
      auto [it, fresh] = shared_.defaultOptions.try_emplace(spec);
      if (fresh) it->second = shared_.options.intern(*spec, completeOptions(*spec, nlohmann::json::object()));
      op.sharedOptions = it->second.json;
      op.parsedOptions = it->second.parsed;
    } else {
      nlohmann::json complete = completeOptions(*spec, declaredOptions(node, *spec));
      if (scope_) retargetTexturePaths(*spec, complete);
      if (options_ && !bindInterfaceTextures(*spec, node, complete)) continue;
      // Valid: lookUpSpecs checked each value.
      SharedOptions held = shared_.options.intern(*spec, std::move(complete));
      op.sharedOptions = std::move(held.json);
      op.parsedOptions = std::move(held.parsed);
    }

    const std::vector<PortSpec>& ports = inputsOf(static_cast<size_t>(ni));
    size_t nin = ports.size();
    op.inputs.assign(nin, ValueRef{});
    // Reused from node to node (two allocations per node on a large graph otherwise).
    std::vector<Type>& sourceTypes = sourceTypes_;
    std::vector<const NodeInput*>& given = given_;
    sourceTypes.assign(nin, Type::Invalid);
    given.assign(nin, nullptr);
    bool ok = true;
    for (size_t k = 0; k < node.inputs.size(); ++k) {
      const NodeInput& in = node.inputs[k];
      const size_t edge = inputBase_[static_cast<size_t>(ni)] + k;
      int pi = inputPort_[edge];  // portIndex(ports, in.port), looked up once in lookUpSpecs
      if (pi < 0) continue;
      given[static_cast<size_t>(pi)] = &in;
      // The referenced node and its port were found by name once, in topologicalOrder.
      auto ref = sourceRef(in.source, inputNode_[edge], inputSourcePort_[edge]);
      if (!ref) {
        ok = false;  // already reported (dangling, unknown parameter, bad upstream node)
        continue;
      }
      if (!existsForItsInputs(*ref, in.source, node.id, [&] { return inputLabel(in.port); })) {
        ok = false;
        continue;
      }
      bool colorLiteral = ports[static_cast<size_t>(pi)].color && in.source.kind == InputSource::Kind::Literal;
      // An instance's literals are linearised after their range check (inlineInstance).
      op.inputs[static_cast<size_t>(pi)] = colorLiteral && !instanceOf_[static_cast<size_t>(ni)] ? linearised(*ref) : *ref;
      sourceTypes[static_cast<size_t>(pi)] = program_.typeOf(*ref);
    }
    for (size_t pi = 0; pi < nin; ++pi) {
      if (given[pi]) continue;
      const PortSpec& port = ports[pi];
      if (port.derived) continue;  // filled below by the node's derive
      if (port.defaultValue) {
        op.inputs[pi] = ValueRef::constant_(shared_.constants.intern(*port.defaultValue));
        if (port.color && !instanceOf_[static_cast<size_t>(ni)]) op.inputs[pi] = linearised(op.inputs[pi]);
        sourceTypes[pi] = port.defaultValue->type;
      } else if (port.defaultBuiltin) {
        op.inputs[pi] = ValueRef::builtin(*port.defaultBuiltin);
        sourceTypes[pi] = builtinType(*port.defaultBuiltin);
      } else {
        diags_.error(DiagCode::MissingInput, node.where,
                     "required input '" + port.name + "' of " + spec->type + " is not connected", node.id,
                     inputLabel(port.name));
        ok = false;
      }
    }
    if (!ok) continue;
    if (instanceOf_[static_cast<size_t>(ni)]) {
      inlineInstance(ni, op, sourceTypes, given);
      continue;
    }
    if (spec->expand) {
      expandNode(ni, op, sourceTypes, given);
      continue;
    }
    if (spec->derive) {
      // The node's own inputs must fit before anything is derived from them: a vec4 wired
      // into linearize_depth's vec2 near_far is the node's type error, reported as such,
      // not a derive that cannot type its op (before, an internal error).
      std::vector<Type> declared = sourceTypes;
      for (size_t pi = 0; pi < nin; ++pi)
        if (ports[pi].derived) declared[pi] = ports[pi].type;
      if (!typePorts(*spec, *op.parsedOptions, declared, [](int) { return std::string(); }).error.empty()) {
        typeOp(op, node, declared, given);  // reports the mismatch
        continue;
      }
      size_t firstDerived = program_.ops.size();
      deriveInputs(*spec, *op.parsedOptions, registry_, op.nodeId, op.where, op.inputs, program_);
      for (size_t k = firstDerived; k < program_.ops.size(); ++k) program_.ops[k].instanceChain = op.instanceChain;
      for (size_t pi = 0; pi < nin; ++pi)
        if (ports[pi].derived) sourceTypes[pi] = program_.typeOf(op.inputs[pi]);
    }
    if (!typeOp(op, node, sourceTypes, given)) continue;
    opOfNode_[static_cast<size_t>(ni)] = static_cast<int>(program_.ops.size());
    program_.ops.push_back(std::move(op));
  }
  if (previous) withinInlinedBudget(*previous);
}

// Whether the ops made so far keep the inlined-size budget; reports at `node`, the one
// whose ops passed it, and stops every resolver of the graph.
bool Resolver::withinInlinedBudget(const Node& node) {
  if (shared_.overBudget) return false;
  const std::vector<Op>& ops = program_.ops;
  for (size_t k = std::min(shared_.opsMeasured, ops.size()); k < ops.size(); ++k)
    shared_.inlinedBytes += ops[k].nodeId.size() + kInlinedNodeBytes;
  shared_.opsMeasured = ops.size();
  if (shared_.inlinedBytes <= kMaxInlinedBytes && ops.size() <= kMaxOps) return true;
  shared_.overBudget = true;
  const std::string what = ops.size() > kMaxOps
                               ? "makes more than " + std::to_string(kMaxOps) + " ops, the limit"
                               : "passes the limit of " + std::to_string(kMaxInlinedBytes / (1024 * 1024)) +
                                     " MiB of inlined size (every op it makes, its full id and " +
                                     std::to_string(kInlinedNodeBytes) + " bytes each) after " +
                                     std::to_string(ops.size()) + " ops";
  diags_.error(DiagCode::LimitExceeded, node.where, "with node '" + idOf(node) + "' the graph " + what, node.id);
  return false;
}

// A node that expands into ops (an expression): its inputs, checked against the ports
// its options declare and converted to their types, go to the spec's expand function;
// the values it names become the node's outputs.
void Resolver::expandNode(int ni, const Op& op, const std::vector<Type>& sourceTypes, const std::vector<const NodeInput*>& given) {
  const Node& node = graph_.nodes[static_cast<size_t>(ni)];
  const NodeSpec& spec = *op.spec;
  NodePorts fixedPorts;  // an expanding type whose ports do not depend on its options
  if (!ports_[static_cast<size_t>(ni)]) fixedPorts = {spec.inputs, spec.outputs};
  const NodePorts& ports = ports_[static_cast<size_t>(ni)] ? *ports_[static_cast<size_t>(ni)] : fixedPorts;
  auto inputs = convertedInputs(node, op, ports.inputs, sourceTypes, given);
  if (!inputs) return;
  size_t firstOp = program_.ops.size();
  ExpandContext ctx{spec, ports, *op.parsedOptions, registry_, idOf(node), node.where, std::move(*inputs), program_,
                    [&](std::string_view option, size_t offset) { return optionWhere(node, option, offset); },
                    {}, DiagCode::InvalidOption, {}, {}, 0};
  size_t opsBefore = program_.ops.size();
  spec.expand(ctx);
  if (!ctx.error.empty()) {
    program_.ops.resize(opsBefore);
    bool atOption = !ctx.errorOption.empty();
    diags_.error(ctx.errorCode, atOption ? optionWhere(node, ctx.errorOption, ctx.errorOffset) : node.where, ctx.error,
                 node.id, atOption ? optionLabel(ctx.errorOption) : "");
    return;
  }
  if (ctx.outputs.size() != ports.outputs.size())
    throw std::logic_error("node type '" + spec.type + "' expanded into " + std::to_string(ctx.outputs.size()) +
                           " outputs for its " + std::to_string(ports.outputs.size()) + " output ports");
  if (scope_)
    for (size_t k = firstOp; k < program_.ops.size(); ++k) program_.ops[k].instanceChain = scope_->chain;
  expandedOutputs_[static_cast<size_t>(ni)] = std::move(ctx.outputs);
}

// An expanding node's or an instance's inputs, each of its port's type (a float splats),
// or nothing after reporting the one that does not fit.
std::optional<std::vector<ValueRef>> Resolver::convertedInputs(const Node& node, const Op& op, const std::vector<PortSpec>& ports,
                                                     const std::vector<Type>& sourceTypes,
                                                     const std::vector<const NodeInput*>& given) {
  std::vector<ValueRef> inputs(ports.size());
  for (size_t pi = 0; pi < ports.size(); ++pi) {
    const PortSpec& port = ports[pi];
    if (port.kind != PortKind::Fixed)  // what a port of another kind means is the expansion's to say
      throw std::logic_error("node type '" + op.spec->type + "' gives its input '" + port.name + "' no fixed type");
    if (!implicitlyConvertible(sourceTypes[pi], port.type)) {
      mismatch(node, given[pi], port.name,
               "input '" + port.name + "' expects " + std::string(typeName(port.type)) + ", but " +
                   sourceName(given[pi]) + " is " + std::string(typeName(sourceTypes[pi])));
      return std::nullopt;
    }
    inputs[pi] = splat(op.inputs[pi], port.type, node);
  }
  return inputs;
}

// `v` as type `want`: a float splats to a vector (as a port does), a constant at once,
// anything else through a `combine` op named after the node.
ValueRef Resolver::splat(const ValueRef& v, Type want, const Node& node) {
  Type have = program_.typeOf(v);
  if (have == want) return v;
  if (v.kind == ValueRef::Kind::Const) return ValueRef::constant_(shared_.constants.intern(v.constant().convertedTo(want)));
  const NodeSpec* combine = registry_.find("combine");
  if (!combine) throw std::logic_error("the registry has no 'combine' node to splat an input with");
  Op op;
  op.spec = combine;
  op.nodeId = idOf(node);
  op.where = node.where;
  if (scope_) op.instanceChain = scope_->chain;
  SharedOptions held = shared_.options.intern(*combine, completeOptions(*combine, {{"type", std::string(typeName(want))}}));
  op.sharedOptions = std::move(held.json);
  op.parsedOptions = std::move(held.parsed);
  int n = componentCount(want);
  op.inputs.assign(combine->inputs.size(), ValueRef::constant_(shared_.constants.intern(Value::scalar(0))));
  std::vector<Type> types(combine->inputs.size(), Type::Float);
  for (int k = 0; k < n; ++k) op.inputs[static_cast<size_t>(k)] = v;
  PortTyping t = typePorts(*combine, *op.parsedOptions, types, [](int) { return std::string(); });
  if (!t.error.empty()) throw std::logic_error("splatting an input: " + t.error);
  op.inputTypes = std::move(t.inputTypes);
  op.outputTypes = std::move(t.outputTypes);
  program_.ops.push_back(std::move(op));
  return ValueRef::op(static_cast<int>(program_.ops.size()) - 1, 0);
}

// Where byte `offset` of the string of option `option` of `node` is in the file: the
// column counts the escapes written before it. The option's own position when the
// file's text is not at hand (a graph built in memory), the node's when it is not written.
SourceRef Resolver::optionWhere(const Node& node, std::string_view option, size_t offset) {
  for (const auto& o : node.options) {
    if (o.name != option) continue;
    SourceRef at = o.where;
    if (at.line <= 0) return at;
    if (!sourceLines_) {
      const std::string* text = diags_.source(graph_.file);
      sourceLines_ = text ? splitLines(*text) : std::vector<std::string_view>{};
    }
    if (static_cast<size_t>(at.line) <= sourceLines_->size())
      at.col = jsonStringByteColumn((*sourceLines_)[static_cast<size_t>(at.line - 1)], at.col, offset);
    else
      at.col += 1 + static_cast<int>(offset);
    return at;
  }
  return node.where;
}

bool Resolver::typeOp(Op& op, const Node& node, const std::vector<Type>& sourceTypes,
            const std::vector<const NodeInput*>& given) {
  PortTyping t = typePorts(*op.spec, *op.parsedOptions, sourceTypes,
                           [&](int i) { return sourceName(given[static_cast<size_t>(i)]); });
  if (!t.error.empty()) {
    const NodeInput* at = t.errorInput >= 0 ? given[static_cast<size_t>(t.errorInput)] : nullptr;
    std::string label = t.errorInput >= 0 ? op.spec->inputs[static_cast<size_t>(t.errorInput)].name : "";
    mismatch(node, at, label, t.error);
    return false;
  }
  op.inputTypes = std::move(t.inputTypes);
  op.outputTypes = std::move(t.outputTypes);
  return true;
}

std::string Resolver::sourceName(const NodeInput* given) {
  return given ? describeSource(given->source) : std::string("its default");
}

void Resolver::mismatch(const Node& node, const NodeInput* given, const std::string& port, const std::string& message) {
  diags_.error(DiagCode::TypeMismatch, portWhere(node, given), message, node.id,
               port.empty() ? std::string() : inputLabel(port));
}

}  // namespace wg::resolving
