// The tap mode of emission (codegen/readback_taps.h) and what it is fed: the plan check
// re-makes (waterPlan) emits the compile's texts byte for byte, the look-ups the planner
// lists are exactly the texture() calls main() makes, and a tap frame differs from the
// water's fragment shader in the colour statement alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "codegen/compile.h"
#include "codegen/readback_taps.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

const std::vector<Target> kTapTargets = {Target::Glsl330, Target::Es300, Target::Vk450};

std::vector<std::string> exampleGraphs() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(test::sourceDir() + "/graphs"))
    if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

CompileResult compiledForTaps(const std::string& path) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  EXPECT_TRUE(graph) << path;
  CompileOptions o;
  o.targets = kTapTargets;
  o.validate = false;  // texts only
  auto result = compileGraph(*graph, defaultRegistry(), o, diags);
  EXPECT_TRUE(result) << path;
  return result ? std::move(*result) : CompileResult{};
}

// The compile's text of `target`'s shader for `stage` (".frag", ".vert", ...).
std::string compiledText(const CompileResult& r, Target target, ShaderStage stage) {
  const std::string suffix = "." + std::string(targetName(target)) + "." + std::string(stageExtension(stage));
  for (const auto& f : r.files)
    if (f.name.size() > suffix.size() && f.name.compare(f.name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return f.contents;
  return "";
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// main()'s text in an emitted shader.
std::string mainText(const std::string& text) {
  size_t at = text.find("\nvoid main() {\n");
  return at == std::string::npos ? "" : text.substr(at);
}

// How often `name` occurs in `text` as a whole identifier.
size_t mentions(const std::string& text, const std::string& name) {
  size_t n = 0;
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t k = text.find(name); k != std::string::npos; k = text.find(name, k + 1))
    n += (k == 0 || !word(text[k - 1])) && (k + name.size() == text.size() || !word(text[k + name.size()]));
  return n;
}

// check re-plans a target's shaders from the compiled program instead of keeping the plans:
// that plan must be the one the compile emitted, in every target.
TEST(ReadbackTaps, WaterPlanEmitsTheCompiledShadersByteForByte) {
  for (const auto& path : exampleGraphs()) {
    SCOPED_TRACE(path);
    CompileResult r = compiledForTaps(path);
    for (Target t : kTapTargets) {
      SCOPED_TRACE(std::string(targetName(t)));
      EmitResult e = emitGlsl(waterPlan(r, t), t);
      for (const auto& s : e.shaders) EXPECT_EQ(s.text, compiledText(r, t, s.stage));
    }
  }
}

// The planner's look-ups of the fragment stage, against the text (the test may read it):
// a sampler main() does not hand on is named in main() only by its listed look-ups, in
// their order; one it hands on is listed as such. A node writing a texture() call by hand
// instead of through EmitContext::sampleTexture or sampleScene fails here.
TEST(ReadbackTaps, ListedLookUpsAreTheTextureCallsMainMakes) {
  size_t fetches = 0, handedOn = 0;
  for (const auto& path : exampleGraphs()) {
    SCOPED_TRACE(path);
    CompileResult r = compiledForTaps(path);
    ShaderPlan plan = waterPlan(r, Target::Glsl330);
    const PlannedStage& fs = *plan.stage(ShaderStage::Fragment);
    const std::string main = mainText(compiledText(r, Target::Glsl330, ShaderStage::Fragment));
    ASSERT_FALSE(main.empty());
    for (size_t i : fs.textures) {
      const std::string& name = plan.textures[i].name;
      SCOPED_TRACE(name);
      size_t listed = 0, at = 0;
      for (const auto& f : fs.fetches) {
        if (f.sampler != name) continue;
        ++listed;
        at = main.find(f.call(), at);
        ASSERT_NE(at, std::string::npos) << f.call() << " is not in main(), after the look-ups before it";
        ++at;
        EXPECT_EQ(f.atScreenUv, f.coord == "b_screen_uv");
      }
      fetches += listed;
      // Every texture() call of the sampler in main() is a listed one, handed on or not.
      size_t calls = 0;
      for (size_t k = main.find("texture(" + name + ", "); k != std::string::npos; k = main.find("texture(" + name + ", ", k + 1))
        ++calls;
      EXPECT_EQ(calls, listed);
      if (fs.handedOn.count(name)) {
        ++handedOn;
        EXPECT_GT(mentions(main, name), listed);
      } else {
        EXPECT_EQ(mentions(main, name), listed);
      }
    }
  }
  EXPECT_GT(fetches, 10u);  // the examples make look-ups of both kinds
  EXPECT_GT(handedOn, 2u);
}

// A tap frame is the water's fragment shader with the colour statement alone replaced, in
// every target: the same interface, declarations and main() up to it.
TEST(ReadbackTaps, TapFrameReplacesOnlyTheColourStatement) {
  for (const char* graph : {"classic_webgl.json", "deferred_underwater.json"}) {
    SCOPED_TRACE(graph);
    CompileResult r = compiledForTaps(test::sourceDir() + "/graphs/" + graph);
    for (Target t : kTapTargets) {
      SCOPED_TRACE(std::string(targetName(t)));
      ShaderPlan plan = waterPlan(r, t);
      TapChannel mark, depth;
      mark.constant = -3.0;
      depth.kind = TapChannel::Kind::FragDepth;
      std::vector<std::string> tap = linesOf(emitTapFragment(plan, t, {mark, depth}).text);
      std::vector<std::string> water = linesOf(compiledText(r, t, ShaderStage::Fragment));
      ASSERT_EQ(tap.size(), water.size());
      std::vector<size_t> differ;
      for (size_t k = 0; k < tap.size(); ++k)
        if (tap[k] != water[k]) differ.push_back(k);
      ASSERT_EQ(differ.size(), 1u);
      EXPECT_EQ(water[differ[0]].rfind("  o_color = vec4(", 0), 0u) << water[differ[0]];
      const std::string fragDepth = plan.kind == ShaderPlan::Kind::Deferred ? "b_water_surface.w" : "gl_FragCoord.z";
      EXPECT_EQ(tap[differ[0]], "  o_color = vec4(float(-3.0), float(" + fragDepth + "), 0.0, 1.0);");
    }
  }
}

// Channels name components of what main() holds; a value it does not hold is refused, not
// emitted as text glslang would reject later.
TEST(ReadbackTaps, ChannelsReadComponentsAndRefuseWhatMainDoesNotHold) {
  CompileResult r = compiledForTaps(test::sourceDir() + "/graphs/deferred_underwater.json");
  ShaderPlan plan = waterPlan(r, Target::Glsl330);
  ASSERT_EQ(plan.kind, ShaderPlan::Kind::Deferred);
  const PlannedStage& fs = *plan.stage(ShaderStage::Fragment);
  ASSERT_FALSE(fs.fetches.empty());
  TapChannel fetch, texel;
  fetch.kind = TapChannel::Kind::Fetch;
  fetch.component = 2;
  texel.kind = TapChannel::Kind::TexelAtPixel;
  texel.index = fs.textures.front();
  texel.component = 0;
  std::string text = emitTapFragment(plan, Target::Glsl330, {fetch, texel}).text;
  EXPECT_NE(text.find("  o_color = vec4(float((" + fs.fetches[0].call() + ").z), float((texelFetch(" +
                      plan.textures[texel.index].name + ", ivec2(gl_FragCoord.xy), 0)).x), 0.0, 1.0);"),
            std::string::npos)
      << text;
  // Deferred water holds no node varying (they feed the G-buffer pass).
  for (size_t v = 0; v < plan.varyings.size(); ++v) {
    const std::string& carries = plan.varyings[v].carries;
    if (carries == "world_position" || carries == "normal" || carries == "uv") continue;
    EXPECT_FALSE(tapHoldsVarying(plan, v));
    TapChannel varying;
    varying.kind = TapChannel::Kind::Varying;
    varying.index = v;
    EXPECT_THROW(emitTapFragment(plan, Target::Glsl330, {varying}), std::logic_error);
  }
  EXPECT_THROW(emitTapFragment(plan, Target::Glsl330, {fetch, fetch, fetch, fetch}), std::logic_error);
}

}  // namespace
}  // namespace wg

namespace wg {
namespace {

// check --target wgsl's tap modules: the same plan's WGSL module (the compile's GRAPH.wgsl,
// byte for byte outside fs_main) with the colour written from the channels; a look-up's value
// is its x taken explicitly (WGSL's f32() takes no vector, where GLSL's float() takes the first
// component).
TEST(ReadbackTaps, WgslTapModulesDifferFromTheGraphsModuleInTheColourAlone) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourceDir() + "/graphs/pool.json", diags);
  ASSERT_TRUE(graph);
  CompileOptions o;
  o.targets = {Target::Es300};
  o.wgsl = true;
  o.validate = false;
  auto r = compileGraph(*graph, defaultRegistry(), o, diags);
  ASSERT_TRUE(r);
  std::string module;
  for (const auto& f : r->files)
    if (f.name == "pool.wgsl") module = f.contents;
  ASSERT_FALSE(module.empty());
  ShaderPlan plan = waterPlan(*r, Target::Es300);
  const PlannedStage& fs = *plan.stage(ShaderStage::Fragment);
  ASSERT_FALSE(fs.fetches.empty());
  TapChannel mark, depth, fetch;
  mark.constant = -3.0;
  depth.kind = TapChannel::Kind::FragDepth;
  fetch.kind = TapChannel::Kind::Fetch;  // the depth look-up: a vec4, its x wanted
  std::string tap = emitTapModuleWgsl(plan, {mark, depth, fetch});
  std::vector<std::string> tapLines, waterLines;
  for (auto* out : {&tapLines, &waterLines}) {
    std::istringstream in(out == &tapLines ? tap : module);
    for (std::string line; std::getline(in, line);) out->push_back(line);
  }
  ASSERT_EQ(tapLines.size(), waterLines.size());
  std::vector<size_t> differ;
  for (size_t k = 0; k < tapLines.size(); ++k)
    if (tapLines[k] != waterLines[k]) differ.push_back(k);
  ASSERT_EQ(differ.size(), 1u) << tap;
  EXPECT_EQ(waterLines[differ[0]].rfind("  o_color = vec4<f32>(", 0), 0u) << waterLines[differ[0]];
  const std::string line = tapLines[differ[0]];
  EXPECT_EQ(line.rfind("  o_color = vec4<f32>(-3.0, wg_frag_coord.z, textureSample(u_scene_depth, u_scene_depth_sampler, ", 0), 0u)
      << line;
  EXPECT_TRUE(line.ends_with(").x, 1.0);")) << line;
}

}  // namespace
}  // namespace wg
