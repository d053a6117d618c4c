// specialisePass: static parameters become constants.
#include <gtest/gtest.h>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

TEST(SpecialisePass, StaticParametersBecomeConstantsThenFoldAway) {
  Program p = resolveText(graphJson(
      R"({"id": "u", "type": "uv"}, {"id": "s", "type": "split", "inputs": {"v": "u.out"}},
         {"id": "k4", "type": "mul", "inputs": {"a": "$k", "b": 4}},
         {"id": "m", "type": "mul", "inputs": {"a": "s.x", "b": "k4.out"}},
         {"id": "n", "type": "mul", "inputs": {"a": "m.out", "b": "$live"}})",
      R"("fragment": {"alpha": "n.out"})",
      R"("k": {"type": "float", "default": 0.25, "static": true}, "live": {"type": "float", "default": 2})"));
  Passes ps;
  EXPECT_EQ(specialisePass(p, ps.ctx), PassResult::Changed);
  const Op* k4 = findOp(p, "k4");
  ASSERT_TRUE(k4);
  ASSERT_EQ(k4->inputs[0].kind, ValueRef::Kind::Const);
  EXPECT_EQ(k4->inputs[0].constant()[0], 0.25);
  // A uniform parameter is left alone.
  EXPECT_EQ(findOp(p, "n")->inputs[1].kind, ValueRef::Kind::Param);

  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  EXPECT_FALSE(findOp(p, "k4"));
  ASSERT_TRUE(findOp(p, "m"));
  EXPECT_EQ(findOp(p, "m")->inputs[1], ValueRef::constant_(Value::scalar(1.0)));
  prunePass(p, ps.ctx);
  EXPECT_FALSE(hasParameter(p, "k"));
  EXPECT_TRUE(hasParameter(p, "live"));
  ASSERT_TRUE(findRemoval(p, "$k"));
  EXPECT_NE(findRemoval(p, "$k")->reason.find("static"), std::string::npos);
}

TEST(SpecialisePass, StaticParameterFeedingAnOutput) {
  Program p = resolveText(graphJson(R"({"id": "u", "type": "uv"})", R"("fragment": {"color": "$c"})",
                                    R"("c": {"type": "vec3", "default": [0.1, 0.2, 0.3], "static": true})"));
  Passes ps;
  EXPECT_EQ(specialisePass(p, ps.ctx), PassResult::Changed);
  const ProgramOutput& color = outputOf(p, OutputSlot::FragmentColor);
  ASSERT_EQ(color.value.kind, ValueRef::Kind::Const);
  EXPECT_EQ(color.value.constant(), Value::vector({0.1, 0.2, 0.3}));
}

TEST(SpecialisePass, NothingStaticIsUnchanged) {
  Program p = resolveText(graphJson(R"({"id": "u", "type": "uv"})", R"("fragment": {"alpha": "$a"})",
                                    R"("a": {"type": "float", "default": 1})"));
  Passes ps;
  EXPECT_EQ(specialisePass(p, ps.ctx), PassResult::Unchanged);
}

}  // namespace
}  // namespace wg
