// Derived uniforms at run time (issue #19): a graph compiled with
// CompileOptions::derivedUniforms renders what it renders without them, on glsl330, es300
// and Vulkan, with the per-draw values computed once per draw in double instead of per
// pixel in float; and a parameter set between two frames reaches the derived uniforms it
// feeds without a recompile (the editor's path: Renderer::setParameter).
#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "core/diagnostic_text.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/uniform_values.h"
#include "runtime/vk_preview.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace derived_render_test {

// Float images of the same draw in float and in double per-draw values differ by float
// rounding carried through the shading: far below one 8-bit step (1/255 = 3.9e-3).
constexpr double kTolerance = 1e-3;

// dir = normalize($wind) * sin(time * $k) per draw; the colour multiplies it per pixel.
const char* kGraph = R"({"version": 1, "name": "derived",
  "parameters": {"k": {"type": "float", "default": 0.5, "min": 0, "max": 4},
                 "wind": {"type": "vec3", "default": [1, 0.5, 2]}},
  "nodes": [{"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
            {"id": "t", "type": "time"},
            {"id": "kt", "type": "mul", "inputs": {"a": "t.out", "b": "$k"}},
            {"id": "s", "type": "sin", "inputs": {"x": "kt.out"}},
            {"id": "w", "type": "normalize", "inputs": {"x": "$wind"}},
            {"id": "dir", "type": "mul", "inputs": {"a": "w.out", "b": "s.out"}},
            {"id": "shade", "type": "mul", "inputs": {"a": "dir.out", "b": "l.out"}}],
  "outputs": {"fragment": {"color": "shade.out"}}})";

// "" for kGraph, else an example graph's name.
CompileResult compileFor(const std::string& example, bool derive, std::vector<Target> targets) {
  Diagnostics diags;
  auto graph = example.empty() ? parseGraph(kGraph, "derived.json", diags)
                               : loadGraphFile(test::sourcePath("graphs/" + example + ".json"), diags);
  std::optional<CompileResult> r;
  if (graph) {
    CompileOptions options;
    options.targets = std::move(targets);
    options.derivedUniforms = derive;
    r = compileGraph(*graph, defaultRegistry(), options, diags);
  }
  std::string messages;
  for (const auto& d : diags.all()) messages += formatText(d) + "\n";
  EXPECT_TRUE(r) << messages;
  return r ? std::move(*r) : CompileResult{};
}

size_t derivedCount(const CompileResult& r) {
  return static_cast<size_t>(std::count_if(r.manifest.uniforms.begin(), r.manifest.uniforms.end(), [](const ManifestUniform& u) {
    return !u.parameter && u.builtin == BuiltinUniform::Derived;
  }));
}

double maxDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.rgba32f.size(), b.rgba32f.size());
  double worst = 0;
  for (size_t i = 0; i < std::min(a.rgba32f.size(), b.rgba32f.size()); ++i)
    worst = std::max(worst, std::abs(static_cast<double>(a.rgba32f[i]) - b.rgba32f[i]));
  return worst;
}

RenderSettings floatSettings() {
  RenderSettings s = test::smallSettings();
  s.floatColor = true;
  return s;
}

class DerivedUniformRender : public ::testing::TestWithParam<std::tuple<std::string, Target>> {};

TEST_P(DerivedUniformRender, MatchesTheRenderWithoutThem) {
  const auto& [graph, target] = GetParam();
  const std::vector<Target> targets = {target};
  CompileResult off = compileFor(graph, false, targets);
  CompileResult on = compileFor(graph, true, targets);
  ASSERT_GE(derivedCount(on), 1u);
  ASSERT_EQ(derivedCount(off), 0u);
  RenderSettings s = floatSettings();
  Image a = target == Target::Vk450 ? renderVulkanPreview(off, s, 1, false, /*validation=*/true).image
                                    : renderPreview(off, target, s).image;
  Image b = target == Target::Vk450 ? renderVulkanPreview(on, s, 1, false, /*validation=*/true).image
                                    : renderPreview(on, target, s).image;
  ASSERT_FALSE(a.rgba32f.empty());
  EXPECT_EQ(countNonFinite(b), 0u);
  double d = maxDifference(a, b);
  std::cout << (graph.empty() ? "test graph" : graph) << " " << targetName(target) << ": " << derivedCount(on)
            << " derived uniform(s), largest difference " << d << "\n";
  EXPECT_LE(d, kTolerance);
}

INSTANTIATE_TEST_SUITE_P(Graphs, DerivedUniformRender,
                         ::testing::Combine(::testing::Values(std::string(), std::string("lagoon")),
                                            ::testing::Values(Target::Glsl330, Target::Es300, Target::Vk450)),
                         [](const auto& info) {
                           std::string g = std::get<0>(info.param);
                           return (g.empty() ? std::string("test_graph") : g) + "_" +
                                  std::string(targetName(std::get<1>(info.param)));
                         });

TEST(DerivedUniformParameters, ASetParameterReachesTheDerivedUniformWithoutARecompile) {
  CompileResult on = compileFor("", true, {Target::Glsl330});
  CompileResult off = compileFor("", false, {Target::Glsl330});
  ASSERT_EQ(derivedCount(on), 1u);
  auto context = EglContext::create(apiFor(Target::Glsl330));
  RenderSettings s = floatSettings();
  Renderer derived(on.manifest, waterShaderSources(on, Target::Glsl330), s, context->isEs(), textureOrigins(on));
  derived.renderFrame();
  Image before = derived.readRgba32f();
  // k and wind are read only by the derived uniform: no shader declares them, yet both
  // can be set, and the next frame computes the uniform from the new values.
  EXPECT_TRUE(derived.setParameter("k", {2.0f}));
  EXPECT_TRUE(derived.setParameter("wind", {0.0f, 3.0f, -4.0f}));
  derived.renderFrame();
  Image after = derived.readRgba32f();
  Renderer plain(off.manifest, waterShaderSources(off, Target::Glsl330), s, context->isEs(), textureOrigins(off));
  EXPECT_TRUE(plain.setParameter("k", {2.0f}));
  EXPECT_TRUE(plain.setParameter("wind", {0.0f, 3.0f, -4.0f}));
  plain.renderFrame();
  Image want = plain.readRgba32f();
  EXPECT_GT(maxDifference(before, after), 0.05);
  EXPECT_LE(maxDifference(after, want), kTolerance);
  // Out of range: clamped before the program reads it, as the shader's own use would be.
  EXPECT_TRUE(derived.setParameter("k", {40.0f}));
  EXPECT_TRUE(plain.setParameter("k", {40.0f}));
  derived.renderFrame();
  plain.renderFrame();
  EXPECT_LE(maxDifference(derived.readRgba32f(), plain.readRgba32f()), kTolerance);
}

// The frame's time is kept in double and a derived uniform reads it so: sin(4 t) at t = 1e7
// + 0.3 s is that of the exact time, not of its float (1e7: float32 steps 1 s there).
TEST(DerivedUniformTime, ADerivedValueReadsTheFramesTimeInDouble) {
  CompileResult on = compileFor("", true, {Target::Glsl330});
  const ManifestUniform* u = nullptr;
  for (const ManifestUniform& m : on.manifest.uniforms)
    if (m.derived && m.type == Type::Vec3) u = &m;  // normalize($wind) * sin(time * $k)
  ASSERT_TRUE(u);
  FrameValues f;
  f.time = 1e7 + 0.3;
  std::vector<Value> parameters = {Value::scalar(4), Value::vector({1, 0.5, 2})};  // k, wind: manifest order
  ASSERT_EQ(manifestParameters(on.manifest.uniforms).size(), 2u);
  ASSERT_EQ(manifestParameters(on.manifest.uniforms)[0].name, "k");
  std::vector<float> got = derivedUniformValue(*u->derived, f, parameters);
  ASSERT_EQ(got.size(), 3u);
  double wind = std::sqrt(1 + 0.25 + 4);
  double exact = std::sin((1e7 + 0.3) * 4) / wind;
  double ofFloat = std::sin(1e7 * 4) / wind;  // what float32(t) would give: 1.2 rad of phase away
  EXPECT_NEAR(got[0], exact, 1e-6);
  EXPECT_GT(std::abs(exact - ofFloat), 0.1) << "the case must tell the two apart";
}

}  // namespace derived_render_test
}  // namespace wg::rt
