// The WGSL module around the plan's translated statements (codegen/emit_wgsl.h) and the manifest's
// "webgpu" section (codegen/manifest_webgpu.h): bindings, the uniform buffer's WGSL layout,
// entry points, clip-space conversion, tessellation left out, and the section read back.
#include <gtest/gtest.h>

#include <functional>

#include "codegen/compile.h"
#include "codegen/emit_wgsl.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

std::optional<CompileResult> compiledWithWgsl(const std::string& graphRel, Diagnostics& diags) {
  auto graph = loadGraphFile(test::sourcePath(graphRel), diags);
  if (!graph) return std::nullopt;
  CompileOptions o;
  o.targets = {Target::Glsl330};
  o.validate = false;
  o.wgsl = true;
  return compileGraph(*graph, defaultRegistry(), o, diags);
}

std::string wgslDiagnosticsText(const Diagnostics& diags) {
  std::string s;
  for (const auto& d : diags.all()) s += formatText(d) + "\n";
  return s;
}

const std::string& fileNamed(const CompileResult& r, const std::string& name) {
  for (const auto& f : r.files)
    if (f.name == name) return f.contents;
  static const std::string none;
  ADD_FAILURE() << "no file " << name;
  return none;
}

TEST(WgslEmit, UniformLayoutFollowsWgslsUniformAddressSpaceRules) {
  // A scalar after a vec3 fills its last 4 bytes; a vec2 aligns to 8; vec3, vec4 and matrices to 16.
  EXPECT_EQ(wgslUniformMember(12, Type::Float).offset, 12u);
  EXPECT_EQ(wgslUniformMember(4, Type::Vec2).offset, 8u);
  EXPECT_EQ(wgslUniformMember(4, Type::Vec3).offset, 16u);
  EXPECT_EQ(wgslUniformMember(4, Type::Vec3).size, 12u);
  EXPECT_EQ(wgslUniformMember(20, Type::Mat3).offset, 32u);
  EXPECT_EQ(wgslUniformMember(20, Type::Mat3).size, 48u);
  EXPECT_EQ(wgslUniformMember(4, Type::Mat4).size, 64u);
  EXPECT_EQ(wgslUniformMember(1, Type::Bool).offset, 4u);  // a u32 in the buffer
  EXPECT_EQ(wgslUniformBufferSize(196), 208u);
}

TEST(WgslEmit, LakeModuleHasBothEntryPointsItsBufferAndTheClipConversion) {
  Diagnostics diags;
  auto r = compiledWithWgsl("graphs/lake.json", diags);
  ASSERT_TRUE(r) << wgslDiagnosticsText(diags);
  const std::string& w = fileNamed(*r, "lake.wgsl");
  EXPECT_NE(w.find("@vertex\nfn vs_main("), std::string::npos);
  EXPECT_NE(w.find("@fragment\nfn fs_main(@builtin(position) wg_frag_coord: vec4<f32>"), std::string::npos);
  EXPECT_NE(w.find("@group(0) @binding(0) var<uniform> wg_u: WgUniforms;"), std::string::npos);
  EXPECT_NE(w.find("p_max_depth: f32,  // offset 188"), std::string::npos) << w;  // packed after p_sky (vec3 at 176)
  EXPECT_NE(w.find("wg_out.wg_position = vec4<f32>(wg_out.wg_position.x, -wg_out.wg_position.y, 0.5 * "
                   "(wg_out.wg_position.z + wg_out.wg_position.w), wg_out.wg_position.w);"),
            std::string::npos);
  // The manifest's section says the same offsets and the entry points.
  auto j = r->manifest.toJson();
  ASSERT_TRUE(j.contains("webgpu"));
  EXPECT_EQ(j["targets"]["wgsl"]["entry_points"]["vert"], "vs_main");
  EXPECT_EQ(j["targets"]["wgsl"]["entry_points"]["frag"], "fs_main");
  bool found = false;
  for (const auto& m : j["webgpu"]["uniform_buffer"]["members"])
    if (m["name"] == "p_max_depth") {
      found = true;
      EXPECT_EQ(m["offset"], 188);
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(j["webgpu"]["uniform_buffer"]["size"], 208);
}

TEST(WgslEmit, TexturesAreTextureAndSamplerBindingsInTheManifestsOrder) {
  Diagnostics diags;
  auto r = compiledWithWgsl("graphs/deferred_underwater.json", diags);
  ASSERT_TRUE(r) << wgslDiagnosticsText(diags);
  const std::string& w = fileNamed(*r, "deferred_underwater.wgsl");
  auto j = r->manifest.toJson();
  const auto& bindings = j["webgpu"]["bindings"];
  ASSERT_EQ(bindings.size(), 1 + 2 * j["textures"].size());
  for (size_t k = 0; k < j["textures"].size(); ++k) {
    const std::string name = j["textures"][k]["name"];
    const auto& tex = bindings[1 + 2 * k];
    const auto& smp = bindings[2 + 2 * k];
    EXPECT_EQ(tex["name"], name);
    EXPECT_EQ(tex["binding"], wgslTextureBinding(k));
    EXPECT_EQ(smp["kind"], "sampler");
    EXPECT_EQ(smp["binding"], wgslTextureBinding(k) + 1);
    std::string decl = "@group(0) @binding(" + std::to_string(wgslTextureBinding(k)) + ") var " + name + ": texture_";
    EXPECT_NE(w.find(decl), std::string::npos) << decl;
  }
}

TEST(WgslEmit, TessellatedGraphIsDrawnAsItsMeshInWgslAndTheManifestReadsBack) {
  Diagnostics diags;
  auto r = compiledWithWgsl("graphs/stylized.json", diags);
  ASSERT_TRUE(r) << wgslDiagnosticsText(diags);
  ASSERT_TRUE(r->manifest.tessellation.has_value());  // glsl330 tessellates ...
  for (const auto& t : r->manifest.tessellation->targets) EXPECT_NE(t, "wgsl");  // ... WGSL draws the mesh as it is
  const std::string& w = fileNamed(*r, "stylized.wgsl");
  EXPECT_NE(w.find("fn vs_main("), std::string::npos);
  // The manifest with its "webgpu" section reads back; an edited section does not.
  auto j = r->manifest.toJson();
  EXPECT_NO_THROW(Manifest::fromJson(j));
  j["webgpu"]["uniform_buffer"]["members"][0]["offset"] = 4;
  EXPECT_THROW(Manifest::fromJson(j), ManifestError);
}

TEST(WgslEmit, ModuleLinesMapBackToTheNodesThatWroteThem) {
  Diagnostics diags;
  auto r = compiledWithWgsl("graphs/lake.json", diags);
  ASSERT_TRUE(r) << wgslDiagnosticsText(diags);
  const std::string& w = fileNamed(*r, "lake.wgsl");
  std::vector<std::string> lines = test::splitLines(w);
  ASSERT_EQ(lines.size(), r->wgslLineOp.size());
  bool sawFresnel = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].find("var n8_fresnel_t1") == std::string::npos) continue;
    int op = r->wgslLineOp[i];
    ASSERT_GE(op, 0);
    EXPECT_EQ(r->program.ops[static_cast<size_t>(op)].nodeId, "fresnel");
    sawFresnel = true;
  }
  EXPECT_TRUE(sawFresnel);
}

// A planned expression outside the translated subset is refused (WG045) at the op of its
// own statement, not guessed at: a declaration whose value takes % of floats, written for
// an op whose lines are elsewhere and placed between the lines of two other ops (so
// neither the statement before it nor the one after gives its op), then a declaration of
// another type than its value's.
TEST(WgslEmit, AStatementWithNoWgslFormIsRefusedAtItsOp) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/lake.json"), diags);
  ASSERT_TRUE(graph);
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  ASSERT_TRUE(program);
  const ShaderPlan plan = planShaders(*program, "lake.json", false);
  ASSERT_FALSE(plan.stages.empty());
  const PlannedLines& body = plan.stages.back().body;
  // Where the lines of one op give way to another's, and a third op.
  size_t at = 1;
  while (at < body.statements.size() &&
         (body.statements[at - 1].op < 0 || body.statements[at].op < 0 || body.statements[at - 1].op == body.statements[at].op))
    ++at;
  ASSERT_LT(at, body.statements.size());
  int op = -1;
  for (const PlannedStatement& s : body.statements)
    if (s.op >= 0 && s.op != body.statements[at - 1].op && s.op != body.statements[at].op) op = s.op;
  ASSERT_GE(op, 0);
  auto refused = [&](const std::function<void(PlannedLines&)>& bad, const char* why) {
    ShaderPlan edited = plan;
    PlannedLines lines;
    for (size_t k = 0; k < body.statements.size(); ++k) {
      if (k == at) bad(lines);
      const PlannedStatement& s = body.statements[k];
      if (s.kind == PlannedStatement::Kind::Declare)
        lines.declare(s.op, s.cost, s.type, body.name(s), body.expression(s));
      else
        lines.assign(s.op, s.cost, body.name(s), body.expression(s));
    }
    edited.stages.back().body = std::move(lines);
    try {
      emitWgsl(edited);
      ADD_FAILURE() << "emitWgsl accepted " << edited.stages.back().body.text;
    } catch (const WgslRefused& r) {
      EXPECT_EQ(r.op, op) << r.message;
      EXPECT_NE(r.message.find(why), std::string::npos) << r.message;
    }
  };
  EXPECT_NO_THROW(emitWgsl(plan));
  refused([&](PlannedLines& l) { l.declare(op, 0, Type::Float, "n99_bad", "7.0 % 2.0"); }, "% on floats");
  refused([&](PlannedLines& l) { l.declare(op, 0, Type::Vec3, "n99_bad", "vec2(1.0)"); }, "a value of another type");
}

TEST(WgslEmit, SameGraphSameBytes) {
  Diagnostics d1, d2;
  auto a = compiledWithWgsl("graphs/ocean.json", d1);
  auto b = compiledWithWgsl("graphs/ocean.json", d2);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(fileNamed(*a, "ocean.wgsl"), fileNamed(*b, "ocean.wgsl"));
}

}  // namespace
}  // namespace wg
