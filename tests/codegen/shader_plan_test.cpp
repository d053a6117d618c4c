// The shader plan (codegen/shader_plan.h): each kind of plan (probe, deferred,
// tessellated) holds what its emitters need, and one plan wrapped for every target keeps
// the same stage bodies — only the declarations around them depend on the dialect.
#include <gtest/gtest.h>

#include <algorithm>

#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "codegen/probe_program.h"
#include "codegen/shader_plan.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

Program exampleProgram(const std::string& name) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourceDir() + "/graphs/" + name, diags);
  EXPECT_TRUE(graph) << name;
  if (!graph) return {};
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  EXPECT_TRUE(program) << name;
  return program ? std::move(*program) : Program{};
}

bool hasUniform(const ShaderPlan& plan, BuiltinUniform u) {
  return std::any_of(plan.uniforms.begin(), plan.uniforms.end(),
                     [&](const UniformInfo& info) { return info.parameter < 0 && info.builtin == u; });
}

// The lines main() holds in an emitted shader: from "void main() {" to the closing "}".
std::string mainOf(const std::string& text) {
  size_t at = text.find("\nvoid main() {\n");
  return at == std::string::npos ? "" : text.substr(at);
}

TEST(ShaderPlan, ProbePlanIsOneFragmentStageReadingBuiltinsAsUniforms) {
  Diagnostics diags;
  auto graph = parseGraph(test::graphJson(R"({"id": "f", "type": "fresnel"}, {"id": "u", "type": "uv"},
      {"id": "w", "type": "world_position"}, {"id": "d", "type": "dot", "inputs": {"a": "u.out", "b": "u.out"}},
      {"id": "l", "type": "length", "inputs": {"x": "w.out"}}, {"id": "m", "type": "mul", "inputs": {"a": "d.out", "b": "l.out"}},
      {"id": "c", "type": "mul", "inputs": {"a": "m.out", "b": "f.reflectance"}})",
                                          R"("fragment": {"alpha": "c.out"})"),
                          "t.json", diags);
  ASSERT_TRUE(graph);
  auto program = buildProbeProgram(*graph, defaultRegistry(), ProbeOutput{"c", ""}, diags);
  ASSERT_TRUE(program);
  ShaderPlan plan = planProbe(*program, "t.json");
  EXPECT_EQ(plan.kind, ShaderPlan::Kind::Probe);
  ASSERT_EQ(plan.stages.size(), 1u);
  EXPECT_EQ(plan.stages[0].stage, ShaderStage::Fragment);
  EXPECT_EQ(plan.stage(ShaderStage::Vertex), nullptr);
  EXPECT_TRUE(plan.attributes.empty());
  EXPECT_TRUE(plan.varyings.empty());
  EXPECT_TRUE(plan.stages[0].inputs.empty());
  // Every builtin the body reads is the uniform the case sets (uv by way of its gradient).
  const PlannedStage& fs = plan.stages[0];
  ASSERT_FALSE(fs.builtins.empty());
  for (Builtin b : fs.builtins) EXPECT_TRUE(hasUniform(plan, builtinRow(b).uniform)) << builtinRow(b).name;
  EXPECT_TRUE(hasUniform(plan, BuiltinUniform::ProbeUvGradient));
  EXPECT_EQ(fs.body.text.find("v_"), std::string::npos) << fs.body.text;
  ASSERT_EQ(fs.locals.statements.size(), 1u);
  EXPECT_EQ(fs.locals.statements[0].type, Type::Vec2);
  EXPECT_EQ(fs.locals.name(fs.locals.statements[0]), "b_uv");
  EXPECT_EQ(fs.locals.text.rfind("  vec2 b_uv = ", 0), 0u) << fs.locals.text;
}

TEST(ShaderPlan, DeferredPlanReadsTheGBufferNotVaryings) {
  Program program = exampleProgram("deferred_underwater.json");
  ShaderPlan plan = planShaders(program, "deferred_underwater.json", false);
  EXPECT_EQ(plan.kind, ShaderPlan::Kind::Deferred);
  std::vector<SceneSampler> scene;  // this graph's fragment reads no normal or uv: one G-buffer texture
  for (const auto& t : plan.textures)
    if (t.scene) scene.push_back(*t.scene);
  EXPECT_NE(std::find(scene.begin(), scene.end(), SceneSampler::WaterSurface), scene.end());
  const PlannedStage* fs = plan.stage(ShaderStage::Fragment);
  const PlannedStage* vs = plan.stage(ShaderStage::Vertex);
  ASSERT_TRUE(fs && vs);
  EXPECT_TRUE(fs->inputs.empty()) << "the full-screen pass reads no varyings";
  // The vertex stage still writes the surface for the runtime's G-buffer pass.
  EXPECT_FALSE(vs->outputs.empty());
  EXPECT_FALSE(plan.varyings.empty());
  const std::string fragText = emitGlsl(plan, Target::Glsl330).shaders.back().text;
  for (const auto& v : plan.varyings)
    EXPECT_EQ(fragText.find("in " + std::string(typeName(v.type)) + " " + v.name + ";"), std::string::npos) << v.name;
  // The G-buffer reads sit among the fragment's locals.
  bool readsSurface = std::any_of(fs->locals.statements.begin(), fs->locals.statements.end(), [&](const PlannedStatement& l) {
    return l.type == Type::Vec4 && fs->locals.expression(l).starts_with("texture(u_water_surface,");
  });
  EXPECT_TRUE(readsSurface);
  // The scene passes the manifest lists come with the plan.
  EXPECT_NE(std::find(plan.resources.begin(), plan.resources.end(), SceneResource::Underwater), plan.resources.end());
  EXPECT_EQ(plan.passes.back(), RenderPass::WaterSurface);
}

TEST(ShaderPlan, TessellatedPlanHasFourStagesWhereTheTargetTessellates) {
  Program program = exampleProgram("stylized.json");
  ShaderPlan flat = planShaders(program, "stylized.json", false);
  ShaderPlan tess = planShaders(program, "stylized.json", true);
  EXPECT_FALSE(flat.tessellation);
  ASSERT_TRUE(tess.tessellation);
  const std::vector<ShaderStage> pipeline = {ShaderStage::Vertex, ShaderStage::TessControl, ShaderStage::TessEvaluation,
                                             ShaderStage::Fragment};
  for (Target t : {Target::Glsl330, Target::Vk450}) {
    EmitResult er = emitGlsl(tess, t);
    ASSERT_EQ(er.shaders.size(), 4u) << targetName(t);
    for (size_t s = 0; s < 4; ++s) EXPECT_EQ(er.shaders[s].stage, pipeline[s]) << targetName(t);
    EXPECT_TRUE(er.tessellation);
  }
  // Compiling for every target: es300 takes the plan that draws the mesh as it is.
  TargetPlans plans = planTargets(program, allTargets(), "stylized.json");
  EXPECT_EQ(plans.plans.size(), 2u);
  for (size_t i = 0; i < allTargets().size(); ++i) {
    bool es = allTargets()[i] == Target::Es300;
    EXPECT_EQ(plans.of(i).tessellation.has_value(), !es) << targetName(allTargets()[i]);
    EXPECT_EQ(emitGlsl(plans.of(i), allTargets()[i]).shaders.size(), es ? 2u : 4u) << targetName(allTargets()[i]);
  }
  // Without tessellation allowed, one plan serves all.
  EXPECT_EQ(planTargets(program, allTargets(), "stylized.json", false).plans.size(), 1u);
}

// Every statement of main() is held as a value whose parts are where it was written: the
// line is "  " + (a declaration's type + " ") + name + " = " + expression + ";\n", the lines
// follow each other to the end of the text, the ops' lines declare a local, the stage's
// outputs are assigned, and the colour statement is the fragment body's last, o_color's.
TEST(ShaderPlan, EachStatementHoldsItsKindTypeNameAndExpression) {
  for (const char* name : {"lake.json", "deferred_underwater.json", "ocean.json"}) {
    Program program = exampleProgram(name);
    const ShaderPlan plan = planShaders(program, name, false);
    size_t declared = 0, assigned = 0;
    for (const PlannedStage& stage : plan.stages)
      for (const PlannedLines* lines : {&stage.locals, &stage.body}) {
        size_t at = 0;
        for (const PlannedStatement& s : lines->statements) {
          const bool declares = s.kind == PlannedStatement::Kind::Declare;
          ASSERT_TRUE(declares || s.kind == PlannedStatement::Kind::Assign) << name;
          EXPECT_EQ(declares, s.type != Type::Invalid) << name;
          const std::string line = "  " + (declares ? std::string(typeName(s.type)) + " " : std::string()) +
                                   std::string(lines->name(s)) + " = " + std::string(lines->expression(s)) + ";\n";
          EXPECT_EQ(lines->text.substr(at, s.end - at), line) << name;
          EXPECT_FALSE(lines->expression(s).empty()) << name << ": " << line;
          // Ops declare their locals; what no op wrote is a builtin local or a stage output.
          if (s.op >= 0) EXPECT_TRUE(declares) << name << ": " << line;
          if (lines == &stage.locals) EXPECT_TRUE(declares && s.op < 0) << name << ": " << line;
          at = s.end;
          (declares ? declared : assigned)++;
        }
        EXPECT_EQ(at, lines->text.size()) << name;
      }
    EXPECT_GT(declared, 10u) << name;
    EXPECT_GE(assigned, 2u) << name;  // gl_Position and o_color at least
    const PlannedStage* fs = plan.stage(ShaderStage::Fragment);
    ASSERT_TRUE(fs);
    ASSERT_EQ(fs->colorStatement + 1, fs->body.statements.size()) << name;
    const PlannedStatement& colour = fs->body.statements.back();
    EXPECT_EQ(colour.kind, PlannedStatement::Kind::Assign);
    EXPECT_EQ(fs->body.name(colour), "o_color");
    EXPECT_TRUE(fs->body.expression(colour).starts_with("vec4(")) << fs->body.expression(colour);
  }
}

TEST(ShaderPlan, OnePlanGivesTheSameBodiesInEveryTarget) {
  for (const auto& path : test::exampleGraphs()) {
    Diagnostics diags;
    auto graph = loadGraphFile(path, diags);
    ASSERT_TRUE(graph) << path;
    auto program = buildProgram(*graph, defaultRegistry(), diags);
    ASSERT_TRUE(program) << path;
    ShaderPlan plan = planShaders(*program, "g.json", false);
    std::vector<EmitResult> emitted;
    for (Target t : allTargets()) emitted.push_back(emitGlsl(plan, t));
    for (size_t s = 0; s < plan.stages.size(); ++s) {
      const PlannedStage& stage = plan.stages[s];
      for (size_t t = 0; t < emitted.size(); ++t) {
        const EmittedShader& sh = emitted[t].shaders.at(s);
        const std::string what = path + " " + std::string(targetName(allTargets()[t])) + " stage " + std::to_string(s);
        EXPECT_EQ(sh.stage, stage.stage) << what;
        EXPECT_EQ(mainOf(sh.text), mainOf(emitted[0].shaders[s].text)) << what;
        // The body is the plan's, line for line, with its ops: right before the closing "}".
        std::vector<int> lineOp;
        for (const PlannedStatement& statement : stage.body.statements) lineOp.push_back(statement.op);
        ASSERT_GE(sh.lineOp.size(), lineOp.size() + 1) << what;
        EXPECT_TRUE(std::equal(lineOp.begin(), lineOp.end(), sh.lineOp.end() - 1 - lineOp.size())) << what;
        EXPECT_NE(sh.text.find(stage.body.text + "}\n"), std::string::npos) << what;
      }
    }
  }
}

}  // namespace
}  // namespace wg
