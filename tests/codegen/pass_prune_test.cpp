// prunePass: what no output reaches goes, with the reason recorded.
#include <gtest/gtest.h>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

TEST(PrunePass, RemovesUnreachableOpsAndRecordsWhy) {
  Program p = resolveText(graphJson(
      R"({"id": "u", "type": "uv"}, {"id": "r", "type": "length", "inputs": {"x": "u.out"}},
         {"id": "junk", "type": "time"}, {"id": "junk2", "type": "sin", "inputs": {"x": "junk.out"}})",
      R"("fragment": {"alpha": "r.out"})"));
  ASSERT_EQ(p.ops.size(), 4u);
  Passes ps;
  EXPECT_EQ(prunePass(p, ps.ctx), PassResult::Changed);
  EXPECT_EQ(p.ops.size(), 2u);
  EXPECT_TRUE(findOp(p, "u") && findOp(p, "r"));
  EXPECT_FALSE(findOp(p, "junk") || findOp(p, "junk2"));
  ASSERT_TRUE(findRemoval(p, "junk"));
  ASSERT_TRUE(findRemoval(p, "junk2"));
  EXPECT_NE(findRemoval(p, "junk")->reason.find("unreachable"), std::string::npos);
  // References were renumbered: the output still reads 'r', which still reads 'u'.
  const ProgramOutput& alpha = outputOf(p, OutputSlot::FragmentAlpha);
  ASSERT_EQ(alpha.value.kind, ValueRef::Kind::Op);
  EXPECT_EQ(p.ops[static_cast<size_t>(alpha.value.index)].nodeId, "r");
  EXPECT_EQ(findOp(p, "r")->inputs[0], ValueRef::op(opIndex(p, "u"), 0));
  EXPECT_TRUE(ps.diags.empty());
  // A second run finds nothing more to do.
  EXPECT_EQ(prunePass(p, ps.ctx), PassResult::Unchanged);
}

TEST(PrunePass, RemovesUnusedParametersAndRenumbersTheRest) {
  Program p = resolveText(graphJson(
      R"({"id": "u", "type": "uv"},
         {"id": "s", "type": "split", "inputs": {"v": "u.out"}},
         {"id": "m", "type": "mul", "inputs": {"a": "s.x", "b": "$used"}},
         {"id": "dead", "type": "mul", "inputs": {"a": "s.y", "b": "$only_dead"}})",
      R"("fragment": {"alpha": "m.out"})",
      R"("unused": {"type": "float", "default": 1},
         "only_dead": {"type": "float", "default": 2},
         "used": {"type": "float", "default": 3})"));
  ASSERT_EQ(p.parameters.size(), 3u);
  Passes ps;
  EXPECT_EQ(prunePass(p, ps.ctx), PassResult::Changed);
  ASSERT_EQ(p.parameters.size(), 1u);
  EXPECT_EQ(p.parameters[0].name, "used");
  EXPECT_EQ(findOp(p, "m")->inputs[1], ValueRef::param(0));
  ASSERT_TRUE(findRemoval(p, "$unused"));
  ASSERT_TRUE(findRemoval(p, "$only_dead"));
  EXPECT_EQ(findRemoval(p, "$unused")->reason, "unused");
  EXPECT_TRUE(findRemoval(p, "dead"));
  EXPECT_FALSE(findRemoval(p, "$used"));
}

TEST(PrunePass, ParameterFeedingAnOutputDirectlyIsKept) {
  Program p = resolveText(graphJson(R"({"id": "u", "type": "uv"})", R"("fragment": {"alpha": "$a"})",
                                    R"("a": {"type": "float", "default": 0.5}, "b": {"type": "float", "default": 1})"));
  Passes ps;
  prunePass(p, ps.ctx);
  EXPECT_TRUE(hasParameter(p, "a"));
  EXPECT_FALSE(hasParameter(p, "b"));
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value, ValueRef::param(0));
  EXPECT_TRUE(p.ops.empty());
}

}  // namespace
}  // namespace wg
