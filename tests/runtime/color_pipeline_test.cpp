// The colour pipeline end to end, as a user meets it: a graph's linear output through the
// runtime's RGBA16F frame and the output transform into the PNG's bytes. A mid-grey sRGB
// PNG (128) sampled by texture_sample comes out as 128, a linear 0.5 as 188, on desktop GL
// OpenGL ES and Vulkan; the graph's "view" and RenderSettings::view choose the tone mapper.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/renderer.h"
#include "runtime/sky_model.h"
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

// HDR survives the scene passes: the sun's disc (tens of thousands of units, far above the
// 1 an RGBA8 target clamps to) seen through the water from below via the scene colour
// copy, and from above via the planar reflection, comes back in the linear frame as the
// sky model's disc radiance within half-float rounding; with ACES at the exposure that
// makes it 4, the displayed pixel is below white.
struct HdrCase {
  const char* pass;
  const char* sampler;
  float cameraY, elevationSign;  // under the water looking up at the sun, or above it looking at its mirror image
};

class HdrThroughScenePasses : public ::testing::TestWithParam<GlApi> {};

TEST_P(HdrThroughScenePasses, TheSunsDiscSurvivesTheCopyAndTheReflection) {
  auto ctx = EglContext::create(GetParam());
  for (const HdrCase& c : {HdrCase{"scene_color_copy", "u_scene_color", -1.0f, 1.0f},
                           HdrCase{"planar_reflection", "u_reflection", 1.0f, -1.0f}}) {
    SCOPED_TRACE(c.pass);
    RenderSettings s = test::smallSettings();
    s.width = s.height = 64;
    const glm::vec3 sun = sunDirection(s.scene);
    const glm::vec3 look(sun.x, c.elevationSign * sun.y, sun.z);
    Camera cam;
    cam.position = glm::vec3(0, c.cameraY, 0);
    cam.target = cam.position + look;
    cam.fovYDegrees = 2.0f;  // the disc (0.27 deg in radius) covers the middle 17 pixels across
    s.customCamera = cam;
    Renderer r(Manifest::fromJson(test::handManifest({c.pass}, {c.sampler})), test::handWaterShaders(ctx->isEs(), {c.sampler}),
               s, ctx->isEs());
    r.renderFrame();
    Image linear = r.readRgba32f();
    const float* px = &linear.rgba32f[(32u * 64u + 32u) * 4];
    // The disc band-limited to these pixels (2 tan(1 deg) / 64 across at the middle): its
    // flat top 1.26 times the capped radiance (runtime/sky_model.h).
    const double footprint = 2.0 * std::tan(glm::radians(1.0)) / 64.0;
    const glm::dvec3 disc = sky::sunDiscRadiance(glm::dvec3(sun)) * sky::sunDiscShape(footprint).scale;
    ASSERT_GT(disc.r, 4.0) << "the case must hold more than an 8-bit target can";
    for (int ch = 0; ch < 3; ++ch)  // half-float rounding (2^-11) and float32 sky arithmetic
      EXPECT_NEAR(px[ch], disc[ch], 2e-3 * disc[ch]) << "channel " << ch;

    // The same pixel shown through ACES at the exposure that makes its red 4: below white.
    const double maxChannel = std::max({disc.r, disc.g, disc.b});
    s.view = {ToneMapper::Aces, std::log2(4.0 / maxChannel)};
    Renderer shown(Manifest::fromJson(test::handManifest({c.pass}, {c.sampler})),
                   test::handWaterShaders(ctx->isEs(), {c.sampler}), s, ctx->isEs());
    shown.renderFrame();
    Image display = shown.readRgba8();
    const uint8_t* d = &display.rgba8[(32u * 64u + 32u) * 4];
    EXPECT_LT(std::max({d[0], d[1], d[2]}), 250);
    EXPECT_GT(std::max({d[0], d[1], d[2]}), 200);
  }
}

INSTANTIATE_TEST_SUITE_P(Apis, HdrThroughScenePasses, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return info.param == GlApi::Es32 ? std::string("es32") : std::string("gl45"); });

INSTANTIATE_TEST_SUITE_P(Targets, ColorPipeline, ::testing::Values(Target::Glsl330, Target::Es300, Target::Vk450),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::rt
