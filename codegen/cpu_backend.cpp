#include "codegen/cpu_backend.h"

#include <filesystem>
#include <map>
#include <stdexcept>

#include "core/node_options.h"
#include "core/port_typing.h"
#include "core/resolve.h"
#include "nodes/registry.h"
#include "nodes/texture_sampling.h"
#include "nodes/texture_source.h"

namespace wg {
namespace {

// Where a program's evaluation is in each source's list of texture fetches.
struct FetchCursor {
  const TextureFetches* fetches = nullptr;
  std::map<std::string, size_t> next;
  FilterNudge* nudge = nullptr;
};

class OpEvalContext final : public EvalContext {
 public:
  OpEvalContext(const Op& op, const std::vector<Value>& inputs, const EvalEnvironment& env, TextureCache* textures,
                const std::string& graphDir, FetchCursor* cursor = nullptr)
      : op_(op), inputs_(inputs), env_(env), textures_(textures), graphDir_(graphDir), cursor_(cursor),
        outputs_(op.outputTypes.size()) {}

  const Value& input(int port) const override { return inputs_.at(static_cast<size_t>(port)); }
  Type inputType(int port) const override { return op_.inputTypes.at(static_cast<size_t>(port)); }
  Type outputType(int port) const override { return op_.outputTypes.at(static_cast<size_t>(port)); }
  const ParsedOptions& parsedOptions() const override {
    if (!op_.parsedOptions) throw std::logic_error("op of '" + op_.spec->type + "' has no parsed options");
    return *op_.parsedOptions;
  }
  void output(int port, Value v) override { outputs_.at(static_cast<size_t>(port)) = v; }
  const EvalEnvironment& environment() const override { return env_; }
  const NodeSpec& spec() const override { return *op_.spec; }
  using EvalContext::sampleTexture;
  Value sampleTexture(std::string_view option, double u, double v, const SamplerState& sampler,
                      const UvGradient& gradient) const override {
    if (!textures_) throw std::logic_error("eval of '" + op_.spec->type + "' samples a texture without a texture cache");
    const std::string source = op_.options().at(std::string(option)).get<std::string>();
    if (cursor_ && cursor_->fetches) {
      auto listed = cursor_->fetches->find(source);
      if (listed != cursor_->fetches->end()) {
        size_t& k = cursor_->next[source];
        if (k >= listed->second.size())
          throw std::logic_error("eval of '" + op_.spec->type + "' samples '" + source + "' more often than the fetches given");
        return listed->second[k++];
      }
    }
    const TextureImage& base = textures_->get(source, graphDir_);
    // The chain is built only for a look-up that can reach it.
    const std::vector<TextureImage>* chain = nullptr;
    if (sampler.filter == TextureFilter::Mipmapped && levelOfDetail(base, gradient) > 0)
      chain = &textures_->mipChain(source, graphDir_, sampler.colorSpace);
    Value value = wg::sampleTexture(base, chain, u, v, sampler, gradient);
    if (FilterNudge* nudge = cursor_ ? cursor_->nudge : nullptr) {
      if (nudge->count++ == nudge->nudged) {
        double delta = nudge->fraction * filterUncertainty(base, u, v, sampler);
        for (int c = 0; c < value.size(); ++c) value[c] += delta;
      }
    }
    return value;
  }
  std::vector<Value> take() { return std::move(outputs_); }

 private:
  const Op& op_;
  const std::vector<Value>& inputs_;
  const EvalEnvironment& env_;
  TextureCache* textures_;
  const std::string& graphDir_;
  FetchCursor* cursor_;
  std::vector<Value> outputs_;
};

// "; it has: a, b, c" for a refusal, so the fix is in the message.
template <class Named>
std::string namesOf(const std::vector<Named>& list) {
  if (list.empty()) return "; it has none";
  std::string s = "; it has: ";
  for (size_t i = 0; i < list.size(); ++i) s += (i ? ", " : "") + list[i].name;
  return s;
}

// A node that expands into ops (an expression) or derives inputs of its own (NodeSpec::
// derive), evaluated as resolve would build it: a one-node graph whose inputs are
// parameters holding the given values, resolved with the default registry (the nodes the
// expansion or derivation is made of) and run through the backend.
std::vector<Value> evaluateExpanded(const NodeSpec& spec, const nlohmann::json& options, const NodePorts& ports,
                                    const std::vector<std::pair<std::string, Value>>& inputs, const EvalEnvironment& env,
                                    const std::string& graphDir) {
  Graph g;
  // In graphDir, so texture options name files relative to it as evaluateNode's do.
  g.file = (std::filesystem::path(graphDir) / ("node '" + spec.type + "'")).string();
  g.name = "eval_" + spec.type;
  Node node;
  node.id = "n";
  node.type = spec.type;
  if (options.is_object())
    for (auto it = options.begin(); it != options.end(); ++it) node.options.push_back({it.key(), it.value(), {}, {}});
  std::vector<Value> values;
  for (const auto& p : ports.inputs) {
    if (p.derived) continue;  // the node computes it from the others
    const Value* given = nullptr;
    for (const auto& [name, value] : inputs)
      if (name == p.name) given = &value;
    Value v = given ? *given : p.defaultValue ? *p.defaultValue : p.defaultBuiltin ? env.builtin(*p.defaultBuiltin) : Value{};
    if (v.type == Type::Invalid) throw std::invalid_argument(spec.type + ": required input '" + p.name + "' is not given");
    // A Gen or Custom port takes the type of the value given; resolve types the node from it.
    Type type = p.kind == PortKind::Fixed ? p.type : v.type;
    if (!implicitlyConvertible(v.type, type))
      throw std::invalid_argument(spec.type + ": input '" + p.name + "' expects " + std::string(typeName(type)) + ", but the value given is " + std::string(typeName(v.type)));
    Parameter param;
    param.name = "in_" + p.name;
    param.type = type;
    param.defaultValue.assign(static_cast<size_t>(componentCount(type)), 0);
    g.parameters.push_back(param);
    values.push_back(v.convertedTo(type));
    NodeInput in;
    in.port = p.name;
    in.source.kind = InputSource::Kind::Parameter;
    in.source.name = param.name;
    node.inputs.push_back(in);
  }
  g.nodes.push_back(node);
  GraphOutput out;
  out.slot = OutputSlot::FragmentAlpha;  // resolve wants one; the node's own outputs are read
  out.source.kind = InputSource::Kind::Literal;
  out.source.literal = {0.0};
  g.outputs.push_back(out);
  Diagnostics diags;
  NodeOutputValues nodeOutputs;
  auto program = resolveGraph(g, defaultRegistry(), diags, nodeOutputs);
  if (!program) {
    std::string why;
    for (const auto& d : diags.sorted()) why += (why.empty() ? "" : "; ") + d.message;
    throw std::invalid_argument(spec.type + ": " + why);
  }
  CpuResult result = evaluateProgram(*program, env, values);
  std::vector<Value> outputs;
  for (const auto& o : nodeOutputs.at("n")) {
    switch (o.value.kind) {
      case ValueRef::Kind::Op:
        outputs.push_back(result.opOutputs[static_cast<size_t>(o.value.index)][static_cast<size_t>(o.value.port)]);
        break;
      case ValueRef::Kind::Param: outputs.push_back(values[static_cast<size_t>(o.value.index)]); break;
      case ValueRef::Kind::Const: outputs.push_back(o.value.constant()); break;
      case ValueRef::Kind::Builtin: outputs.push_back(env.builtin(static_cast<Builtin>(o.value.index))); break;
      case ValueRef::Kind::None: throw std::logic_error(spec.type + ": an output expanded into nothing");
    }
  }
  return outputs;
}

}  // namespace

namespace {

std::vector<Value> evaluateOpAt(const Op& op, const std::vector<Value>& inputs, const EvalEnvironment& env,
                                TextureCache* textures, const std::string& graphDir, FetchCursor* cursor) {
  std::vector<Value> converted(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) converted[i] = inputs[i].convertedTo(op.inputTypes[i]);
  if (!op.spec->eval)
    throw std::runtime_error("node '" + op.nodeId + "' (" + op.spec->type + ") has no double reference");
  OpEvalContext ctx(op, converted, env, textures, graphDir, cursor);
  op.spec->eval(ctx);
  std::vector<Value> out = ctx.take();
  for (size_t i = 0; i < out.size(); ++i)
    if (op.outputTypes[i] != Type::Invalid && out[i].type != op.outputTypes[i])
      throw std::logic_error("eval of '" + op.spec->type + "' produced " + std::string(typeName(out[i].type)) +
                             " for output '" + op.spec->outputs[i].name + "' typed " +
                             std::string(typeName(op.outputTypes[i])));
  return out;
}

}  // namespace

std::vector<Value> evaluateOp(const Op& op, const std::vector<Value>& inputs, const EvalEnvironment& env,
                              TextureCache* textures, const std::string& graphDir) {
  return evaluateOpAt(op, inputs, env, textures, graphDir, nullptr);
}

std::vector<Value> evaluateNode(const NodeSpec& spec, const nlohmann::json& options,
                                const std::vector<std::pair<std::string, Value>>& inputs, const EvalEnvironment& env,
                                TextureCache* textures, const std::string& graphDir) {
  // A name the node does not have would otherwise leave its default in place: a misspelt
  // hard case would test the default and pass.
  if (!options.is_object() && !options.is_null()) throw std::invalid_argument(spec.type + ": options must be an object");
  for (auto it = options.begin(); it != options.end(); ++it) {
    int oi = spec.optionIndex(it.key());
    if (oi < 0) throw std::invalid_argument(spec.type + ": no option '" + it.key() + "'" + namesOf(spec.options));
    std::string why = checkOption(spec.options[static_cast<size_t>(oi)], it.value(), graphDir);
    if (!why.empty()) throw std::invalid_argument(spec.type + ": option '" + it.key() + "' " + why);
  }
  NodePorts ports = portsOfNode(spec, options);  // the options are valid: checked above
  for (const auto& [name, value] : inputs)
    if (ports.inputIndex(name) < 0) throw std::invalid_argument(spec.type + ": no input '" + name + "'" + namesOf(ports.inputs));
  for (const auto& [name, value] : inputs)
    if (ports.inputs[static_cast<size_t>(ports.inputIndex(name))].derived)
      throw std::invalid_argument(spec.type + ": input '" + name + "' is computed by the node itself");
  if (spec.expand || spec.derive) return evaluateExpanded(spec, options, ports, inputs, env, graphDir);
  Op op;
  op.spec = &spec;
  op.nodeId = spec.type;
  op.setOptions(completeOptions(spec, options));
  op.parsedOptions = parseOptions(spec, op.options());
  std::vector<Value> values;
  std::vector<Type> sourceTypes;
  for (const auto& p : spec.inputs) {
    const Value* given = nullptr;
    for (const auto& [name, value] : inputs)
      if (name == p.name) given = &value;
    if (given) values.push_back(*given);
    else if (p.defaultValue) values.push_back(*p.defaultValue);
    else if (p.defaultBuiltin) values.push_back(env.builtin(*p.defaultBuiltin));
    else throw std::invalid_argument(spec.type + ": required input '" + p.name + "' is not given");
    sourceTypes.push_back(values.back().type);
  }
  PortTyping t = typePorts(spec, *op.parsedOptions, sourceTypes, [](int) { return std::string("the value given"); });
  if (!t.error.empty()) throw std::invalid_argument(spec.type + ": " + t.error);
  op.inputTypes = std::move(t.inputTypes);
  op.outputTypes = std::move(t.outputTypes);
  return evaluateOp(op, values, env, textures, graphDir);
}

CpuResult evaluateProgram(const Program& program, const EvalEnvironment& env, const std::vector<Value>& parameters,
                          const TextureFetches* fetches, FilterNudge* nudge) {
  CpuResult result;
  TextureCache textures;
  FetchCursor cursor{fetches, {}, nudge};
  if (nudge) nudge->count = 0;
  result.opOutputs.resize(program.ops.size());
  auto valueOf = [&](const ValueRef& r) -> Value {
    switch (r.kind) {
      case ValueRef::Kind::Op:
        return result.opOutputs[static_cast<size_t>(r.index)][static_cast<size_t>(r.port)];
      case ValueRef::Kind::Param:
        return static_cast<size_t>(r.index) < parameters.size() ? parameters[static_cast<size_t>(r.index)]
                                                                : program.parameters[static_cast<size_t>(r.index)].defaultValue;
      case ValueRef::Kind::Const: return r.constant();
      case ValueRef::Kind::Builtin: return env.builtin(static_cast<Builtin>(r.index));
      case ValueRef::Kind::None: break;
    }
    throw std::logic_error("evaluateProgram: unset value reference");
  };
  for (size_t i = 0; i < program.ops.size(); ++i) {
    const Op& op = program.ops[i];
    std::vector<Value> inputs;
    inputs.reserve(op.inputs.size());
    for (const auto& in : op.inputs) inputs.push_back(valueOf(in));
    result.opOutputs[i] = evaluateOpAt(op, inputs, env, &textures, program.directory, fetches || nudge ? &cursor : nullptr);
  }
  for (const auto& out : program.outputs) result.outputs.push_back(valueOf(out.value).convertedTo(out.type));
  return result;
}

}  // namespace wg
