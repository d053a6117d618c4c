// What check reads back for the reference (accuracy/readback.h) and the fragment stage it
// evaluates (accuracy/fragment_program.h), planned from compiled example graphs: no GPU.
#include <algorithm>

#include <gtest/gtest.h>

#include "accuracy/fragment_program.h"
#include "accuracy/readback.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/preview.h"
#include "compile_text.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

CompileResult compiled(const std::string& name) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/" + name), diags);
  EXPECT_TRUE(graph) << name;
  CompileOptions o;
  o.targets = {Target::Glsl330};
  auto result = compileGraph(*graph, defaultRegistry(), o, diags);
  EXPECT_TRUE(result) << name;
  return *result;
}

// A channel of the plan: what it reads (kind, index) and which component.
bool reads(const TapChannel& c, TapChannel::Kind kind, int component, size_t index = 0) {
  return c.kind == kind && c.component == component && (kind == TapChannel::Kind::FragDepth || c.index == index);
}

size_t textureNamed(const ShaderPlan& plan, const std::string& name) {
  for (size_t i = 0; i < plan.textures.size(); ++i)
    if (plan.textures[i].name == name) return i;
  ADD_FAILURE() << "no texture " << name;
  return 0;
}

std::string fragmentText(const std::vector<rt::ShaderSource>& sources) {
  for (const auto& s : sources)
    if (s.stage == GL_FRAGMENT_SHADER) return s.text;
  return "";
}

// classic_webgl: the varyings, one look-up each of depth, refraction and reflection, and
// the two water_normal look-ups main() makes; its dudv texture is sampled inside a library
// function, so the reference samples that one itself.
TEST(ReadbackPlan, ListsTheVaryingsAndLookUpsOfTheFragmentShader) {
  CompileResult r = compiled("classic_webgl.json");
  ShaderPlan shaders = waterPlan(r, Target::Glsl330);
  ReadbackPlan plan;
  ASSERT_EQ(planReadback(r, shaders, &plan), "");
  EXPECT_GE(plan.mask, 0);
  EXPECT_GE(plan.fragDepth, 0);
  EXPECT_GE(plan.worldPosition, 0);
  EXPECT_GE(plan.normal, 0);
  EXPECT_GE(plan.uv, 0);
  EXPECT_EQ(plan.varyings.size(), r.program.varyings.size());
  ASSERT_EQ(plan.lookups.size(), 3u);
  for (SceneSampler s : {SceneSampler::SceneDepth, SceneSampler::Refraction, SceneSampler::Reflection})
    EXPECT_EQ(std::count_if(plan.lookups.begin(), plan.lookups.end(), [&](const auto& l) { return l.sampler == s; }), 1);
  ASSERT_EQ(plan.textureFetches.size(), 2u);
  for (const auto& f : plan.textureFetches) EXPECT_EQ(f.source, "builtin:water_normal");
  EXPECT_EQ(plan.frames(), (static_cast<int>(plan.channels.size()) + 2) / 3);

  // A tap frame writes its three channels as the colour instead of the graph's.
  auto sources = rt::waterShaderSources(r, Target::Glsl330);
  auto tapped = tapShaders(sources, shaders, Target::Glsl330, plan, 0);
  std::string text = fragmentText(tapped);
  EXPECT_NE(text.find("o_color = vec4(float(-3.0), float(gl_FragCoord.z), float((v_world_position).x), 1.0);"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("o_color = vec4(n14_color, 1.0);"), std::string::npos);
  // Each look-up channel reads a look-up main() makes of its sampler.
  const PlannedStage& fs = *shaders.stage(ShaderStage::Fragment);
  for (const auto& l : plan.lookups) {
    const TapChannel& c = plan.channels[static_cast<size_t>(l.channel)];
    ASSERT_EQ(c.kind, TapChannel::Kind::Fetch);
    EXPECT_EQ(fs.fetches.at(c.index).sampler, sceneSamplerRow(l.sampler).glslName);
  }
}

// Deferred water: the surface builtins come from the G-buffer locals of main() (no
// look-up of the G-buffer is read back), and the scene depth and colour, which its SSR
// march and underwater node sample at positions of their own, are read back whole.
TEST(ReadbackPlan, PlansDeferredWaterFromTheGBufferAndWholeSceneTextures) {
  CompileResult r = compiled("deferred_underwater.json");
  ShaderPlan shaders = waterPlan(r, Target::Glsl330);
  ReadbackPlan plan;
  std::string why = planReadback(r, shaders, &plan);
  ASSERT_EQ(why, "");
  ASSERT_GE(plan.worldPosition, 0);
  EXPECT_TRUE(reads(plan.channels[static_cast<size_t>(plan.worldPosition)], TapChannel::Kind::Varying, 0));
  EXPECT_EQ(shaders.varyings[plan.channels[static_cast<size_t>(plan.worldPosition)].index].name, "v_world_position");
  ASSERT_GE(plan.fragDepth, 0);
  EXPECT_TRUE(reads(plan.channels[static_cast<size_t>(plan.fragDepth)], TapChannel::Kind::FragDepth, -1));
  EXPECT_EQ(plan.normal, -1);  // not declared by this shader: nothing reads the G-buffer normal
  ASSERT_EQ(plan.images.size(), 2u);
  EXPECT_EQ(plan.images[0].sampler, SceneSampler::SceneDepth);
  EXPECT_TRUE(reads(plan.channels[static_cast<size_t>(plan.images[0].channel)], TapChannel::Kind::TexelAtPixel, 0,
                    textureNamed(shaders, "u_scene_depth")));
  EXPECT_EQ(plan.images[1].sampler, SceneSampler::SceneColor);
  EXPECT_EQ(plan.images[1].size, 3);
  for (const auto& lookup : plan.lookups) EXPECT_EQ(lookup.sampler, SceneSampler::Environment);
  EXPECT_EQ(plan.lookups.size(), 1u);
}

// Deferred water that reads the surface only inside the underwater node (no surface
// builtin of its own, so no G-buffer locals): the surface texel is fetched at the pixel
// for the reference's world position and depth.
TEST(ReadbackPlan, FetchesTheSurfaceTexelWhereNoLocalHoldsIt) {
  CompileResult r = test::compileText(R"({"version": 1, "name": "t", "nodes": [
      {"id": "water", "type": "underwater", "inputs": {"normal": [0, 1, 0]}}],
    "outputs": {"fragment": {"color": "water.color"}}})");
  std::string text = fragmentText(rt::waterShaderSources(r, Target::Glsl330));
  ASSERT_EQ(text.find("vec3 v_world_position = "), std::string::npos) << text;
  ShaderPlan shaders = waterPlan(r, Target::Glsl330);
  ReadbackPlan plan;
  ASSERT_EQ(planReadback(r, shaders, &plan), "");
  const size_t surface = textureNamed(shaders, "u_water_surface");
  ASSERT_GE(plan.worldPosition, 0);
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(reads(plan.channels[static_cast<size_t>(plan.worldPosition + k)], TapChannel::Kind::TexelAtPixel, k, surface));
  ASSERT_GE(plan.fragDepth, 0);
  EXPECT_TRUE(reads(plan.channels[static_cast<size_t>(plan.fragDepth)], TapChannel::Kind::TexelAtPixel, 3, surface));
}

// The reference takes the G-buffer as this pixel's builtins, so a look-up of it anywhere
// else is refused with that reason: the underwater node reading the surface at a fixed
// position instead of the pixel's.
TEST(ReadbackPlan, RefusesAGBufferLookUpAwayFromThePixel) {
  CompileResult r = test::compileText(R"({"version": 1, "name": "t", "nodes": [
      {"id": "water", "type": "underwater", "inputs": {"normal": [0, 1, 0], "screen_uv": [0.25, 0.5]}}],
    "outputs": {"fragment": {"color": "water.color"}}})");
  ReadbackPlan plan;
  std::string why = planReadback(r, waterPlan(r, Target::Glsl330), &plan);
  EXPECT_NE(why.find("u_water_surface) other than at the pixel's own position"), std::string::npos) << why;
}

// A read-back image's rows run top to bottom; the scene image the reference samples has
// GL's rows, bottom first.
TEST(ReadbackImage, SceneImagesHaveGlsRowOrder) {
  ReadbackImage taps;
  taps.width = 2, taps.height = 2, taps.channels = 2;
  // Channel 1 holds 10 * row-from-top + column.
  taps.values = {0, 0, 0, 1, 0, 10, 0, 11};
  SceneImage img = taps.sceneImage({SceneSampler::SceneDepth, 1, 1}, true);
  EXPECT_EQ(img.texel(0, 0, 0), 10.0f);  // bottom row = the image's last row
  EXPECT_EQ(img.texel(1, 0, 0), 11.0f);
  EXPECT_EQ(img.texel(0, 1, 0), 0.0f);
  EXPECT_EQ(img.texel(1, 1, 0), 1.0f);
  EXPECT_TRUE(img.nearest);
}

// Forward water that samples a scene texture inside a library function keeps the refusal:
// the water does not cover the screen, so the texture cannot be read back whole.
TEST(ReadbackPlan, RefusesALibraryLookUpOfForwardWater) {
  CompileResult r = compiled("deferred_underwater.json");
  ShaderPlan forward = waterPlan(r, Target::Glsl330);
  forward.kind = ShaderPlan::Kind::Surface;
  ReadbackPlan plan;
  std::string why = planReadback(r, forward, &plan);
  EXPECT_NE(why.find("u_scene_depth inside a library function"), std::string::npos) << why;
}

// ocean: the vertex stage's Gerstner ops are left out; what the fragment reads of them
// arrives through varyings turned into parameters.
TEST(FragmentProgram, KeepsOnlyFragmentOpsWithVaryingsAsParameters) {
  CompileResult r = compiled("ocean.json");
  FragmentProgram f = fragmentProgram(r.program);
  EXPECT_LT(f.program.ops.size(), r.program.ops.size());
  for (const auto& op : f.program.ops) EXPECT_TRUE(op.stage & kFragmentStage) << op.nodeId;
  EXPECT_EQ(f.varyingParameters.size(), r.program.varyings.size());
  EXPECT_EQ(f.program.parameters.size(), r.program.parameters.size() + r.program.varyings.size());
  ASSERT_EQ(f.program.outputs.size(), 1u);
  EXPECT_EQ(f.program.outputs[0].slot, OutputSlot::FragmentColor);
}

}  // namespace
}  // namespace wg::accuracy
