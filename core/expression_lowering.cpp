#include "core/expression_lowering.h"

#include "core/expression_types.h"
#include "core/node_options.h"
#include "core/port_typing.h"

namespace wg::expr {
namespace {

const char* comparisonOption(const std::string& op) {
  if (op == "<") return "less";
  if (op == "<=") return "less_equal";
  if (op == ">") return "greater";
  if (op == ">=") return "greater_equal";
  if (op == "==") return "equal";
  return "not_equal";
}

const char* arithmeticNode(const std::string& op) {
  if (op == "+") return "add";
  if (op == "-") return "sub";
  if (op == "*") return "mul";
  return "div";
}

struct LoweringStop {
  FormulaError error;
};

class Lowering {
 public:
  Lowering(const Ast& ast, const std::vector<Type>& types, const LoweringContext& context, Program& program)
      : ast_(ast), types_(types), context_(context), program_(program) {}

  LoweredFormula run() {
    values_.assign(ast_.nodes.size(), ValueRef{});
    for (std::size_t i = 0; i < ast_.nodes.size(); ++i) {
      const Node& n = ast_.nodes[i];
      values_[i] = lower(n);
      Type got = n.kind == NodeKind::Compare ? Type::Bool : program_.typeOf(values_[i]);
      if (got != types_[i])  // a defect of ours, not of the formula: said plainly, not hidden
        fail(n.span, "internal error: the formula's type rules give " + std::string(typeName(types_[i])) +
                         " here and the node computing it gives " + std::string(typeName(got)));
    }
    ValueRef root = values_[static_cast<std::size_t>(ast_.root)];
    return {root, program_.typeOf(root)};
  }

 private:
  [[noreturn]] static void fail(Span span, std::string message) { throw LoweringStop{{span, std::move(message)}}; }

  ValueRef operand(const Node& n, std::size_t k) const { return values_[static_cast<std::size_t>(n.operands[k])]; }

  // One op of node `type`; unconnected ports take their defaults. Typed by the node's own
  // rules, which agree with typeFormula's (tests/core/expression_lowering_test.cpp).
  int addOp(std::string_view type, const nlohmann::json& options, const std::vector<ValueRef>& inputs, Span span) {
    const NodeSpec* spec = context_.registry->find(type);
    if (!spec) fail(span, "the node '" + std::string(type) + "' that computes this is not in the registry");
    Op op;
    op.spec = spec;
    op.nodeId = context_.nodeId;
    op.where = context_.where ? context_.where(span) : SourceRef{};
    op.setOptions(completeOptions(*spec, options));
    op.parsedOptions = parseOptions(*spec, op.options());
    std::size_t n = spec->inputs.size();
    op.inputs.assign(n, ValueRef{});
    std::vector<Type> sourceTypes(n, Type::Invalid);
    for (std::size_t k = 0; k < n; ++k) {
      if (k < inputs.size()) {
        op.inputs[k] = inputs[k];
      } else if (spec->inputs[k].defaultValue) {
        op.inputs[k] = ValueRef::constant_(*spec->inputs[k].defaultValue);
      } else {
        fail(span, "'" + std::string(type) + "' needs its input '" + spec->inputs[k].name + "'");
      }
      sourceTypes[k] = program_.typeOf(op.inputs[k]);
    }
    PortTyping typed = typePorts(*spec, *op.parsedOptions, sourceTypes, [&](int k) {
      return "argument " + std::to_string(k + 1);
    });
    if (!typed.error.empty()) fail(span, typed.error);
    op.inputTypes = std::move(typed.inputTypes);
    op.outputTypes = std::move(typed.outputTypes);
    program_.ops.push_back(std::move(op));
    return static_cast<int>(program_.ops.size()) - 1;
  }

  ValueRef single(std::string_view type, const nlohmann::json& options, const std::vector<ValueRef>& inputs, Span span) {
    return ValueRef::op(addOp(type, options, inputs, span), 0);
  }

  // vecN(...): the arguments' components in order (a float alone fills every one).
  ValueRef construct(const Node& n) {
    int want = componentCount(*parseType(n.text));
    std::vector<ValueRef> components;
    for (std::size_t k = 0; k < n.operands.size() && static_cast<int>(components.size()) < want; ++k) {
      ValueRef arg = operand(n, k);
      Type t = program_.typeOf(arg);
      if (t == Type::Float) {
        components.push_back(arg);
        continue;
      }
      int split = addOp("split", nlohmann::json::object(), {arg}, ast_.nodes[static_cast<std::size_t>(n.operands[k])].span);
      for (int c = 0; c < componentCount(t) && static_cast<int>(components.size()) < want; ++c)
        components.push_back(ValueRef::op(split, c));
    }
    while (static_cast<int>(components.size()) < want) components.push_back(components.front());  // vec3(0.5)
    return single("combine", {{"type", n.text}}, components, n.span);
  }

  ValueRef lower(const Node& n) {
    switch (n.kind) {
      case NodeKind::Number: return ValueRef::constant_(Value::scalar(n.value));
      case NodeKind::Name: {
        auto it = context_.inputs.find(n.text);
        if (it == context_.inputs.end()) fail(n.span, "unknown input '" + n.text + "'");
        return it->second;
      }
      case NodeKind::Negate: return single("negate", nlohmann::json::object(), {operand(n, 0)}, n.span);
      case NodeKind::Binary:
        return single(arithmeticNode(n.text), nlohmann::json::object(), {operand(n, 0), operand(n, 1)}, n.span);
      case NodeKind::Compare: return ValueRef{};  // taken apart by the '?:' it conditions
      case NodeKind::Select: {
        const Node& condition = ast_.nodes[static_cast<std::size_t>(n.operands[0])];
        return single("select", {{"op", comparisonOption(condition.text)}},
                      {operand(condition, 0), operand(condition, 1), operand(n, 1), operand(n, 2)}, n.span);
      }
      case NodeKind::Swizzle: {
        std::string mask;  // the swizzle node reads xyzw; the formula may write rgba or stpq
        for (char c : n.text) mask += "xyzw"[std::string_view("xyzwrgbastpq").find(c) % 4];
        return single("swizzle", {{"mask", mask}}, {operand(n, 0)}, n.span);
      }
      case NodeKind::Call: {
        if (n.text == "vec2" || n.text == "vec3" || n.text == "vec4") return construct(n);
        for (const auto& f : formulaFunctions())
          if (f.name == n.text && f.arity == static_cast<int>(n.operands.size())) {
            std::vector<ValueRef> args;
            for (std::size_t k = 0; k < n.operands.size(); ++k) args.push_back(operand(n, k));
            return single(f.node, nlohmann::json::object(), args, n.span);
          }
        fail(n.span, "unknown function '" + n.text + "'");
      }
    }
    return ValueRef{};
  }

  const Ast& ast_;
  const std::vector<Type>& types_;
  const LoweringContext& context_;
  Program& program_;
  std::vector<ValueRef> values_;
};

}  // namespace

std::variant<LoweredFormula, FormulaError> lowerFormula(const Ast& ast, const std::vector<Type>& types,
                                                        const LoweringContext& context, Program& program) {
  std::size_t before = program.ops.size();
  try {
    LoweredFormula lowered = Lowering(ast, types, context, program).run();
    return lowered;
  } catch (const LoweringStop& stop) {
    program.ops.resize(before);  // nothing half-appended
    return stop.error;
  }
}

}  // namespace wg::expr
