// simplifyPass: an op that equals one of its inputs for the constants it is given (x * 1,
// x + 0, x / 1, mix(a, b, 0 or 1)) is replaced by that input; anything else stays.
#include <gtest/gtest.h>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

const char* kParams = R"("x": {"type": "float", "default": 0.5}, "y": {"type": "float", "default": 0.25})";

// The parameter index of `name`, as a ValueRef reads it.
ValueRef param(const Program& p, const std::string& name) {
  for (size_t i = 0; i < p.parameters.size(); ++i)
    if (p.parameters[i].name == name) return ValueRef::param(static_cast<int>(i));
  return {};
}

// One op `node` with `inputs` feeding alpha, simplified once.
struct Simplified {
  Program program;
  PassResult result;
};
Simplified simplifyOne(const std::string& type, const std::string& inputs) {
  Simplified s;
  s.program = resolveText(
      graphJson(R"({"id": "n", "type": ")" + type + R"(", "inputs": {)" + inputs + "}}", R"("fragment": {"alpha": "n.out"})",
                kParams));
  Passes ps;
  s.result = simplifyPass(s.program, ps.ctx);
  return s;
}

TEST(SimplifyPass, EachIdentityIsReplacedByTheInputItKeeps) {
  struct Case {
    const char* type;
    const char* inputs;
    const char* kept;      // the parameter the output reads afterwards
    const char* keptPort;  // named in the removal's reason
  };
  const Case cases[] = {
      {"mul", R"("a": "$x", "b": 1)", "x", "a"},  {"mul", R"("a": 1, "b": "$y")", "y", "b"},
      {"add", R"("a": "$x", "b": 0)", "x", "a"},  {"add", R"("a": 0, "b": "$y")", "y", "b"},
      {"sub", R"("a": "$x", "b": 0)", "x", "a"},  {"div", R"("a": "$x", "b": 1)", "x", "a"},
      {"mix", R"("a": "$x", "b": "$y", "t": 0)", "x", "a"}, {"mix", R"("a": "$x", "b": "$y", "t": 1)", "y", "b"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.type) + " {" + c.inputs + "}");
    Simplified s = simplifyOne(c.type, c.inputs);
    EXPECT_EQ(s.result, PassResult::Changed);
    EXPECT_TRUE(s.program.ops.empty());
    EXPECT_EQ(outputOf(s.program, OutputSlot::FragmentAlpha).value, param(s.program, c.kept));
    const Removal* r = findRemoval(s.program, "n");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->reason, std::string("simplified: equals its input '") + c.keptPort + "'");
  }
}

TEST(SimplifyPass, WhatIsNotAnIdentityStays) {
  const char* cases[][2] = {
      {"sub", R"("a": 0, "b": "$y")"},           // 0 - y is -y
      {"div", R"("a": 1, "b": "$y")"},           // 1 / y
      {"mul", R"("a": "$x", "b": 2)"},           // not the unit
      {"add", R"("a": "$x", "b": "$y")"},        // nothing constant
      {"mix", R"("a": "$x", "b": "$y", "t": 0.5)"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c[0]) + " {" + c[1] + "}");
    Simplified s = simplifyOne(c[0], c[1]);
    EXPECT_EQ(s.result, PassResult::Unchanged);
    ASSERT_EQ(s.program.ops.size(), 1u);
    EXPECT_FALSE(findRemoval(s.program, "n"));
  }
}

TEST(SimplifyPass, AScalarTimesAVectorOfOnesIsASplatNotTheScalar) {
  Program p = resolveText(graphJson(R"({"id": "n", "type": "mul", "inputs": {"a": "$x", "b": [1, 1, 1]}})",
                                    R"("fragment": {"color": "n.out"})", kParams));
  Passes ps;
  EXPECT_EQ(simplifyPass(p, ps.ctx), PassResult::Unchanged);
  ASSERT_EQ(p.ops.size(), 1u);
  EXPECT_EQ(p.ops[0].outputTypes[0], Type::Vec3);
}

TEST(SimplifyPass, ChainsCollapseInOneSweepAndLaterOpsAreRewired) {
  Program p = resolveText(graphJson(
      R"({"id": "one", "type": "mul", "inputs": {"a": "$x", "b": 1}},
         {"id": "zero", "type": "add", "inputs": {"a": "one.out", "b": 0}},
         {"id": "keep", "type": "mul", "inputs": {"a": "zero.out", "b": "$y"}})",
      R"("fragment": {"alpha": "keep.out"})", kParams));
  Passes ps;
  EXPECT_EQ(simplifyPass(p, ps.ctx), PassResult::Changed);
  ASSERT_EQ(p.ops.size(), 1u);
  EXPECT_EQ(p.ops[0].nodeId, "keep");
  EXPECT_EQ(p.ops[0].inputs[0], param(p, "x")) << "keep reads x directly";
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value, ValueRef::op(0, 0)) << "the output follows keep's new index";
  EXPECT_TRUE(findRemoval(p, "one"));
  EXPECT_TRUE(findRemoval(p, "zero"));
  EXPECT_EQ(simplifyPass(p, ps.ctx), PassResult::Unchanged) << "nothing is left to simplify";
}

}  // namespace
}  // namespace wg
