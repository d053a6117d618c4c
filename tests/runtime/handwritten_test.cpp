// The hand-written water of bench/handwritten/ (wg_bench_handwritten compares it with the
// generated shaders) must not rot: it compiles and links with glslang as glsl330, uses the
// same stages as the generated program, and renders, in the generated manifest's scene and
// passes, the same image as the generated shaders (PSNR >= 35 dB) from two cameras.
#include <gtest/gtest.h>

#include "bench/handwritten/handwritten_water.h"
#include "codegen/glslang_validate.h"
#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

class Handwritten : public ::testing::TestWithParam<std::string> {};

TEST_P(Handwritten, CompilesWithGlslangInTheGeneratedStages) {
  CompileResult result = test::compileExample(GetParam());
  auto generated = handwritten::generatedShaders(result);
  auto hand = handwritten::handwrittenShaders(WG_SOURCE_DIR, GetParam(), result.manifest);
  ASSERT_EQ(hand.size(), generated.size());
  for (size_t i = 0; i < hand.size(); ++i) EXPECT_EQ(hand[i].stage, generated[i].stage) << hand[i].fileName;
  ValidationResult v = validateShaders(Target::Glsl330, hand);
  std::string messages;
  for (const auto& e : v.errors) messages += e.fileName + ":" + std::to_string(e.line) + ": " + e.text + "\n";
  EXPECT_TRUE(v.ok) << messages;
  // The form the bench counts SPIR-V instructions in.
  EXPECT_TRUE(relaxedSpirv(hand).has_value());
  EXPECT_TRUE(relaxedSpirv(generated).has_value());
}

TEST_P(Handwritten, RendersTheGeneratedImage) {
  CompileResult result = test::compileExample(GetParam());
  auto generated = handwritten::generatedShaders(result);
  auto hand = handwritten::handwrittenShaders(WG_SOURCE_DIR, GetParam(), result.manifest);
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  for (const char* camera : {"above", "grazing", "topdown"}) {
    RenderSettings settings = test::smallSettings();
    settings.camera = camera;
    Renderer gen(result.manifest, handwritten::forRuntime(generated), settings, false, textureOrigins(result));
    Renderer hw(result.manifest, handwritten::forRuntime(hand), settings, false, textureOrigins(result));
    gen.renderFrame();
    hw.renderFrame();
    Image a = gen.readRgba8(), b = hw.readRgba8();
    EXPECT_GT(lumaVariance(a, 0, a.height * 3 / 4, a.width, a.height), 1.0) << camera << ": the water is blank";
    EXPECT_GE(psnrRgb8(a, b), 35.0) << GetParam() << ", camera " << camera;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, Handwritten, ::testing::ValuesIn(handwritten::graphs()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace wg::rt
