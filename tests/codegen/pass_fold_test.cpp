// foldPass: ops whose inputs are all constant become constants, with GLSL semantics.
#include <gtest/gtest.h>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

TEST(FoldPass, ConstantProductBecomesAConstant) {
  Program p = resolveText(graphJson(R"({"id": "m", "type": "mul", "inputs": {"a": 2, "b": 3}})",
                                    R"("fragment": {"alpha": "m.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  const ProgramOutput& alpha = outputOf(p, OutputSlot::FragmentAlpha);
  ASSERT_EQ(alpha.value.kind, ValueRef::Kind::Const);
  EXPECT_EQ(alpha.value.constant().type, Type::Float);
  EXPECT_EQ(alpha.value.constant()[0], 6.0);
  EXPECT_TRUE(p.ops.empty());
  ASSERT_TRUE(findRemoval(p, "m"));
  EXPECT_NE(findRemoval(p, "m")->reason.find("folded"), std::string::npos);
}

TEST(FoldPass, ConstantChainsFoldInOneSweep) {
  Program p = resolveText(graphJson(
      R"({"id": "m", "type": "mul", "inputs": {"a": 2, "b": 3}},
         {"id": "a", "type": "add", "inputs": {"a": "m.out", "b": [1, 2, 3]}},
         {"id": "s", "type": "sub", "inputs": {"a": "a.out", "b": 0.5}})",
      R"("fragment": {"color": "s.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  EXPECT_TRUE(p.ops.empty());
  const ProgramOutput& color = outputOf(p, OutputSlot::FragmentColor);
  ASSERT_EQ(color.value.kind, ValueRef::Kind::Const);
  EXPECT_EQ(color.value.constant(), Value::vector({6.5, 7.5, 8.5}));
}

TEST(FoldPass, NeverFoldsSources) {
  Program p = resolveText(graphJson(
      R"({"id": "t", "type": "time"}, {"id": "u", "type": "uv"},
         {"id": "m", "type": "mul", "inputs": {"a": "t.out", "b": 2}},
         {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
         {"id": "sum", "type": "add", "inputs": {"a": "m.out", "b": "l.out"}})",
      R"("fragment": {"alpha": "sum.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Unchanged);
  EXPECT_EQ(p.ops.size(), 5u);
  EXPECT_TRUE(p.removed.empty());
}

TEST(FoldPass, SourceWithAConstantInputIsStillNotFolded) {
  // fresnel reads builtins (normal, view) when they are not connected: not constant.
  Program p = resolveText(graphJson(R"({"id": "f", "type": "fresnel", "inputs": {"f0": 0.04}})",
                                    R"("fragment": {"alpha": "f.reflectance"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Unchanged);
  EXPECT_TRUE(findOp(p, "f"));
}

TEST(FoldPass, DivisionByZeroStaysAnOperation) {
  Program p = resolveText(graphJson(
      R"({"id": "inf", "type": "div", "inputs": {"a": 1, "b": 0}},
         {"id": "nan", "type": "div", "inputs": {"a": 0, "b": 0}},
         {"id": "big", "type": "mul", "inputs": {"a": 3e38, "b": 10}},
         {"id": "sum", "type": "add", "inputs": {"a": "inf.out", "b": "nan.out"}},
         {"id": "all", "type": "add", "inputs": {"a": "sum.out", "b": "big.out"}})",
      R"("fragment": {"alpha": "all.out"})"));
  Passes ps;
  foldPass(p, ps.ctx);
  // inf, NaN and a float32 overflow cannot be written as literals: the GPU computes them.
  EXPECT_TRUE(findOp(p, "inf"));
  EXPECT_TRUE(findOp(p, "nan"));
  EXPECT_TRUE(findOp(p, "big"));
  EXPECT_TRUE(findOp(p, "sum"));
  EXPECT_TRUE(findOp(p, "all"));
  for (const auto& op : p.ops)
    for (const auto& in : op.inputs)
      if (in.kind == ValueRef::Kind::Const) {
        EXPECT_TRUE(in.constant().allFinite()) << op.nodeId;
      }
}

TEST(FoldPass, FiniteDivisionFolds) {
  Program p = resolveText(graphJson(R"({"id": "d", "type": "div", "inputs": {"a": 1, "b": 4}})",
                                    R"("fragment": {"alpha": "d.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value.constant()[0], 0.25);
}

TEST(FoldPass, FoldsUsingGlslSemantics) {
  // safe pow: a negative base is clamped to 0, never NaN.
  Program p = resolveText(graphJson(R"({"id": "p", "type": "pow", "inputs": {"x": -2, "y": 0.5}})",
                                    R"("fragment": {"alpha": "p.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value.constant()[0], 0.0);
}

}  // namespace
}  // namespace wg
