// The spectral ocean's persistent foam on the GPU (runtime/ocean_gpu_foam.h) on desktop GL
// 4.5 and ES 3.2 (llvmpipe) against the double reference's replay (core/ocean_foam.h).
// The bound is ocean_foam_bound.h's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "core/ocean_foam.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/ocean_gpu_foam.h"
#include "runtime/ocean_simulation.h"
#include "ocean_foam_bound.h"
#include "ocean_transform_bound.h"

namespace wg::rt {
// Named, not anonymous: the unity build joins this file with ocean_gpu_cascade_test.cpp.
namespace foam_gpu_test {

using ocean_test::foamBound;
using ocean_test::referenceFoam;
using ocean_test::storm;
using ocean_test::worstDifference;

SceneShaderApi apiOf(GlApi api) { return api == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330; }

class OceanGpuFoamTest : public ::testing::TestWithParam<GlApi> {};

TEST_P(OceanGpuFoamTest, FoamMatchesTheReplayedReferenceWithinItsBound) {
  auto ctx = EglContext::create(GetParam());
  const double lambda = 2.5;
  ocean::FoamSettings f;
  for (int resolution : {64, 256}) {
    ocean::OceanCascade cascade = storm(resolution);
    OceanGpuCascade gpu(cascade, apiOf(GetParam()), /*slopes=*/false, /*jacobian=*/true);
    OceanGpuFoam foam(resolution, f, apiOf(GetParam()));
    // The finer grid at the huge time alone: its replay's reference is most of the test's time.
    for (double t : resolution == 64 ? std::vector<double>{4.25, 1e6 + 0.07} : std::vector<double>{1e6 + 0.07}) {
      SCOPED_TRACE("N = " + std::to_string(resolution) + ", t = " + std::to_string(t));
      foam.update(t, lambda, gpu, FoamHistory::Replay);
      EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
      std::vector<float> got = foam.readMap();
      for (float v : got) ASSERT_TRUE(std::isfinite(v));
      std::vector<double> want = referenceFoam(cascade, lambda, f, t);
      // The sea reaches what the comparison is about: foam below the clamp and clear water.
      const auto partial = std::count_if(want.begin(), want.end(), [](double v) { return v > 0.01 && v < 0.99; });
      EXPECT_GT(partial, static_cast<long>(want.size() / 100));
      const double error = worstDifference(got, want), bound = foamBound(cascade, lambda, f, t);
      std::printf("  foam N = %d, t = %.2f: max error %.3e, bound %.3e (%.1f%%)\n", resolution, t, error, bound,
                  100 * error / bound);
      EXPECT_LE(error, bound);
    }
  }
}

// An animation continues its steps: a frame 0.25 s on runs the 2 or 3 steps since, and its
// foam is the replay's to within the window's forgetting e^(-K step / decay) and the bound.
TEST_P(OceanGpuFoamTest, AnAnimationContinuesItsStepsInsteadOfReplaying) {
  auto ctx = EglContext::create(GetParam());
  const double lambda = 2.5;
  ocean::FoamSettings f;
  ocean::OceanCascade cascade = storm(64);
  OceanGpuCascade gpu(cascade, apiOf(GetParam()), false, true);
  OceanGpuFoam foam(64, f, apiOf(GetParam()));
  foam.update(10.02, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);  // the first frame replays
  foam.update(10.05, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), 0);  // the same step: only the blend
  foam.update(10.27, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), 2);  // f_100 and f_101 were held; f_102 and f_103 now
  std::vector<double> want = referenceFoam(cascade, lambda, f, 10.27);
  const double error = worstDifference(foam.readMap(), want);
  EXPECT_LE(error, std::pow(ocean::foamKeep(f), ocean::historySteps(f)) + foamBound(cascade, lambda, f, 10.27));
  // Backwards or further than the window: a replay.
  foam.update(3.0, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
  // A still frame replays whenever the step changes.
  foam.update(3.15, lambda, gpu, FoamHistory::Replay);
  EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
}

// The simulation keeps foam for the cascades whose foam map a shader samples, and only the
// first foam_cascades of them make any.
TEST_P(OceanGpuFoamTest, TheSimulationComputesFoamOnlyWhereItIsRead) {
  auto ctx = EglContext::create(GetParam());
  auto compile = [](const std::string& color) {
    Diagnostics diags;
    auto graph = parseGraph(R"({"version": 1, "name": "foam_test", "nodes": [
        {"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [100, 10], "foam_cascades": 1,
                                                       "foam_decay": 0.3}},
        {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
        {"id": "foam", "type": "ocean_foam", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}}],
        "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": ")" + color + R"("}}})",
                            "foam_test.json", diags);
    CompileOptions o;
    o.targets = {Target::Glsl330};
    auto result = graph ? compileGraph(*graph, defaultRegistry(), o, diags) : std::nullopt;
    if (!result) throw std::runtime_error("the test graph does not compile");
    return result->manifest;
  };
  Manifest withFoam = compile("foam.foam");
  OceanSimulation foam(withFoam.oceans, withFoam.textures, apiOf(GetParam()));
  EXPECT_TRUE(foam.computesFoam(0, 0));
  EXPECT_FALSE(foam.computesFoam(0, 1));  // foam_cascades 1
  foam.update(2.0);
  EXPECT_EQ(foam.lastFoamSteps(), 16);  // K = 15 (5 x 0.3 s / 0.1 s) + 1, one cascade
  Manifest without = compile("moved.position");
  OceanSimulation none(without.oceans, without.textures, apiOf(GetParam()));
  EXPECT_FALSE(none.computesFoam(0, 0));
  none.update(2.0);
  EXPECT_EQ(none.lastFoamSteps(), 0);
  // Four R32F 64^2 maps for the one foam cascade.
  EXPECT_EQ(OceanSimulation::textureBytes(withFoam.oceans, withFoam.textures) -
                OceanSimulation::textureBytes(without.oceans, without.textures),
            4u * 64u * 64u * 4u);
}

INSTANTIATE_TEST_SUITE_P(Apis, OceanGpuFoamTest, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return info.param == GlApi::Es32 ? std::string("es32") : std::string("gl45"); });

}  // namespace foam_gpu_test
}  // namespace wg::rt
