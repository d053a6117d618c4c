#include "nodes/glsl_function_reference.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "core/expression_lowering.h"
#include "core/expression_parser.h"
#include "core/expression_types.h"
#include "nodes/registry.h"

namespace wg {
namespace {

// One op of a lowered formula evaluated in double, as the CPU backend evaluates any op.
class ReferenceOpContext final : public EvalContext {
 public:
  ReferenceOpContext(const Op& op, const std::vector<Value>& inputs, const EvalContext& outer)
      : op_(op), inputs_(inputs), outer_(outer), outputs_(op.outputTypes.size()) {}
  const Value& input(int port) const override { return inputs_.at(static_cast<size_t>(port)); }
  Type inputType(int port) const override { return op_.inputTypes.at(static_cast<size_t>(port)); }
  Type outputType(int port) const override { return op_.outputTypes.at(static_cast<size_t>(port)); }
  const ParsedOptions& parsedOptions() const override {
    if (!op_.parsedOptions) throw std::logic_error("reference op of '" + op_.spec->type + "' has no parsed options");
    return *op_.parsedOptions;
  }
  void output(int port, Value v) override { outputs_.at(static_cast<size_t>(port)) = std::move(v); }
  const EvalEnvironment& environment() const override { return outer_.environment(); }
  const NodeSpec& spec() const override { return *op_.spec; }
  using EvalContext::sampleTexture;
  Value sampleTexture(std::string_view, double, double, const SamplerState&, const UvGradient&) const override {
    throw std::logic_error("a reference formula samples no texture");
  }
  std::vector<Value> take() { return std::move(outputs_); }

 private:
  const Op& op_;
  const std::vector<Value>& inputs_;
  const EvalContext& outer_;
  std::vector<Value> outputs_;
};

// The formulas lowered into one program whose parameters are the function's inputs.
struct LoweredReference {
  Program program;
  std::vector<ValueRef> outputs;  // per output port
  std::vector<Type> outputTypes;
};

void evaluateReference(const LoweredReference& r, EvalContext& ctx) {
  std::vector<std::vector<Value>> values(r.program.ops.size());
  auto valueOf = [&](const ValueRef& ref) -> Value {
    switch (ref.kind) {
      case ValueRef::Kind::Op: return values[static_cast<size_t>(ref.index)][static_cast<size_t>(ref.port)];
      case ValueRef::Kind::Param: return ctx.input(ref.index);
      case ValueRef::Kind::Const: return ref.constant();
      case ValueRef::Kind::Builtin: return ctx.environment().builtin(static_cast<Builtin>(ref.index));
      case ValueRef::Kind::None: break;
    }
    throw std::logic_error("reference formula: unset value");
  };
  for (size_t i = 0; i < r.program.ops.size(); ++i) {
    const Op& op = r.program.ops[i];
    std::vector<Value> inputs;
    for (size_t k = 0; k < op.inputs.size(); ++k) inputs.push_back(valueOf(op.inputs[k]).convertedTo(op.inputTypes[k]));
    ReferenceOpContext inner(op, inputs, ctx);
    op.spec->eval(inner);
    values[i] = inner.take();
  }
  for (size_t p = 0; p < r.outputs.size(); ++p) ctx.output(static_cast<int>(p), valueOf(r.outputs[p]).convertedTo(r.outputTypes[p]));
}

}  // namespace

std::variant<FunctionReference, FunctionReferenceFault> makeFunctionReference(
    const FunctionSignature& signature, const nlohmann::json& reference) {
  if (!reference.is_object()) return FunctionReferenceFault{false, "must be an object: {\"output\": \"formula\", ...}"};
  auto lowered = std::make_shared<LoweredReference>();
  expr::FormulaInputs inputs;
  expr::LoweringContext lowering;
  lowering.registry = &defaultRegistry();
  lowering.nodeId = "reference";
  lowering.where = [](expr::Span) { return SourceRef{}; };
  std::vector<std::pair<std::string, Type>> outputs;
  if (signature.returns != Type::Invalid) outputs.emplace_back("out", signature.returns);
  for (const auto& p : signature.parameters) {
    if (p.type == Type::Sampler2D) continue;
    if (!isFloatScalarOrVector(p.type))
      return FunctionReferenceFault{false, "parameter '" + p.name + "' is a " + std::string(typeName(p.type)) +
                                               ": a reference formula takes float and vecN values only"};
    if (p.out) {
      outputs.emplace_back(p.name, p.type);
      continue;
    }
    lowering.inputs[p.name] = ValueRef::param(static_cast<int>(inputs.size()));
    inputs.emplace_back(p.name, p.type);
    ProgramParameter parameter;
    parameter.name = p.name;
    parameter.type = p.type;
    parameter.defaultValue = Value::ofType(p.type);
    lowered->program.parameters.push_back(std::move(parameter));
  }
  for (auto it = reference.begin(); it != reference.end(); ++it) {
    bool known = false;
    for (const auto& o : outputs) known |= o.first == it.key();
    if (!known) return FunctionReferenceFault{false, "names '" + it.key() + "', which is not an output of the function"};
  }
  for (const auto& [name, type] : outputs) {
    auto it = reference.find(name);
    if (it == reference.end() || !it->is_string())
      return FunctionReferenceFault{false, "gives no formula (a string) for output '" + name + "'; a reference covers every output"};
    auto parsed = expr::parseFormula(it->get_ref<const std::string&>());
    if (auto* e = std::get_if<expr::FormulaError>(&parsed)) return FunctionReferenceFault{true, "output '" + name + "': " + e->message};
    const expr::Ast& ast = std::get<expr::Ast>(parsed);
    auto typed = expr::typeFormula(ast, inputs);
    if (auto* e = std::get_if<expr::FormulaError>(&typed)) return FunctionReferenceFault{false, "output '" + name + "': " + e->message};
    auto value = expr::lowerFormula(ast, std::get<std::vector<Type>>(typed), lowering, lowered->program);
    if (auto* e = std::get_if<expr::FormulaError>(&value)) return FunctionReferenceFault{false, "output '" + name + "': " + e->message};
    const expr::LoweredFormula& f = std::get<expr::LoweredFormula>(value);
    if (!implicitlyConvertible(f.type, type))
      return FunctionReferenceFault{false, "output '" + name + "': the formula gives a " + std::string(typeName(f.type)) +
                                               ", the function a " + std::string(typeName(type))};
    lowered->outputs.push_back(f.value);
    lowered->outputTypes.push_back(type);
  }
  FunctionReference made;
  for (const Op& op : lowered->program.ops) {
    made.tolerance = std::max(made.tolerance, op.spec->tolerance);
    made.conditionRoundings = std::max(made.conditionRoundings, op.spec->conditionRoundings);
  }
  made.eval = [lowered](EvalContext& ctx) { evaluateReference(*lowered, ctx); };
  return made;
}

}  // namespace wg
