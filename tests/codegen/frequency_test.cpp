// Frequency analysis (codegen/frequency.h), its report (codegen/frequency_report.h) and the
// cost estimate the report reads (the operations the planner counted from the values as it
// wrote each fragment line, core/glsl_operation_count.h), on small hand-made graphs.
#include <gtest/gtest.h>

#include <algorithm>

#include "codegen/compile.h"
#include "codegen/frequency.h"
#include "codegen/frequency_report.h"
#include "codegen/shader_plan.h"
#include "core/emit_context.h"
#include "nodes/glsl_library_cost.h"
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

TEST(GlslCost, ALibraryCallCostsItsBody) {
  GlslCost cost;
  // v * inversesqrt(max(dot(v, v), 1e-30)): a product and three calls.
  EXPECT_EQ(cost.ofFunction("wg_safe_normalize_vec3"), 4);
  EXPECT_EQ(cost.ofFunction("wg_not_in_the_library"), 0);
  // What a node's call costs is the library's count of the body, plus its arguments.
  EXPECT_EQ(EmitContext::call("wg_safe_normalize_vec3", {GlslExpr::name("a") + " + " + GlslExpr::name("b")}).operations(), 5);
}

// kParameterChain with one more node in its per-draw chain, between k2 and kt: `type`
// with inputs `ports` (a JSON object without its closing brace), one of them k2.
std::string chainWithOneMore(const std::string& type, const std::string& ports) {
  return graphJson(
      R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
         {"id": "t", "type": "time"},
         {"id": "k2", "type": "mul", "inputs": {"a": "$k", "b": 2}},
         {"id": "extra", "type": ")" + type + R"(", "inputs": )" + ports + R"(}},
         {"id": "kt", "type": "add", "inputs": {"a": "extra.out", "b": "t.out"}},
         {"id": "kn", "type": "sin", "inputs": {"x": "kt.out"}},
         {"id": "shade", "type": "mul", "inputs": {"a": "l.out", "b": "kn.out"}})",
      R"("fragment": {"alpha": "shade.out", "color": [1, 0, 0]})", R"("k": {"type": "float", "default": 0.5})");
}

// One more node in a per-draw chain adds exactly its own count to the op, the root, the
// per-draw total and the stage: a product 1, a library call the library's count of its body.
TEST(FrequencyReport, OneMoreNodeAddsExactlyItsOperations) {
  Program base = finalProgram(kParameterChain);
  FrequencyReport before = frequencyReport(base);
  ASSERT_EQ(before.roots.size(), 1u);
  struct Case {
    std::string type, ports;
    int operations;
  };
  // pow's base k * 2 is a parameter's: no fact makes the native pow safe, so the guarded
  // wg_safe_pow_float is called, with names for arguments.
  const Case cases[] = {{"mul", R"({"a": "k2.out", "b": 3)", 1},
                        {"pow", R"({"x": "k2.out", "y": 1.5)", GlslCost().ofFunction("wg_safe_pow_float")}};
  ASSERT_GT(cases[1].operations, 1) << "the library's count, not the call's 1";
  for (const Case& c : cases) {
    SCOPED_TRACE(c.type);
    Program p = finalProgram(chainWithOneMore(c.type, c.ports));
    FrequencyReport after = frequencyReport(p);
    const int extra = opIndex(p, "extra");
    ASSERT_GE(extra, 0);
    ASSERT_EQ(after.ops[static_cast<size_t>(extra)], Frequency::PerDraw);
    EXPECT_EQ(after.fragmentCost[static_cast<size_t>(extra)], c.operations);
    EXPECT_EQ(after.perDrawCost, before.perDrawCost + c.operations);
    EXPECT_EQ(after.fragmentTotalCost, before.fragmentTotalCost + c.operations);
    ASSERT_EQ(after.roots.size(), 1u);
    EXPECT_EQ(after.roots[0].cost, before.roots[0].cost + c.operations);
    for (const char* id : {"k2", "kt", "kn", "l", "shade"})
      EXPECT_EQ(after.fragmentCost[static_cast<size_t>(opIndex(p, id))], before.fragmentCost[static_cast<size_t>(opIndex(base, id))])
          << id;
  }
}

// kParameterChain with every node and the parameter renamed, and laid out otherwise.
const std::string kRenamedChain = graphJson(
    "{\"id\":\"surface_uv\",\"type\":\"uv\"},\n\t{\"id\": \"uv_length\", \"type\": \"length\", \"inputs\": {\"x\": \"surface_uv.out\"}},"
    R"(
    {   "id" : "clock",   "type" : "time"   },
    {"id": "gain_twice", "type": "mul", "inputs": {"a": "$wave_gain", "b": 2}},
    {"id": "gain_plus_time", "type": "add", "inputs": {"a": "gain_twice.out", "b": "clock.out"}},
    {"id": "sine_of_it", "type": "sin", "inputs": {"x": "gain_plus_time.out"}},
    {"id": "final_shade", "type": "mul", "inputs": {"a": "uv_length.out", "b": "sine_of_it.out"}})",
    R"("fragment": {"alpha": "final_shade.out", "color": [1, 0, 0]})", R"("wave_gain": {"type": "float", "default": 0.5})");

// The counts are built from the values, never from the names in the text: renaming every
// node and the parameter (which renames the shader's locals and uniform) changes none.
TEST(FrequencyReport, CostsDoNotDependOnNamesOrLayout) {
  Program a = finalProgram(kParameterChain), b = finalProgram(kRenamedChain);
  ASSERT_EQ(a.ops.size(), b.ops.size());
  const ShaderPlan planA = planShaders(a, "", false), planB = planShaders(b, "", false);
  const PlannedStage *fa = planA.stage(ShaderStage::Fragment), *fb = planB.stage(ShaderStage::Fragment);
  ASSERT_TRUE(fa && fb);
  ASSERT_NE(fa->body.text, fb->body.text) << "the names reach the shader";
  auto costs = [](const PlannedLines& lines) {
    std::vector<int> out;
    for (const PlannedStatement& s : lines.statements) out.push_back(s.cost);
    return out;
  };
  EXPECT_EQ(costs(fa->body), costs(fb->body));
  EXPECT_EQ(fa->locals.cost(), fb->locals.cost());
  FrequencyReport ra = frequencyReport(a), rb = frequencyReport(b);
  EXPECT_EQ(ra.fragmentCost, rb.fragmentCost);
  EXPECT_EQ(ra.perDrawCost, rb.perDrawCost);
  EXPECT_EQ(ra.fragmentTotalCost, rb.fragmentTotalCost);
  ASSERT_EQ(ra.roots.size(), rb.roots.size());
  for (size_t i = 0; i < ra.roots.size(); ++i) EXPECT_EQ(ra.roots[i].cost, rb.roots[i].cost);
}

// The report's total is the planner's: the locals and every body line, each counted once.
TEST(FrequencyReport, TheTotalIsThePlannersLineCounts) {
  Program p = finalProgram(graphJson(
      R"({"id": "n", "type": "normal"}, {"id": "v", "type": "view_direction"},
         {"id": "f", "type": "dot", "inputs": {"a": "n.out", "b": "v.out"}})",
      R"("fragment": {"alpha": "f.out", "color": [1, 0, 0]})"));
  const ShaderPlan plan = planShaders(p, "", false);
  const PlannedStage* frag = plan.stage(ShaderStage::Fragment);
  ASSERT_TRUE(frag);
  ASSERT_EQ(frag->locals.statements.size(), 2u);
  // b_normal and b_view_direction: one wg_safe_normalize_vec3 each, the second of a difference.
  const int normalize = GlslCost().ofFunction("wg_safe_normalize_vec3");
  EXPECT_EQ(frag->locals.cost(), 2 * normalize + 1);
  int lines = 0;
  for (const PlannedStatement& s : frag->body.statements) lines += s.cost;
  EXPECT_EQ(frequencyReport(p).fragmentTotalCost, frag->locals.cost() + lines);
  EXPECT_EQ(frequencyReport(p).fragmentCost[static_cast<size_t>(opIndex(p, "f"))], 1) << "dot()";
}

}  // namespace
}  // namespace wg
