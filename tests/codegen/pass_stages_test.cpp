// stagePass: which stage each op runs in, and what crosses as a varying.
#include <gtest/gtest.h>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

TEST(StagePass, VertexOutputMathRunsInTheVertexStage) {
  Program p = resolveText(graphJson(
      R"({"id": "wp", "type": "world_position"},
         {"id": "lift", "type": "add", "inputs": {"a": "wp.out", "b": [0, 1, 0]}})",
      R"("vertex": {"position": "lift.out"}, "fragment": {"color": [1, 0, 0]})"));
  Passes ps;
  EXPECT_NE(stagePass(p, ps.ctx), PassResult::Failed) << allText(ps.diags);
  EXPECT_EQ(findOp(p, "lift")->stage, unsigned{kVertexStage});
  EXPECT_EQ(findOp(p, "wp")->stage, unsigned{kVertexStage});
  EXPECT_TRUE(p.varyings.empty());
}

TEST(StagePass, FragmentUseOfAPerVertexValueBecomesAVarying) {
  Program p = resolveText(graphJson(
      R"({"id": "wp", "type": "world_position"},
         {"id": "lift", "type": "add", "inputs": {"a": "wp.out", "b": [0, 1, 0]}},
         {"id": "shade", "type": "saturate", "inputs": {"x": "lift.out"}})",
      R"("vertex": {"position": "lift.out"}, "fragment": {"color": "shade.out"})"));
  Passes ps;
  EXPECT_NE(stagePass(p, ps.ctx), PassResult::Failed) << allText(ps.diags);
  int lift = opIndex(p, "lift");
  EXPECT_EQ(findOp(p, "lift")->stage, unsigned{kVertexStage}) << "computed once per vertex, not again per fragment";
  EXPECT_EQ(findOp(p, "shade")->stage, unsigned{kFragmentStage});
  ASSERT_EQ(p.varyings.size(), 1u);
  EXPECT_EQ(p.varyings[0], ValueRef::op(lift, 0));
}

TEST(StagePass, UniformOnlyValuesAreRecomputedInsteadOfInterpolated) {
  Program p = resolveText(graphJson(
      R"({"id": "wp", "type": "world_position"}, {"id": "t", "type": "time"},
         {"id": "t2", "type": "mul", "inputs": {"a": "t.out", "b": 2}},
         {"id": "moved", "type": "add", "inputs": {"a": "wp.out", "b": "t2.out"}})",
      R"("vertex": {"position": "moved.out"}, "fragment": {"alpha": "t2.out", "color": [0, 0, 1]})"));
  Passes ps;
  EXPECT_NE(stagePass(p, ps.ctx), PassResult::Failed) << allText(ps.diags);
  EXPECT_EQ(findOp(p, "t2")->stage, unsigned{kVertexStage | kFragmentStage});
  EXPECT_EQ(findOp(p, "t")->stage, unsigned{kVertexStage | kFragmentStage});
  EXPECT_EQ(findOp(p, "moved")->stage, unsigned{kVertexStage});
  EXPECT_TRUE(p.varyings.empty()) << "time * 2 is the same for every vertex: no varying";
}

TEST(StagePass, SourcesAreReadInTheFragmentStageNotInterpolatedAsVaryings) {
  Program p = resolveText(graphJson(
      R"({"id": "wp", "type": "world_position"},
         {"id": "lift", "type": "add", "inputs": {"a": "wp.out", "b": [0, 1, 0]}},
         {"id": "l", "type": "length", "inputs": {"x": "wp.out"}})",
      R"("vertex": {"position": "lift.out"}, "fragment": {"alpha": "l.out"})"));
  Passes ps;
  EXPECT_NE(stagePass(p, ps.ctx), PassResult::Failed) << allText(ps.diags);
  EXPECT_EQ(findOp(p, "wp")->stage, unsigned{kVertexStage | kFragmentStage});
  EXPECT_TRUE(p.varyings.empty());
}

TEST(StagePass, ScreenUvFeedingTheVertexPositionIsWG033) {
  Program p = resolveText(graphJson(
      R"({"id": "su", "type": "screen_uv"},
         {"id": "p", "type": "swizzle", "options": {"mask": "xyx"}, "inputs": {"x": "su.out"}})",
      R"("vertex": {"position": "p.out"}, "fragment": {"color": [1, 0, 0]})"));
  Passes ps;
  EXPECT_EQ(stagePass(p, ps.ctx), PassResult::Failed);
  ASSERT_EQ(ps.diags.errorCount(), 1u) << allText(ps.diags);
  const Diagnostic& d = ps.diags.all().front();
  EXPECT_EQ(d.code, DiagCode::StageMismatch);
  EXPECT_EQ(d.node, "su");
  EXPECT_NE(d.message.find("vertex.position"), std::string::npos) << d.message;
  EXPECT_EQ(d.where.line, 1);
  EXPECT_GT(d.where.col, 1);
}

TEST(StagePass, ScreenUvInTheFragmentStageIsFine) {
  Program p = resolveText(graphJson(R"({"id": "su", "type": "screen_uv"},
                                       {"id": "l", "type": "length", "inputs": {"x": "su.out"}})",
                                    R"("fragment": {"alpha": "l.out"})"));
  Passes ps;
  EXPECT_NE(stagePass(p, ps.ctx), PassResult::Failed) << allText(ps.diags);
  EXPECT_EQ(findOp(p, "su")->stage, unsigned{kFragmentStage});
}

}  // namespace
}  // namespace wg
