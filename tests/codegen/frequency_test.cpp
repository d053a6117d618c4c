// Frequency analysis (codegen/frequency.h), its report (codegen/frequency_report.h) and the
// GLSL cost estimate the report uses (codegen/glsl_cost.h), on small hand-made graphs.
#include <gtest/gtest.h>

#include <algorithm>

#include "codegen/compile.h"
#include "codegen/frequency.h"
#include "codegen/frequency_report.h"
#include "codegen/glsl_cost.h"
#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;


Frequency opFrequency(const Program& p, const std::vector<Frequency>& f, const std::string& id) {
  int i = opIndex(p, id);
  if (i < 0) throw std::runtime_error("no op '" + id + "'");
  return f[static_cast<size_t>(i)];
}

// k2 = k * 2, kt = k2 + time, kn = sin(kt): parameters and time only. shade reads kn and
// the uv, so it varies per pixel.
const std::string kParameterChain = graphJson(
    R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
       {"id": "t", "type": "time"},
       {"id": "k2", "type": "mul", "inputs": {"a": "$k", "b": 2}},
       {"id": "kt", "type": "add", "inputs": {"a": "k2.out", "b": "t.out"}},
       {"id": "kn", "type": "sin", "inputs": {"x": "kt.out"}},
       {"id": "shade", "type": "mul", "inputs": {"a": "l.out", "b": "kn.out"}})",
    R"("fragment": {"alpha": "shade.out", "color": [1, 0, 0]})", R"("k": {"type": "float", "default": 0.5})");

TEST(Frequency, AParameterOnlyChainIsPerDraw) {
  Program p = finalProgram(kParameterChain);
  auto f = analyseFrequency(p);
  ASSERT_EQ(f.size(), p.ops.size());
  for (const char* id : {"t", "k2", "kt", "kn"}) EXPECT_EQ(opFrequency(p, f, id), Frequency::PerDraw) << id;
  for (const char* id : {"u", "l", "shade"}) EXPECT_EQ(opFrequency(p, f, id), Frequency::PerFragment) << id;
  EXPECT_EQ(frequencyOf(ValueRef::param(0), f), Frequency::PerDraw);
  EXPECT_EQ(frequencyOf(ValueRef::builtin(Builtin::CameraPosition), f), Frequency::PerDraw);
  EXPECT_EQ(frequencyOf(ValueRef::builtin(Builtin::ScreenUv), f), Frequency::PerFragment);
}

TEST(Frequency, AnythingTouchingAVaryingIsPerVertexOrPerFragment) {
  // lift runs in the vertex stage only and reaches the fragment stage through a varying;
  // glow reads that varying; the sun term stays per-draw however it is used.
  Program p = finalProgram(graphJson(
      R"({"id": "wp", "type": "world_position"},
         {"id": "lift", "type": "add", "inputs": {"a": "wp.out", "b": "$offset"}},
         {"id": "sun", "type": "sun_direction"},
         {"id": "sd", "type": "dot", "inputs": {"a": "sun.out", "b": "$dir"}},
         {"id": "h", "type": "length", "inputs": {"x": "lift.out"}},
         {"id": "glow", "type": "mul", "inputs": {"a": "h.out", "b": "sd.out"}})",
      R"("vertex": {"position": "lift.out"}, "fragment": {"alpha": "glow.out", "color": [0, 0, 1]})",
      R"("offset": {"type": "vec3", "default": [0, 1, 0]}, "dir": {"type": "vec3", "default": [0, 1, 0]})"));
  auto f = analyseFrequency(p);
  ASSERT_EQ(findOp(p, "lift")->stage, unsigned{kVertexStage});
  EXPECT_EQ(opFrequency(p, f, "wp"), Frequency::PerVertex);
  EXPECT_EQ(opFrequency(p, f, "lift"), Frequency::PerVertex);
  EXPECT_EQ(opFrequency(p, f, "h"), Frequency::PerFragment);
  EXPECT_EQ(opFrequency(p, f, "glow"), Frequency::PerFragment);
  EXPECT_EQ(opFrequency(p, f, "sun"), Frequency::PerDraw);
  EXPECT_EQ(opFrequency(p, f, "sd"), Frequency::PerDraw);
}

TEST(Frequency, ConstantsAreConstantAndFoldAway) {
  const std::string json = graphJson(
      R"({"id": "c1", "type": "mul", "inputs": {"a": 2, "b": 3}},
         {"id": "c2", "type": "add", "inputs": {"a": "c1.out", "b": 1}},
         {"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
         {"id": "ck", "type": "mul", "inputs": {"a": "c2.out", "b": "$k"}},
         {"id": "col", "type": "combine", "inputs": {"x": "ck.out", "y": "l.out"}})",
      R"("fragment": {"alpha": "c2.out", "color": "col.out"})", R"("k": {"type": "float", "default": 0.5})");
  // Before the passes: the chain is there, constant; the rest as everywhere (no stages
  // decided yet, so a varying op counts as per-fragment).
  Program resolved = resolveText(json);
  auto before = analyseFrequency(resolved);
  EXPECT_EQ(opFrequency(resolved, before, "c1"), Frequency::Constant);
  EXPECT_EQ(opFrequency(resolved, before, "c2"), Frequency::Constant);
  EXPECT_EQ(opFrequency(resolved, before, "ck"), Frequency::PerDraw);
  EXPECT_EQ(opFrequency(resolved, before, "l"), Frequency::PerFragment);
  // After: folding left a constant where the chain was.
  Program p = finalProgram(json);
  auto f = analyseFrequency(p);
  EXPECT_FALSE(findOp(p, "c1"));
  EXPECT_FALSE(findOp(p, "c2"));
  EXPECT_EQ(frequencyOf(outputOf(p, OutputSlot::FragmentAlpha).value, f), Frequency::Constant);
  EXPECT_EQ(opFrequency(p, f, "ck"), Frequency::PerDraw);
}

TEST(FrequencyReport, TheRootIsTheMaximalPerDrawSubexpression) {
  Program p = finalProgram(kParameterChain);
  FrequencyReport r = frequencyReport(p);
  EXPECT_EQ(r.counts[static_cast<size_t>(Frequency::PerDraw)], 4);
  EXPECT_EQ(r.counts[static_cast<size_t>(Frequency::PerFragment)], 3);
  // k * 2, + u_time and sin(): one operation each; reading u_time costs nothing.
  EXPECT_EQ(r.perDrawInFragment, 4);
  EXPECT_EQ(r.perDrawCost, 3);
  EXPECT_EQ(r.fragmentTotalCost, 5) << "and length(uv), shade's product";
  ASSERT_EQ(r.roots.size(), 1u) << formatFrequencyReport(p, r);
  const PerDrawRoot& c = r.roots[0];
  EXPECT_EQ(c.op, opIndex(p, "kn")) << "the root is the last per-draw op, not one inside the chain";
  EXPECT_EQ(c.ports, std::vector<int>{0});
  std::vector<int> want = {opIndex(p, "t"), opIndex(p, "k2"), opIndex(p, "kt"), opIndex(p, "kn")};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(c.ops, want);
  EXPECT_EQ(c.cost, 3);
  std::string text = formatFrequencyReport(p, r);
  EXPECT_NE(text.find("t: 7 ops after the passes: 0 constant, 4 per-draw, 0 per-vertex, 3 per-fragment"), std::string::npos)
      << text;
  EXPECT_NE(text.find("node 'kn' (sin) output out (float): 3 operations from 4 ops"), std::string::npos) << text;
}

TEST(FrequencyReport, AUniformReadAloneIsNoRoot) {
  // The time node is per-draw and read per pixel, but it is the uniform already.
  Program p = finalProgram(graphJson(
      R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
         {"id": "t", "type": "time"}, {"id": "m", "type": "mul", "inputs": {"a": "l.out", "b": "t.out"}})",
      R"("fragment": {"alpha": "m.out", "color": [1, 0, 0]})"));
  FrequencyReport r = frequencyReport(p);
  EXPECT_EQ(r.perDrawInFragment, 1);
  EXPECT_EQ(r.perDrawCost, 0);
  EXPECT_TRUE(r.roots.empty()) << formatFrequencyReport(p, r);
  EXPECT_NE(formatFrequencyReport(p, r).find("per-draw values computed per pixel: none"), std::string::npos);
}

TEST(FrequencyReport, PerDrawWorkOnlyTheVertexStageDoesCostsNoPixel) {
  // The parameter chain feeds only the vertex position: no fragment work to move.
  Program p = finalProgram(graphJson(
      R"({"id": "wp", "type": "world_position"},
         {"id": "k2", "type": "mul", "inputs": {"a": "$k", "b": 2}},
         {"id": "lift", "type": "add", "inputs": {"a": "wp.out", "b": "k2.out"}})",
      R"("vertex": {"position": "lift.out"}, "fragment": {"color": [1, 0, 0]})", R"("k": {"type": "float", "default": 0.5})"));
  FrequencyReport r = frequencyReport(p);
  EXPECT_EQ(r.ops[static_cast<size_t>(opIndex(p, "k2"))], Frequency::PerDraw);
  EXPECT_EQ(r.perDrawInFragment, 0);
  EXPECT_TRUE(r.roots.empty());
}

TEST(GlslCost, CountsOperatorsAndCallsNotSignsConstructorsOrComments) {
  GlslCost cost;
  EXPECT_EQ(cost.of("a + b * c"), 2);
  EXPECT_EQ(cost.of("-x * 2.0"), 1) << "a unary minus is free";
  EXPECT_EQ(cost.of("max(x, 1e-30) - 1.5e+3"), 2) << "an exponent's sign is no subtraction";
  EXPECT_EQ(cost.of("vec3(a, b.xy)"), 0) << "constructors and swizzles are free";
  EXPECT_EQ(cost.of("float y = x < 0.5 ? a : b;"), 2);
  EXPECT_EQ(cost.of("a // b + c\n"), 0) << "comments are skipped";
  EXPECT_EQ(cost.of("texture(s, uv).rgb"), 1);
}

TEST(GlslCost, ALibraryCallCostsItsBody) {
  GlslCost cost;
  // v * inversesqrt(max(dot(v, v), 1e-30)): a product and three calls.
  EXPECT_EQ(cost.ofFunction("wg_safe_normalize_vec3"), 4);
  EXPECT_EQ(cost.of("wg_safe_normalize_vec3(a + b)"), 5);
  EXPECT_EQ(cost.ofFunction("wg_not_in_the_library"), 0);
}

}  // namespace
}  // namespace wg
