// csePass: ops of the same type, options and inputs merge.
#include <gtest/gtest.h>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

TEST(CsePass, MergesIdenticalFresnelNodes) {
  Program p = resolveText(graphJson(
      R"({"id": "f1", "type": "fresnel", "options": {"model": "schlick"}},
         {"id": "f2", "type": "fresnel", "options": {"model": "schlick"}},
         {"id": "f3", "type": "fresnel", "options": {"model": "exact"}},
         {"id": "m", "type": "mul", "inputs": {"a": "f1.reflectance", "b": "f2.transmittance"}},
         {"id": "n", "type": "mul", "inputs": {"a": "m.out", "b": "f3.reflectance"}})",
      R"("fragment": {"alpha": "n.out"})"));
  Passes ps;
  EXPECT_EQ(csePass(p, ps.ctx), PassResult::Changed);
  EXPECT_TRUE(findOp(p, "f1"));
  EXPECT_FALSE(findOp(p, "f2"));
  EXPECT_TRUE(findOp(p, "f3")) << "a fresnel with other options is a different computation";
  EXPECT_EQ(findOp(p, "f1")->mergedIds, std::vector<std::string>{"f2"});
  ASSERT_TRUE(findRemoval(p, "f2"));
  EXPECT_NE(findRemoval(p, "f2")->reason.find("f1"), std::string::npos);
  // The user now reads both outputs of the one that stayed, port by port.
  int f1 = opIndex(p, "f1");
  EXPECT_EQ(findOp(p, "m")->inputs[0], ValueRef::op(f1, 0));
  EXPECT_EQ(findOp(p, "m")->inputs[1], ValueRef::op(f1, 1));
  EXPECT_EQ(csePass(p, ps.ctx), PassResult::Unchanged);
}

TEST(CsePass, MergesChainsOfDuplicates) {
  Program p = resolveText(graphJson(
      R"({"id": "u1", "type": "uv"}, {"id": "u2", "type": "uv"},
         {"id": "l1", "type": "length", "inputs": {"x": "u1.out"}},
         {"id": "l2", "type": "length", "inputs": {"x": "u2.out"}},
         {"id": "s", "type": "add", "inputs": {"a": "l1.out", "b": "l2.out"}})",
      R"("fragment": {"alpha": "s.out"})"));
  Passes ps;
  EXPECT_EQ(csePass(p, ps.ctx), PassResult::Changed);
  EXPECT_EQ(p.ops.size(), 3u);
  EXPECT_EQ(findOp(p, "u1")->mergedIds, std::vector<std::string>{"u2"});
  EXPECT_EQ(findOp(p, "l1")->mergedIds, std::vector<std::string>{"l2"});
  const Op* s = findOp(p, "s");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->inputs[0], s->inputs[1]);
}

TEST(CsePass, DifferentInputsAreNotMerged) {
  Program p = resolveText(graphJson(
      R"({"id": "u", "type": "uv"},
         {"id": "a", "type": "mul", "inputs": {"a": "u.out", "b": 2}},
         {"id": "b", "type": "mul", "inputs": {"a": "u.out", "b": 3}},
         {"id": "c", "type": "mul", "inputs": {"a": 2, "b": "u.out"}},
         {"id": "s", "type": "add", "inputs": {"a": "a.out", "b": "b.out"}},
         {"id": "t", "type": "add", "inputs": {"a": "s.out", "b": "c.out"}},
         {"id": "l", "type": "length", "inputs": {"x": "t.out"}})",
      R"("fragment": {"alpha": "l.out"})"));
  Passes ps;
  EXPECT_EQ(csePass(p, ps.ctx), PassResult::Unchanged);
  EXPECT_EQ(p.ops.size(), 7u);
}

}  // namespace
}  // namespace wg
