// Formulas lowered to math-node ops (core/expression_lowering.h) and evaluated by the CPU
// backend: each built-in's argument order and result against the value GLSL defines,
// operators, ?: and swizzles, constructors, and every op named after the expression node
// at its place in the formula.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "codegen/cpu_backend.h"
#include "core/expression_lowering.h"
#include "core/expression_parser.h"
#include "core/expression_types.h"
#include "nodes/registry.h"

namespace wg::expr {
namespace {

struct Input {
  std::string name;
  Value value;
};

const std::vector<Input> kInputs = {{"f", Value::scalar(0.7)},
                                    {"g", Value::scalar(-2.5)},
                                    {"u", Value::vector({0.25, 4.0})},
                                    {"v", Value::vector({1.0, 2.0, 3.0})},
                                    {"n", Value::vector({0.0, 1.0, 0.0})},
                                    {"c", Value::vector({0.1, 0.2, 0.3, 0.4})}};

struct Result {
  Value value;
  Program program;
  std::string error;
  std::string stage;  // where the error came from: "parse", "type" or "lower"
};

// The formula parsed, typed, lowered into a program whose parameters are kInputs, and
// evaluated in double.
Result run(const std::string& formula) {
  Result r;
  auto parsed = parseFormula(formula);
  if (auto* e = std::get_if<FormulaError>(&parsed)) return {{}, {}, e->message, "parse"};
  const Ast& ast = std::get<Ast>(parsed);
  FormulaInputs types;
  LoweringContext context;
  context.registry = &defaultRegistry();
  context.nodeId = "e";
  context.where = [](Span s) { return SourceRef{FileName("g.json"), 7, 20 + static_cast<int>(s.offset)}; };
  for (std::size_t i = 0; i < kInputs.size(); ++i) {
    ProgramParameter p;
    p.name = kInputs[i].name;
    p.type = kInputs[i].value.type;
    p.defaultValue = kInputs[i].value;
    r.program.parameters.push_back(p);
    types.emplace_back(p.name, p.type);
    context.inputs[p.name] = ValueRef::param(static_cast<int>(i));
  }
  auto typed = typeFormula(ast, types);
  if (auto* e = std::get_if<FormulaError>(&typed)) return {{}, {}, e->message, "type"};
  auto lowered = lowerFormula(ast, std::get<std::vector<Type>>(typed), context, r.program);
  if (auto* e = std::get_if<FormulaError>(&lowered)) return {{}, {}, e->message, "lower"};
  const ValueRef& root = std::get<LoweredFormula>(lowered).value;
  CpuResult cpu = evaluateProgram(r.program, EvalEnvironment{});
  switch (root.kind) {
    case ValueRef::Kind::Op: r.value = cpu.opOutputs[static_cast<std::size_t>(root.index)][static_cast<std::size_t>(root.port)]; break;
    case ValueRef::Kind::Const: r.value = root.constant(); break;
    case ValueRef::Kind::Param: r.value = kInputs[static_cast<std::size_t>(root.index)].value; break;
    default: ADD_FAILURE() << "the formula lowered to nothing";
  }
  return r;
}

double scalar(const std::string& formula) {
  Result r = run(formula);
  EXPECT_EQ(r.error, "") << formula;
  EXPECT_EQ(r.value.type, Type::Float) << formula;
  return r.value.size() > 0 ? r.value[0] : std::nan("");
}

std::vector<double> vec(const std::string& formula) {
  Result r = run(formula);
  EXPECT_EQ(r.error, "") << formula;
  std::vector<double> out;
  for (int i = 0; i < r.value.size(); ++i) out.push_back(r.value[i]);
  return out;
}

TEST(ExpressionLowering, OperatorsAndPrecedence) {
  EXPECT_DOUBLE_EQ(scalar("f * g + 1"), 0.7 * -2.5 + 1);
  EXPECT_DOUBLE_EQ(scalar("f - g - 1"), 0.7 + 2.5 - 1);
  EXPECT_DOUBLE_EQ(scalar("-f / 2"), -0.35);
  EXPECT_EQ(vec("v * 2 - 1"), (std::vector<double>{1, 3, 5}));
  EXPECT_EQ(vec("1 - v"), (std::vector<double>{0, -1, -2}));
  EXPECT_DOUBLE_EQ(scalar("f"), 0.7);  // an input alone: no op
  EXPECT_DOUBLE_EQ(scalar("2.5"), 2.5);
}

TEST(ExpressionLowering, SelectsSwizzlesAndConstructors) {
  EXPECT_DOUBLE_EQ(scalar("f < g ? 1 : 2"), 2);
  EXPECT_DOUBLE_EQ(scalar("f >= 0.7 ? 1 : 2"), 1);
  EXPECT_DOUBLE_EQ(scalar("f != 0.7 ? 1 : 2"), 2);
  EXPECT_EQ(vec("g <= f ? v : n"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(vec("v.zx"), (std::vector<double>{3, 1}));
  EXPECT_EQ(vec("c.abg"), (std::vector<double>{0.4, 0.3, 0.2}));
  EXPECT_EQ(vec("c.qp"), (std::vector<double>{0.4, 0.3}));
  EXPECT_DOUBLE_EQ(scalar("u.yx.x"), 4.0);
  EXPECT_EQ(vec("vec3(0.5)"), (std::vector<double>{0.5, 0.5, 0.5}));
  EXPECT_EQ(vec("vec4(v, 1)"), (std::vector<double>{1, 2, 3, 1}));
  EXPECT_EQ(vec("vec3(u, f)"), (std::vector<double>{0.25, 4, 0.7}));
  EXPECT_EQ(vec("vec3(c)"), (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(vec("vec2(f, g)"), (std::vector<double>{0.7, -2.5}));
}

// Each built-in with arguments whose order matters, against the value GLSL's definition gives.
TEST(ExpressionLowering, BuiltinsTakeGlslsArgumentOrder) {
  EXPECT_DOUBLE_EQ(scalar("step(0.5, f)"), 1);  // step(edge, x)
  EXPECT_DOUBLE_EQ(scalar("step(f, 0.5)"), 0);
  EXPECT_DOUBLE_EQ(scalar("smoothstep(0, 1, 0.25)"), 0.15625);  // smoothstep(edge0, edge1, x)
  EXPECT_DOUBLE_EQ(scalar("clamp(g, -1, 1)"), -1);                // clamp(x, lo, hi)
  EXPECT_DOUBLE_EQ(scalar("mix(2, 4, 0.25)"), 2.5);               // mix(a, b, t)
  EXPECT_DOUBLE_EQ(scalar("mod(7, 3)"), 1);
  EXPECT_DOUBLE_EQ(scalar("mod(-1, 3)"), 2);  // GLSL's mod floors
  EXPECT_DOUBLE_EQ(scalar("pow(2, 3)"), 8);
  EXPECT_NEAR(scalar("atan(1, 0)"), std::numbers::pi / 2, 1e-15);  // atan(y, x)
  EXPECT_NEAR(scalar("atan(0, -1)"), std::numbers::pi, 1e-15);
  EXPECT_NEAR(scalar("atan(1)"), std::numbers::pi / 4, 1e-15);
  EXPECT_DOUBLE_EQ(scalar("min(f, g)"), -2.5);
  EXPECT_DOUBLE_EQ(scalar("max(f, g)"), 0.7);
  EXPECT_DOUBLE_EQ(scalar("dot(v, n)"), 2);
  EXPECT_DOUBLE_EQ(scalar("length(vec2(3, 4))"), 5);
  EXPECT_DOUBLE_EQ(scalar("distance(v, n)"), std::sqrt(1 + 1 + 9));
  EXPECT_EQ(vec("cross(vec3(1, 0, 0), n)"), (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(vec("reflect(vec3(1, -1, 0), n)"), (std::vector<double>{1, 1, 0}));  // reflect(I, N)
  EXPECT_EQ(vec("faceforward(n, vec3(0, -1, 0), n)"), (std::vector<double>{0, 1, 0}));  // dot(Nref, I) < 0: N
  EXPECT_EQ(vec("faceforward(n, n, n)"), (std::vector<double>{0, -1, 0}));
  // refract(I, N, eta) at 45 degrees into water: Snell's law.
  std::vector<double> t = vec("refract(normalize(vec3(1, -1, 0)), n, 1 / 1.333)");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t[0] / std::sqrt(t[0] * t[0] + t[1] * t[1]), std::sin(std::numbers::pi / 4) / 1.333, 1e-12);
  EXPECT_DOUBLE_EQ(scalar("fract(-0.25)"), 0.75);
  EXPECT_NEAR(scalar("exp(-f * 2)"), std::exp(-1.4), 1e-15);
  EXPECT_DOUBLE_EQ(scalar("abs(g) + sign(g)"), 1.5);
}

TEST(ExpressionLowering, OpsAreNamedAfterTheExpressionAtTheirPlaceInTheFormula) {
  Result r = run("mix(v, n, 1.0 - exp(-f))");
  ASSERT_EQ(r.error, "");
  ASSERT_FALSE(r.program.ops.empty());
  for (const Op& op : r.program.ops) {
    EXPECT_EQ(op.nodeId, "e");
    EXPECT_EQ(op.where.line, 7);
  }
  EXPECT_EQ(r.program.ops.back().spec->type, "mix");
  EXPECT_EQ(r.program.ops.back().where.col, 20);  // "mix" starts the formula
  EXPECT_EQ(r.program.ops.front().spec->type, "negate");
  EXPECT_EQ(r.program.ops.front().where.col, 20 + 20);  // "-f"
}

// The type rules of the formula (typeFormula) and those of the nodes computing it agree on
// every built-in, for every argument type a formula may give it.
TEST(ExpressionLowering, FormulaTypesAgreeWithTheNodesForEveryBuiltin) {
  const std::vector<std::string> samples = {"f", "u", "v", "c"};
  int accepted = 0, refused = 0;
  for (const auto& fn : formulaFunctions()) {
    std::vector<std::string> combos = {""};
    for (int k = 0; k < fn.arity; ++k) {
      std::vector<std::string> next;
      for (const auto& prefix : combos)
        for (const auto& s : samples) next.push_back(prefix + (k ? ", " : "") + s);
      combos = next;
    }
    for (const auto& args : combos) {
      std::string formula = std::string(fn.name) + "(" + args + ")";
      Result r = run(formula);
      // What the formula's rules accept, the nodes accept with the same type (the
      // lowering compares them); what they refuse never reaches the nodes.
      EXPECT_NE(r.stage, "lower") << formula << ": " << r.error;
      accepted += r.error.empty();
      refused += r.stage == "type";
    }
  }
  EXPECT_GT(accepted, 200);  // both sides of the agreement are exercised
  EXPECT_GT(refused, 200);
}

}  // namespace
}  // namespace wg::expr
