// The runtimes honour the manifest's "pass_scales" (the `resolution` knob of the nodes
// reading the scene): the scene targets are created at that fraction of the frame (the GL
// objects' measured bytes are the plan's), and the frame rendered from them differs from
// the full-resolution one yet stays close to it and finite. Vulkan renders the same
// reduced passes as GL. The shaders are the graph's own: only the manifest changes.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/vk_preview.h"
#include "runtime_test_support.h"

namespace wg::rt {
namespace {

// Every frame-sized scene pass the manifest lists at `scale` of the frame.
CompileResult scaled(CompileResult r, double scale) {
  for (RenderPass p : r.manifest.passes)
    if (p != RenderPass::WaterSurface && p != RenderPass::EnvironmentCubemap) r.manifest.passScales.push_back({p, scale});
  return r;
}

// PSNR (peak 1) of the frames as exposure 0 shows them, each value clamped to [0, 1]: the
// frames are linear radiance in which the sun's disc and its glints reach 30000
// (runtime/sky_model.h), so one glint a pixel away would outweigh the whole picture.
double floatPsnr(const Image& a, const Image& b) {
  double sq = 0;
  size_t n = 0;
  auto shown = [](float v) { return std::clamp(static_cast<double>(v), 0.0, 1.0); };
  for (size_t i = 0; i < a.rgba32f.size(); ++i) {
    if (i % 4 == 3) continue;
    double d = shown(a.rgba32f[i]) - shown(b.rgba32f[i]);
    sq += d * d, ++n;
  }
  return sq > 0 ? 10 * std::log10(static_cast<double>(n) / sq) : INFINITY;
}

struct ResolutionCase {
  std::string graph;
  Target target;
  double minPsnrHalf;  // at 0.5; at 0.25 the bound is 8 dB lower
};

void PrintTo(const ResolutionCase& c, std::ostream* os) { *os << c.graph << "/" << targetName(c.target); }

class SceneResolution : public ::testing::TestWithParam<ResolutionCase> {};

TEST_P(SceneResolution, ReducedScenePassesDifferButStayCloseAndFinite) {
  const ResolutionCase& c = GetParam();
  CompileResult full = test::compileExample(c.graph);
  RenderSettings s = test::smallSettings();  // 320 x 180
  s.floatColor = true;
  Preview ref = renderPreview(full, c.target, s);
  double previous = INFINITY;
  for (double scale : {0.5, 0.25}) {
    SCOPED_TRACE(scale);
    Preview p = renderPreview(scaled(full, scale), c.target, s);
    ASSERT_EQ(p.image.width, 320);
    for (const TargetSpec& t : p.plan.targets) {
      if (t.name == "frame" || t.cube) continue;
      EXPECT_EQ(t.width, scaledSize(320, scale)) << t.name;
      EXPECT_EQ(t.height, scaledSize(180, scale)) << t.name;
    }
    EXPECT_EQ(p.targetBytes, p.plan.totalBytes()) << "the GL targets are the plan's smaller sizes";
    EXPECT_LT(p.targetBytes, ref.targetBytes);
    EXPECT_EQ(countNonFinite(p.image), 0u);
    double psnr = floatPsnr(ref.image, p.image);
    std::printf("%s %s scene passes at %g: %.2f dB against full resolution\n", c.graph.c_str(),
                std::string(targetName(c.target)).c_str(), scale, psnr);
    EXPECT_LT(psnr, 200.0) << "a reduced scene changes the frame";
    EXPECT_GE(psnr, scale == 0.5 ? c.minPsnrHalf : c.minPsnrHalf - 8) << "but stays near it";
    EXPECT_LE(psnr, previous + 0.5) << "a quarter is no closer than a half";
    previous = psnr;
  }
}

INSTANTIATE_TEST_SUITE_P(Graphs, SceneResolution,
                         // Bounds ~2 dB under the measured half-resolution PSNR (deferred
                         // 20.0 dB: the nearest-read G-buffer and depth turn edges into 2x2
                         // blocks; classic_webgl 30.1, stylized 30.2, with the daylight sky).
                         ::testing::Values(ResolutionCase{"deferred_underwater", Target::Glsl330, 18.0},
                                           ResolutionCase{"deferred_underwater", Target::Es300, 18.0},
                                           ResolutionCase{"classic_webgl", Target::Glsl330, 28.0},
                                           ResolutionCase{"stylized", Target::Glsl330, 28.0}),
                         [](const auto& info) {
                           return info.param.graph + "_" + std::string(targetName(info.param.target));
                         });

// Vulkan (lavapipe, validation on) renders the same reduced passes: its frame matches
// GL's at half resolution as closely as at full (the vulkan suite's 40 dB).
TEST(SceneResolutionVulkan, HalfResolutionMatchesGl) {
  for (const char* graph : {"deferred_underwater", "classic_webgl"}) {
    SCOPED_TRACE(graph);
    CompileResult r = scaled(test::compileExample(graph, {Target::Glsl330, Target::Vk450}), 0.5);
    RenderSettings s = test::smallSettings();
    Preview gl = renderPreview(r, Target::Glsl330, s);
    Preview vk = renderVulkanPreview(r, s, 1, false, /*validation=*/true);
    EXPECT_EQ(vk.targetBytes, vk.plan.totalBytes());
    EXPECT_EQ(vk.plan.target("scene_depth")->width, 160);
    EXPECT_GE(psnrRgb8(gl.image, vk.image), 40.0);
  }
}

}  // namespace
}  // namespace wg::rt
