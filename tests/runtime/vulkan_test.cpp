// The vk450 SPIR-V runs on Vulkan (lavapipe) under the Khronos validation layer: every
// example graph's image (open_ocean's spectral ocean simulated by each runtime's own
// passes) matches the glsl330 image of the same settings, rendered in the same test, at
// >= 40 dB PSNR, and so does every camera for two graphs that run every pass
// kind (deferred_underwater: depth, scene copy, cube map, deferred G-buffer;
// classic_webgl: planar reflection and refraction). Every render here has the layer on and
// fails on any message it reports; the layer is shown to be active by a deliberate misuse,
// and a missing layer is an error, never a skip.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"
#include "runtime/vk_context.h"
#include "runtime/vk_preview.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

// Renders `graph` with both backends and compares; on a failure both images are left in
// the temporary folder.
void expectVulkanMatchesGl(const std::string& graph, const RenderSettings& settings) {
  CompileResult r = test::compileExample(graph, {Target::Glsl330, Target::Vk450});
  Preview gl = renderPreview(r, Target::Glsl330, settings);
  Preview vk = renderVulkanPreview(r, settings, 1, false, /*validation=*/true);
  ASSERT_EQ(vk.image.width, gl.image.width);
  ASSERT_EQ(vk.image.height, gl.image.height);
  EXPECT_EQ(vk.plan.passes, gl.plan.passes);
  EXPECT_EQ(vk.targetBytes, vk.plan.totalBytes());
  double psnr = psnrRgb8(gl.image, vk.image);
  std::printf("  %s at camera %s: vk450 against glsl330 %.1f dB\n", graph.c_str(), settings.camera.c_str(), psnr);
  EXPECT_GE(psnr, 40.0) << graph << " at camera " << settings.camera;
  if (psnr < 40.0) {
    auto dir = std::filesystem::temp_directory_path();
    std::string base = graph + "." + settings.camera;
    writePng((dir / (base + ".glsl330.png")).string(), gl.image);
    writePng((dir / (base + ".vk450.png")).string(), vk.image);
    ADD_FAILURE() << "the images are " << (dir / (base + ".{glsl330,vk450}.png")).string();
  }
}

class VulkanExample : public ::testing::TestWithParam<std::string> {};

TEST_P(VulkanExample, MatchesTheGlsl330Image) { expectVulkanMatchesGl(GetParam(), test::smallSettings()); }

INSTANTIATE_TEST_SUITE_P(Graphs, VulkanExample, ::testing::ValuesIn(test::exampleGraphNames()),
                         [](const auto& info) { return info.param; });

struct CameraCase {
  std::string graph, camera;
};
void PrintTo(const CameraCase& c, std::ostream* os) { *os << c.graph << "/" << c.camera; }

std::vector<CameraCase> cameraCases() {
  std::vector<CameraCase> out;
  for (const char* g : {"deferred_underwater", "classic_webgl"})
    for (const auto& cam : cameraPresetNames()) out.push_back({g, cam});
  return out;
}

class VulkanCamera : public ::testing::TestWithParam<CameraCase> {};

// Smaller than the example renders: four cameras per graph, each frame on both backends.
TEST_P(VulkanCamera, MatchesTheGlsl330Image) {
  RenderSettings s = test::smallSettings();
  s.width = 160;
  s.height = 90;
  s.camera = GetParam().camera;
  expectVulkanMatchesGl(GetParam().graph, s);
}

INSTANTIATE_TEST_SUITE_P(Cameras, VulkanCamera, ::testing::ValuesIn(cameraCases()),
                         [](const auto& info) { return info.param.graph + "_" + info.param.camera; });

// A buffer of size 0 breaks VUID-VkBufferCreateInfo-size-00912: the layer must say so,
// and the context must turn what it said into an error.
TEST(VulkanValidation, TheLayerReportsADeliberateMisuse) {
  auto context = VkContext::create({.validation = true});
  ASSERT_TRUE(context->validating());
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = 0;
  bci.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(context->device(), &bci, nullptr, &buffer) == VK_SUCCESS && buffer)
    vkDestroyBuffer(context->device(), buffer, nullptr);
  std::vector<std::string> messages = context->takeValidationMessages();
  ASSERT_FALSE(messages.empty()) << "the validation layer is not active";
  EXPECT_NE(messages.front().find("VUID-VkBufferCreateInfo-size-00912"), std::string::npos) << messages.front();

  if (vkCreateBuffer(context->device(), &bci, nullptr, &buffer) == VK_SUCCESS && buffer)
    vkDestroyBuffer(context->device(), buffer, nullptr);
  EXPECT_THROW(context->throwOnValidationMessages("testing"), RuntimeError);
}

// The loader finds no layer where VK_LAYER_PATH points to an empty folder: asking for
// validation is then an environment error naming the layer, not a render without it.
TEST(VulkanValidation, AMissingLayerIsAnError) {
  std::string empty = test::makeTempDir("wg_no_layers");
  const char* previous = std::getenv("VK_LAYER_PATH");
  std::string saved = previous ? previous : "";
  setenv("VK_LAYER_PATH", empty.c_str(), 1);
  try {
    VkContext::create({.validation = true});
    ADD_FAILURE() << "a context was made without the validation layer";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Environment);
    EXPECT_NE(std::string(e.what()).find(kValidationLayer), std::string::npos) << e.what();
  }
  if (previous) setenv("VK_LAYER_PATH", saved.c_str(), 1);
  else unsetenv("VK_LAYER_PATH");
}

}  // namespace
}  // namespace wg::rt
