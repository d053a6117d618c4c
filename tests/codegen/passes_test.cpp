// One pass at a time, on small Programs built from inline graphs (parseGraph +
// resolveGraph): what each pass keeps, removes, folds, merges and places, and why.
// Then the emitter: only what is used appears in the GLSL, and names are generated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>

#include "codegen/compile.h"
#include "codegen/passes.h"
#include "core/graph_io.h"
#include "core/resolve.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

using test::graphJson;

std::string allText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.sorted()) s += formatText(x) + "\n";
  return s;
}

Program resolveText(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "test.json", diags);
  EXPECT_TRUE(graph) << allText(diags);
  if (!graph) return {};
  auto program = resolveGraph(*graph, defaultRegistry(), diags);
  EXPECT_TRUE(program) << allText(diags);
  if (!program) return {};
  return std::move(*program);
}

const Op* findOp(const Program& p, const std::string& id) {
  for (const auto& op : p.ops)
    if (op.nodeId == id) return &op;
  return nullptr;
}

int opIndex(const Program& p, const std::string& id) {
  for (size_t i = 0; i < p.ops.size(); ++i)
    if (p.ops[i].nodeId == id) return static_cast<int>(i);
  return -1;
}

const Removal* findRemoval(const Program& p, const std::string& what) {
  for (const auto& r : p.removed)
    if (r.what == what) return &r;
  return nullptr;
}

bool hasParameter(const Program& p, const std::string& name) {
  for (const auto& param : p.parameters)
    if (param.name == name) return true;
  return false;
}

const ProgramOutput& outputOf(const Program& p, OutputSlot slot) {
  const ProgramOutput* o = p.output(slot);
  if (!o) throw std::runtime_error("no such output");
  return *o;
}

struct Passes {
  Diagnostics diags;
  PassContext ctx{diags};
};

// --- prune ---------------------------------------------------------------------------

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

// --- fold ----------------------------------------------------------------------------

TEST(FoldPass, ConstantProductBecomesAConstant) {
  Program p = resolveText(graphJson(R"({"id": "m", "type": "mul", "inputs": {"a": 2, "b": 3}})",
                                    R"("fragment": {"alpha": "m.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  const ProgramOutput& alpha = outputOf(p, OutputSlot::FragmentAlpha);
  ASSERT_EQ(alpha.value.kind, ValueRef::Kind::Const);
  EXPECT_EQ(alpha.value.constant.type, Type::Float);
  EXPECT_EQ(alpha.value.constant[0], 6.0);
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
  EXPECT_EQ(color.value.constant, Value::vector({6.5, 7.5, 8.5}));
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
        EXPECT_TRUE(in.constant.allFinite()) << op.nodeId;
      }
}

TEST(FoldPass, FiniteDivisionFolds) {
  Program p = resolveText(graphJson(R"({"id": "d", "type": "div", "inputs": {"a": 1, "b": 4}})",
                                    R"("fragment": {"alpha": "d.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value.constant[0], 0.25);
}

TEST(FoldPass, FoldsUsingGlslSemantics) {
  // safe pow: a negative base is clamped to 0, never NaN.
  Program p = resolveText(graphJson(R"({"id": "p", "type": "pow", "inputs": {"x": -2, "y": 0.5}})",
                                    R"("fragment": {"alpha": "p.out"})"));
  Passes ps;
  EXPECT_EQ(foldPass(p, ps.ctx), PassResult::Changed);
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value.constant[0], 0.0);
}

// --- specialise ----------------------------------------------------------------------

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
  EXPECT_EQ(k4->inputs[0].constant[0], 0.25);
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
  EXPECT_EQ(color.value.constant, Value::vector({0.1, 0.2, 0.3}));
}

TEST(SpecialisePass, NothingStaticIsUnchanged) {
  Program p = resolveText(graphJson(R"({"id": "u", "type": "uv"})", R"("fragment": {"alpha": "$a"})",
                                    R"("a": {"type": "float", "default": 1})"));
  Passes ps;
  EXPECT_EQ(specialisePass(p, ps.ctx), PassResult::Unchanged);
}

// --- cse -----------------------------------------------------------------------------

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

// --- stages --------------------------------------------------------------------------

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

// --- the recipe and the emitter ------------------------------------------------------

struct Compiled {
  std::optional<CompileResult> result;
  std::string diagnostics;
  std::string text(const std::string& suffix) const {
    if (!result) return "";
    for (const auto& f : result->files)
      if (f.name.size() >= suffix.size() && f.name.compare(f.name.size() - suffix.size(), suffix.size(), suffix) == 0)
        return f.contents;
    return "";
  }
  // Every GLSL file, concatenated.
  std::string allGlsl() const {
    std::string s;
    if (result)
      for (const auto& f : result->files)
        if (f.name.find(".spv") == std::string::npos && f.name.find(".manifest") == std::string::npos) s += f.contents;
    return s;
  }
};

Compiled compileText(const std::string& json, const std::string& file = "test.json") {
  Compiled c;
  Diagnostics diags;
  auto graph = parseGraph(json, file, diags);
  if (graph) c.result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  c.diagnostics = allText(diags);
  return c;
}

Compiled compileExample(const std::string& name) {
  return compileText(test::readFile(test::sourcePath("graphs/" + name + ".json")), name + ".json");
}

TEST(Recipe, ShelfFoldsItsStaticSlopeAndPrunesTheDebugNode) {
  Compiled c = compileExample("shelf");
  ASSERT_TRUE(c.result) << c.diagnostics;
  const Program& p = c.result->program;
  EXPECT_FALSE(findOp(p, "debug_depth"));
  EXPECT_FALSE(findOp(p, "slope_scaled"));
  EXPECT_FALSE(hasParameter(p, "slope"));
  EXPECT_FALSE(hasParameter(p, "ior"));
  EXPECT_TRUE(hasParameter(p, "sky"));
  EXPECT_TRUE(findRemoval(p, "debug_depth"));
  EXPECT_TRUE(findRemoval(p, "slope_scaled"));
  EXPECT_EQ(c.result->nodesTotal, 8);
  EXPECT_EQ(c.result->nodesKept, static_cast<int>(p.ops.size()));
}

TEST(Emit, OnlyCalledLibraryFunctionsAppear) {
  Compiled lake = compileExample("lake");
  ASSERT_TRUE(lake.result) << lake.diagnostics;
  for (const char* target : {"glsl330", "es300", "vk450"}) {
    SCOPED_TRACE(target);
    std::string frag = lake.text(std::string(".") + target + ".frag");
    std::string vert = lake.text(std::string(".") + target + ".vert");
    ASSERT_FALSE(frag.empty());
    EXPECT_NE(frag.find("wg_fresnel_schlick("), std::string::npos);
    EXPECT_EQ(frag.find("wg_fresnel_exact"), std::string::npos);
    EXPECT_EQ(frag.find("wg_fresnel_power"), std::string::npos);
    EXPECT_EQ(frag.find("wg_fresnel_schlick_from_below"), std::string::npos);
    EXPECT_EQ(frag.find("wg_depth_tint_smooth"), std::string::npos);
    EXPECT_EQ(vert.find("wg_fresnel"), std::string::npos) << "the vertex stage calls no fresnel";
  }
  auto functions = lake.result->manifest.at("functions");
  EXPECT_NE(std::find(functions.begin(), functions.end(), "wg_fresnel_schlick"), functions.end());
  EXPECT_EQ(std::find(functions.begin(), functions.end(), "wg_fresnel_exact"), functions.end());

  Compiled shelf = compileExample("shelf");
  ASSERT_TRUE(shelf.result) << shelf.diagnostics;
  std::string frag = shelf.text(".glsl330.frag");
  EXPECT_NE(frag.find("wg_fresnel_exact("), std::string::npos);
  EXPECT_EQ(frag.find("wg_fresnel_schlick"), std::string::npos);
  EXPECT_NE(frag.find("wg_depth_tint_smooth("), std::string::npos);
  EXPECT_EQ(frag.find("wg_depth_tint_linear"), std::string::npos);
}

TEST(Emit, EveryLibraryFunctionDefinedIsCalled) {
  // A definition nobody calls is dead code: each `float wg_x(` defined must be called
  // somewhere else in the same shader.
  for (const char* name : {"lake", "shelf"}) {
    Compiled c = compileExample(name);
    ASSERT_TRUE(c.result) << c.diagnostics;
    for (const auto& f : c.result->files) {
      if (f.name.find(".spv") != std::string::npos || f.name.find(".manifest") != std::string::npos) continue;
      std::regex def(R"((?:^|\n)(?:float|vec2|vec3|vec4|bool|int)\s+(wg_\w+)\s*\()");
      for (auto it = std::sregex_iterator(f.contents.begin(), f.contents.end(), def); it != std::sregex_iterator(); ++it) {
        std::string fn = (*it)[1];
        size_t defAt = static_cast<size_t>(it->position(1));
        size_t calls = 0;
        for (size_t at = f.contents.find(fn + "("); at != std::string::npos; at = f.contents.find(fn + "(", at + 1))
          if (at != defAt) ++calls;
        EXPECT_GT(calls, 0u) << f.name << " defines " << fn << " but never calls it";
      }
    }
  }
}

TEST(Emit, GraphIdsAreSanitisedInGeneratedNames) {
  Compiled c = compileText(graphJson(
      R"({"id": "weird__Name", "type": "fresnel", "options": {"model": "schlick"}},
         {"id": "gl_Position", "type": "mul", "inputs": {"a": "weird__Name.reflectance", "b": "$tint__amount"}},
         {"id": "a_very_long_node_identifier_that_goes_on_and_on", "type": "uv"},
         {"id": "l", "type": "length", "inputs": {"x": "a_very_long_node_identifier_that_goes_on_and_on.out"}},
         {"id": "sum", "type": "add", "inputs": {"a": "gl_Position.out", "b": "l.out"}})",
      R"("fragment": {"alpha": "sum.out"})", R"("tint__amount": {"type": "float", "default": 0.5})"));
  ASSERT_TRUE(c.result) << c.diagnostics;
  std::string glsl = c.allGlsl();
  EXPECT_EQ(glsl.find("__"), std::string::npos) << "GLSL reserves identifiers containing '__'";
  EXPECT_NE(glsl.find("weird_Name"), std::string::npos);
  EXPECT_NE(glsl.find("p_tint_amount"), std::string::npos);
  EXPECT_EQ(glsl.find("a_very_long_node_identifier_that_goes_on_and_on"), std::string::npos);
  // The id 'gl_Position' only ever appears inside a generated name (n1_gl_Position); the
  // builtin itself is only written by the vertex stage ("gl_Position = ...").
  size_t realWrites = 0;
  for (size_t at = glsl.find("gl_Position"); at != std::string::npos; at = glsl.find("gl_Position", at + 1)) {
    bool insideName = at > 0 && (std::isalnum(static_cast<unsigned char>(glsl[at - 1])) || glsl[at - 1] == '_');
    bool builtinWrite = glsl.compare(at, 14, "gl_Position = ") == 0 && !insideName;
    EXPECT_TRUE(insideName || builtinWrite) << glsl.substr(at > 20 ? at - 20 : 0, 60);
    realWrites += builtinWrite;
  }
  EXPECT_EQ(realWrites, 3u) << "one gl_Position write per vertex shader (3 targets)";
}

TEST(Emit, GraphStringsNeverReachTheShader) {
  // Descriptions and parameter descriptions are data for the manifest and editor only.
  Compiled c = compileText(
      "{\"version\": 1, \"name\": \"t\", \"description\": \"*/ #error injected\\n#define x\","
      "\"parameters\": {\"a\": {\"type\": \"float\", \"default\": 1, \"description\": \"*/ void main() {} /*\"}},"
      "\"nodes\": [{\"id\": \"u\", \"type\": \"uv\"}, {\"id\": \"l\", \"type\": \"length\", \"inputs\": {\"x\": \"u.out\"}},"
      "{\"id\": \"m\", \"type\": \"mul\", \"inputs\": {\"a\": \"l.out\", \"b\": \"$a\"}}],"
      "\"outputs\": {\"fragment\": {\"alpha\": \"m.out\"}}}");
  ASSERT_TRUE(c.result) << c.diagnostics;
  std::string glsl = c.allGlsl();
  EXPECT_EQ(glsl.find("injected"), std::string::npos);
  EXPECT_EQ(glsl.find("void main() {} /*"), std::string::npos);
  EXPECT_EQ(glsl.find("#define"), std::string::npos);
}

TEST(Emit, SourceFileNameCannotBreakOutOfTheHeaderComment) {
  // The header comment names the graph file; a newline in that name must not start a
  // line of GLSL (this name would otherwise inject a valid preprocessor line).
  Compiled c = compileText(graphJson(R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}})",
                                     R"("fragment": {"alpha": "l.out"})"),
                           "odd\n#define WG_INJECTED 1\n#pragma .json");
  ASSERT_TRUE(c.result) << c.diagnostics;
  for (const auto& line : test::splitLines(c.allGlsl()))
    EXPECT_NE(line.rfind("#define", 0), 0u) << line;
}

TEST(Emit, UnusedParametersProduceNoUniform) {
  Compiled shelf = compileExample("shelf");
  ASSERT_TRUE(shelf.result) << shelf.diagnostics;
  std::string glsl = shelf.allGlsl();
  EXPECT_EQ(glsl.find("p_ior"), std::string::npos) << "'ior' is declared but never read";
  EXPECT_EQ(glsl.find("p_slope"), std::string::npos) << "'slope' is static: compiled in";
  EXPECT_NE(glsl.find("p_sky"), std::string::npos);
  for (const auto& u : shelf.result->manifest.at("uniforms")) {
    if (!u.contains("parameter")) continue;
    EXPECT_NE(u["parameter"], "ior");
    EXPECT_NE(u["parameter"], "slope");
  }

  Compiled c = compileText(graphJson(R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}})",
                                     R"("fragment": {"alpha": "l.out"})",
                                     R"("never_read": {"type": "vec3", "default": [1, 2, 3]})"));
  ASSERT_TRUE(c.result) << c.diagnostics;
  EXPECT_EQ(c.allGlsl().find("never_read"), std::string::npos);
  EXPECT_EQ(c.allGlsl().find("uniform float p_"), std::string::npos);
}

TEST(Emit, UsedParametersAreUniformsInTheStageThatReadsThem) {
  Compiled lake = compileExample("lake");
  ASSERT_TRUE(lake.result) << lake.diagnostics;
  std::string frag = lake.text(".glsl330.frag");
  std::string vert = lake.text(".glsl330.vert");
  const std::pair<const char*, const char*> params[] = {
      {"p_shallow", "vec3"}, {"p_deep", "vec3"}, {"p_sky", "vec3"}, {"p_max_depth", "float"}, {"p_centre_depth", "float"}};
  for (const auto& [name, type] : params) {
    EXPECT_NE(frag.find(std::string("uniform ") + type + " " + name + ";"), std::string::npos) << name;
    EXPECT_EQ(vert.find(name), std::string::npos) << name << " is only read in the fragment stage";
  }
}

TEST(Emit, UnusedBuiltinsDeclareNothing) {
  // A graph that reads no uv declares no uv attribute and no uv varying.
  Compiled c = compileText(graphJson(R"({"id": "t", "type": "time"}, {"id": "s", "type": "sin", "inputs": {"x": "t.out"}})",
                                     R"("fragment": {"alpha": "s.out"})"));
  ASSERT_TRUE(c.result) << c.diagnostics;
  std::string glsl = c.allGlsl();
  EXPECT_EQ(glsl.find("a_uv"), std::string::npos);
  EXPECT_EQ(glsl.find("v_uv"), std::string::npos);
  EXPECT_EQ(glsl.find("a_normal"), std::string::npos);
  EXPECT_EQ(glsl.find("wg_fresnel"), std::string::npos);
}

}  // namespace
}  // namespace wg
