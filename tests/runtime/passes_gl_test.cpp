// The passes on the GPU (llvmpipe) with hand-written water shaders that sample the scene
// textures: targets exist only for planned passes, their sizes are what the driver
// allocated, and each texture carries an image of the scene.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/renderer.h"
#include "runtime/runtime_error.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

const std::vector<std::string> kAllPasses = {"depth_prepass", "scene_color_copy", "planar_reflection", "refraction",
                                             "environment_cubemap"};
const std::vector<std::string> kAllSamplers = {"u_scene_depth", "u_scene_color", "u_reflection", "u_refraction",
                                               "u_environment"};

Image renderWith(EglContext& ctx, const std::vector<std::string>& passes, const std::vector<std::string>& samplers,
                 RenderSettings s = test::smallSettings(), int* targetCount = nullptr, size_t* bytes = nullptr,
                 size_t* plannedBytes = nullptr) {
  Renderer r(Manifest::fromJson(test::handManifest(passes, samplers)), test::handWaterShaders(ctx.isEs(), samplers), s,
             ctx.isEs());
  r.renderFrame();
  if (targetCount) *targetCount = r.createdTargetCount();
  if (bytes) *bytes = r.createdTargetBytes();
  if (plannedBytes) *plannedBytes = r.plan().totalBytes();
  Image img = s.floatColor ? r.readRgba32f() : r.readRgba8();
  // WG_RUNTIME_DUMP=folder keeps each 8-bit render for a look: <api>_<samplers>.png.
  if (const char* dump = std::getenv("WG_RUNTIME_DUMP"); dump && !s.floatColor) {
    std::string name = ctx.isEs() ? "es32" : "gl45";
    for (const auto& x : samplers) name += "_" + x;
    writePng(std::string(dump) + "/" + name + ".png", img);
  }
  return img;
}

class PassesGl : public ::testing::TestWithParam<GlApi> {};

TEST_P(PassesGl, AllPassesCreateTheirTargetsAndFeedTheWater) {
  auto ctx = EglContext::create(GetParam());
  int count = 0;
  size_t bytes = 0, planned = 0;
  RenderSettings s = test::smallSettings();
  s.floatColor = true;
  s.environmentSize = 32;
  Image img = renderWith(*ctx, kAllPasses, kAllSamplers, s, &count, &bytes, &planned);
  EXPECT_EQ(count, 6);
  EXPECT_EQ(bytes, planned) << "driver-reported texture sizes differ from the plan";
  EXPECT_EQ(bytes, 320u * 180u * (20 + 4 + 16 + 20 + 20) + 32u * 32u * 6u * 16u);
  EXPECT_EQ(countNonFinite(img), 0u);
}

TEST_P(PassesGl, EachSceneTextureShowsTheScene) {
  auto ctx = EglContext::create(GetParam());
  for (size_t i = 0; i < kAllPasses.size(); ++i) {
    SCOPED_TRACE(kAllPasses[i]);
    int count = 0;
    Image img = renderWith(*ctx, {kAllPasses[i]}, {kAllSamplers[i]}, test::smallSettings(), &count);
    EXPECT_EQ(count, 3) << "the frame, this pass's target and the display image only";
    EXPECT_GT(lumaVariance(img, 0, 90, 320, 180), 1.0) << "the sampled texture is flat";
  }
}

TEST_P(PassesGl, ReflectionAndRefractionDiffer) {
  auto ctx = EglContext::create(GetParam());
  Image refl = renderWith(*ctx, {"planar_reflection"}, {"u_reflection"});
  Image refr = renderWith(*ctx, {"refraction"}, {"u_refraction"});
  EXPECT_LT(psnrRgb8(refl, refr), 25.0);
}

TEST_P(PassesGl, SamplingATextureWhosePassIsNotListedIsAnError) {
  auto ctx = EglContext::create(GetParam());
  Manifest m = Manifest::fromJson(test::handManifest({}, {}));  // no passes, no textures listed
  try {
    Renderer r(m, test::handWaterShaders(ctx->isEs(), {"u_reflection"}), test::smallSettings(), ctx->isEs());
    ADD_FAILURE() << "no error";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Manifest);
    EXPECT_NE(std::string(e.what()).find("u_reflection"), std::string::npos) << e.what();
  }
  // Listed as a texture but its pass is not: also an error.
  Manifest m2 = Manifest::fromJson(test::handManifest({}, {"u_reflection"}));
  EXPECT_THROW(Renderer(m2, test::handWaterShaders(ctx->isEs(), {"u_reflection"}), test::smallSettings(), ctx->isEs()),
               RuntimeError);
}

INSTANTIATE_TEST_SUITE_P(Apis, PassesGl, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return std::string(info.param == GlApi::Es32 ? "es32" : "gl45"); });

TEST(DriverErrors, ARejectedShaderNamesTheFileAndCarriesTheLog) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  auto shaders = test::handWaterShaders(false, {});
  shaders[1].text = "#version 330 core\nout vec4 o_color;\nvoid main() { o_color = undefined_thing; }\n";
  try {
    Renderer r(Manifest::fromJson(test::handManifest({}, {})), shaders, test::smallSettings(), false);
    ADD_FAILURE() << "no error";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Driver);
    EXPECT_EQ(e.exitCode(), 1);
    std::string m = e.what();
    EXPECT_NE(m.find("hand.glsl330.frag"), std::string::npos) << m;
    EXPECT_NE(m.find("undefined_thing"), std::string::npos) << m;
  }
}

// A builtin that only the probe sets (an unknown one is refused by Manifest::fromJson) and an
// attribute the water grid does not have.
TEST(ManifestErrors, ProbeBuiltinAndBadAttribute) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  nlohmann::json m = test::handManifest({}, {});
  m["uniforms"].push_back({{"name", "u_probe_uv"}, {"type", "vec2"}, {"stages", {"fragment"}}, {"builtin", "uv"}});
  try {
    Renderer r(Manifest::fromJson(m), test::handWaterShaders(false, {}), test::smallSettings(), false);
    ADD_FAILURE() << "no error";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Manifest);
    EXPECT_NE(std::string(e.what()).find("does not provide"), std::string::npos) << e.what();
  }
  nlohmann::json m2 = test::handManifest({}, {});
  m2["attributes"].push_back({{"name", "a_tangent"}, {"type", "vec4"}, {"location", 3}});
  EXPECT_THROW(Renderer(Manifest::fromJson(m2), test::handWaterShaders(false, {}), test::smallSettings(), false),
               RuntimeError);
}

TEST(NodeTextures, AMalformedPngIsAnErrorNamingTheNode) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  std::string dir = test::makeTempDir("wg_tex_");
  { std::ofstream(dir + "/broken.png") << "not a png at all"; }
  nlohmann::json m = test::handManifest({}, {});
  m["textures"].push_back(
      {{"name", "t0_broken"}, {"type", "sampler2D"}, {"binding", 1}, {"stages", {"fragment"}}, {"source", "broken.png"}, {"file", "g.t0_broken.png"}});
  std::map<std::string, TextureOrigin> origins{{"broken.png", {dir, "pond.json:7:5: node 'foam'"}}};
  try {
    Renderer r(Manifest::fromJson(m), test::handWaterShaders(false, {}), test::smallSettings(), false, origins);
    ADD_FAILURE() << "no error";
  } catch (const RuntimeError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("node 'foam'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("broken.png"), std::string::npos) << msg;
  }
  nlohmann::json missing = test::handManifest({}, {});
  missing["textures"].push_back(
      {{"name", "t0_gone"}, {"type", "sampler2D"}, {"binding", 1}, {"stages", {"fragment"}}, {"source", "gone.png"}, {"file", "g.t0_gone.png"}});
  std::map<std::string, TextureOrigin> o2{{"gone.png", {dir, "pond.json:9:5: node 'ripples'"}}};
  try {
    Renderer r(Manifest::fromJson(missing), test::handWaterShaders(false, {}), test::smallSettings(), false, o2);
    ADD_FAILURE() << "no error";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("node 'ripples'"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(NodeTextures, ABuiltinTextureLoads) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  nlohmann::json m = test::handManifest({}, {});
  m["textures"].push_back(
      {{"name", "t0_foam"}, {"type", "sampler2D"}, {"binding", 1}, {"stages", {"fragment"}}, {"source", "builtin:foam"}, {"file", "g.t0_foam.png"}});
  EXPECT_NO_THROW(Renderer(Manifest::fromJson(m), test::handWaterShaders(false, {}), test::smallSettings(), false));
}

}  // namespace
}  // namespace wg::rt
