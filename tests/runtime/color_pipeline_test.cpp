// The colour pipeline end to end, as a user meets it: a graph's linear output through the
// runtime's RGBA16F frame and the output transform into the PNG's bytes. A mid-grey sRGB
// PNG (128) sampled by texture_sample comes out as 128, a linear 0.5 as 188, on desktop GL
// OpenGL ES and Vulkan; the graph's "view" and RenderSettings::view choose the tone mapper.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/vk_preview.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

namespace fs = std::filesystem;

// A folder with a 4x4 PNG of one grey level and a graph showing it (or `color` when given)
// on the water, alone over black.
CompileResult compileGreyGraph(const fs::path& dir, const std::string& fragmentColor, const std::string& extra = "") {
  fs::create_directories(dir);
  Image png;
  png.width = png.height = 4;
  png.rgba8.assign(4 * 4 * 4, 128);
  for (size_t i = 3; i < png.rgba8.size(); i += 4) png.rgba8[i] = 255;
  writePng((dir / "grey.png").string(), png);
  const std::string text = R"({"version": 1, "name": "grey",)" + extra + R"(
    "parameters": {"half": {"type": "vec3", "default": [0.5, 0.5, 0.5], "description": "data, not a colour"}},
    "nodes": [{"id": "t", "type": "texture_sample", "options": {"texture": "grey.png", "color_space": "srgb"}}],
    "outputs": {"fragment": {"color": ")" + fragmentColor + R"("}}})";
  std::ofstream((dir / "grey.json").string()) << text;
  Diagnostics diags;
  auto graph = loadGraphFile((dir / "grey.json").string(), diags);
  for (const auto& d : diags.all()) ADD_FAILURE() << formatText(d);
  EXPECT_TRUE(graph);
  auto r = compileGraph(*graph, defaultRegistry(), [] { CompileOptions o; o.targets = {Target::Glsl330, Target::Es300, Target::Vk450}; return o; }(), diags);
  for (const auto& d : diags.all()) ADD_FAILURE() << formatText(d);
  EXPECT_TRUE(r);
  return std::move(*r);
}

RenderSettings waterAlone() {
  RenderSettings s = test::smallSettings();
  s.scene.drawScene = false;
  return s;
}

// The bottom-centre pixel: water in the "above" view.
const uint8_t* waterPixel(const Image& img) {
  return &img.rgba8[(static_cast<size_t>(img.height) * 7 / 8 * img.width + img.width / 2) * 4];
}

// Desktop GL and ES through EGL, vk450 on lavapipe under the validation layer.
Preview renderOn(const CompileResult& r, Target t, const RenderSettings& s) {
  return t == Target::Vk450 ? renderVulkanPreview(r, s, 1, false, /*validation=*/true) : renderPreview(r, t, s);
}

class ColorPipeline : public ::testing::TestWithParam<Target> {};

TEST_P(ColorPipeline, AnSrgbTextureOf128RendersAs128) {
  CompileResult r = compileGreyGraph(fs::path(test::makeTempDir("color_pipeline_128")), "t.rgb");
  Preview p = renderOn(r, GetParam(), waterAlone());
  const uint8_t* px = waterPixel(p.image);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[c], 128, 1) << "channel " << c;
}

TEST_P(ColorPipeline, ALinearHalfRendersAs188) {
  CompileResult r = compileGreyGraph(fs::path(test::makeTempDir("color_pipeline_half")), "$half");
  Preview p = renderOn(r, GetParam(), waterAlone());
  const uint8_t* px = waterPixel(p.image);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(px[c], 188) << "channel " << c;
  // The frame itself stays linear: the float read-back is the 0.5 the graph wrote.
  RenderSettings f = waterAlone();
  f.floatColor = true;
  Preview linear = renderOn(r, GetParam(), f);
  const size_t at = (static_cast<size_t>(linear.image.height) * 7 / 8 * linear.image.width + linear.image.width / 2) * 4;
  EXPECT_FLOAT_EQ(linear.image.rgba32f[at], 0.5f);
}

TEST_P(ColorPipeline, TheGraphsViewAndTheSettingsChooseTheToneMapper) {
  // A linear 0.5 at +3 EV is 4: clamped to white by none, below white by ACES.
  CompileResult r = compileGreyGraph(fs::path(test::makeTempDir("color_pipeline_view")), "$half",
                                     R"( "view": {"tonemap": "aces", "exposure": 3},)");
  EXPECT_EQ(r.program.view.toneMapper, ToneMapper::Aces);
  EXPECT_EQ(r.manifest.view.exposureEv, 3.0);
  RenderSettings s = waterAlone();
  s.view = r.program.view;
  const uint8_t aces = waterPixel(renderOn(r, GetParam(), s).image)[1];
  EXPECT_EQ(aces, std::lround(255 * outputTransform(s.view, {0.5, 0.5, 0.5})[1]));
  EXPECT_LT(aces, 250);
  s.view.toneMapper = ToneMapper::None;
  EXPECT_EQ(waterPixel(renderOn(r, GetParam(), s).image)[1], 255);
}

INSTANTIATE_TEST_SUITE_P(Targets, ColorPipeline, ::testing::Values(Target::Glsl330, Target::Es300, Target::Vk450),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::rt
