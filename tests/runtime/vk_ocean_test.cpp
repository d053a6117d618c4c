// The spectral ocean on Vulkan (runtime/vk_ocean_cascade.h, vk_ocean_foam.h,
// vk_ocean_simulation.h) on lavapipe under the Khronos validation layer, held to the same
// double references and bounds as the GL runtime's passes: each field of a cascade
// against FFTW (core/ocean_fft_reference.h) within the float32 transform's bound
// (ocean_gpu_cascade_test.cpp derives it, ocean_transform_bound.h computes it), the foam
// against the replayed reference (core/ocean_foam.h) within ocean_foam_bound.h's bound, and
// the simulation computing only the maps the shaders read, once per time, with GL's foam
// history. Any validation message fails the test that caused it.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "core/ocean_settings.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"
#include "runtime/vk_ocean_simulation.h"
#include "ocean_foam_bound.h"
#include "ocean_transform_bound.h"

namespace wg::rt {
// Named, not anonymous: the unity build joins this file with the GL ocean tests.
namespace vk_ocean_test {

constexpr double u = ocean_test::kUnitRoundoff;
using ocean_test::norm;

std::vector<double> mapChannel(const std::vector<float>& map, int c) {
  std::vector<double> out(map.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = map[i * 4 + static_cast<size_t>(c)];
  return out;
}

double distanceBetween(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

std::vector<double> times(const std::vector<double>& v, double s) {
  std::vector<double> out(v);
  for (double& x : out) x *= s;
  return out;
}

std::unique_ptr<VkContext> validatingContext() { return VkContext::create({.validation = true}); }

void recordCascade(VkContext& context, VkOceanCascade& cascade, double t, double lambda) {
  context.submit([&](VkCommandBuffer cmd) { cascade.record(cmd, t, lambda); });
  context.throwOnValidationMessages("simulating an ocean cascade");
}

TEST(VkOcean, FieldsMatchTheDoubleReferenceWithinTheTransformsBound) {
  auto context = validatingContext();
  ocean::SpectrumSettings s;  // JONSWAP, U10 = 10 m/s, 100 km
  for (int resolution : {64, 256}) {
    VkOceanPasses passes(*context);  // declared first: it outlives the images its sets name
    ocean::CascadeSettings c;
    c.resolution = resolution;
    c.tileLengths = {250};
    c.seed = 3;
    ocean::OceanCascade cascade = ocean::initialCascade(s, c, 0);
    VkOceanCascade gpu(passes, cascade);
    const double lambda = 0.8, bound = ocean_test::transformBound(resolution);
    for (double t : {0.0, 3.7, 1e6}) {
      SCOPED_TRACE("N = " + std::to_string(resolution) + ", t = " + std::to_string(t));
      recordCascade(*context, gpu, t, lambda);
      std::vector<float> displacement = gpu.readDisplacement(), slopes = gpu.readSlopes();
      ASSERT_EQ(displacement.size(), static_cast<size_t>(resolution) * resolution * 4);
      for (float v : displacement) ASSERT_TRUE(std::isfinite(v));
      for (float v : slopes) ASSERT_TRUE(std::isfinite(v));
      ocean::OceanFields f = ocean::oceanFields(cascade, t, lambda);
      // The four complex transforms' norms, as on GL.
      double z1 = std::hypot(norm(f.height), norm(f.displacementX));
      double z2 = std::hypot(norm(f.displacementZ), norm(f.slopeX));
      double z3 = std::hypot(norm(f.slopeZ), norm(f.dDxdx));
      double z4 = std::hypot(norm(f.dDzdz), norm(f.dDxdz));
      struct Check {
        const char* name;
        std::vector<double> got, want;
        double allowed;
      };
      const std::vector<Check> checks = {
          {"h", mapChannel(displacement, 1), f.height, bound * z1},
          {"lambda Dx", mapChannel(displacement, 0), times(f.displacementX, lambda),
           lambda * bound * z1 + u * lambda * norm(f.displacementX)},
          {"lambda Dz", mapChannel(displacement, 2), times(f.displacementZ, lambda),
           lambda * bound * z2 + u * lambda * norm(f.displacementZ)},
          {"dh/dx", mapChannel(slopes, 0), f.slopeX, bound * z2},
          {"dh/dz", mapChannel(slopes, 1), f.slopeZ, bound * z3},
          {"l dDx/dx", mapChannel(slopes, 2), times(f.dDxdx, lambda), lambda * bound * z3 + u * lambda * norm(f.dDxdx)},
          {"l dDz/dz", mapChannel(slopes, 3), times(f.dDzdz, lambda), lambda * bound * z4 + u * lambda * norm(f.dDzdz)},
          {"l dDx/dz", mapChannel(displacement, 3), times(f.dDxdz, lambda), lambda * bound * z4 + u * lambda * norm(f.dDxdz)},
      };
      for (const Check& check : checks) {
        double error = distanceBetween(check.got, check.want);
        std::printf("  vk450 %-9s ||error|| %.3e, bound %.3e (%.0f%%)\n", check.name, error, check.allowed,
                    100 * error / check.allowed);
        EXPECT_LE(error, check.allowed) << check.name;
      }
    }
  }
}

// A resolution per cascade (cascade_sizes): open_ocean's tiles on grids of 16^2, 32^2 and
// 64^2, each transformed on its own grid and held to FFTW there within its own N's bound.
TEST(VkOcean, EachCascadeOnItsOwnGridMatchesTheReference) {
  auto context = validatingContext();
  VkOceanPasses passes(*context);
  ocean::SpectrumSettings s;
  s.windSpeed = 7;
  s.fetch = 50e3;
  ocean::CascadeSettings c;
  c.tileLengths = {120, 24, 5};
  c.sizes = {16, 32, 64};
  const double lambda = 1.0, t = 3.7;
  for (int i = 0; i < 3; ++i) {
    const int n = c.sizes[static_cast<size_t>(i)];
    SCOPED_TRACE("cascade " + std::to_string(i) + " at " + std::to_string(n) + "^2");
    const ocean::OceanCascade cascade = ocean::initialCascade(s, c, i);
    VkOceanCascade gpu(passes, cascade);
    recordCascade(*context, gpu, t, lambda);
    const std::vector<float> displacement = gpu.readDisplacement(), slopes = gpu.readSlopes();
    ASSERT_EQ(displacement.size(), static_cast<size_t>(n) * n * 4);
    const ocean::OceanFields f = ocean::oceanFields(cascade, t, lambda);
    const double bound = ocean_test::transformBound(n);
    const double z1 = std::hypot(norm(f.height), norm(f.displacementX));
    const double z2 = std::hypot(norm(f.displacementZ), norm(f.slopeX));
    const double z3 = std::hypot(norm(f.slopeZ), norm(f.dDxdx));
    ASSERT_GT(norm(f.height), 0) << "a cascade with waves";
    EXPECT_LE(distanceBetween(mapChannel(displacement, 1), f.height), bound * z1);
    EXPECT_LE(distanceBetween(mapChannel(slopes, 0), f.slopeX), bound * z2);
    EXPECT_LE(distanceBetween(mapChannel(slopes, 1), f.slopeZ), bound * z3);
  }
}

// Nothing reads the slopes: the first texture's two transforms alone, the same
// displacement within the same bound, w = 0, no slope map.
TEST(VkOcean, ADisplacementOnlyCascadeComputesTheDisplacementAlone) {
  auto context = validatingContext();
  VkOceanPasses passes(*context);
  ocean::CascadeSettings c;
  c.resolution = 64;
  c.tileLengths = {250};
  ocean::OceanCascade cascade = ocean::initialCascade(ocean::SpectrumSettings{}, c, 0);
  VkOceanCascade gpu(passes, cascade, /*slopes=*/false);
  EXPECT_FALSE(gpu.computesSlopes());
  EXPECT_THROW(gpu.slopeMap(), std::logic_error);
  const double lambda = 0.8, t = 3.7, bound = ocean_test::transformBound(64);
  recordCascade(*context, gpu, t, lambda);
  std::vector<float> displacement = gpu.readDisplacement();
  ocean::OceanFields f = ocean::oceanFields(cascade, t, lambda);
  double z1 = std::hypot(norm(f.height), norm(f.displacementX));
  double z2 = std::hypot(norm(f.displacementZ), norm(f.slopeX));
  EXPECT_LE(distanceBetween(mapChannel(displacement, 1), f.height), bound * z1);
  EXPECT_LE(distanceBetween(mapChannel(displacement, 0), times(f.displacementX, lambda)),
            lambda * bound * z1 + u * lambda * norm(f.displacementX));
  EXPECT_LE(distanceBetween(mapChannel(displacement, 2), times(f.displacementZ, lambda)),
            lambda * bound * z2 + u * lambda * norm(f.displacementZ));
  for (double w : mapChannel(displacement, 3)) ASSERT_EQ(w, 0.0);
}

void recordFoam(VkContext& context, VkOceanFoam& foam, double t, double lambda, VkOceanCascade& cascade, FoamHistory h) {
  context.submit([&](VkCommandBuffer cmd) { foam.record(cmd, t, lambda, cascade, h); });
  context.throwOnValidationMessages("stepping an ocean's foam");
}

TEST(VkOcean, FoamMatchesTheReplayedReferenceWithinItsBound) {
  auto context = validatingContext();
  VkOceanPasses passes(*context);
  const double lambda = 2.5;
  ocean::FoamSettings f;
  ocean::OceanCascade cascade = ocean_test::storm(64);
  VkOceanCascade gpu(passes, cascade, /*slopes=*/true, /*jacobian=*/true);
  VkOceanFoam foam(passes, 64, f);
  for (double t : {4.25, 1e6 + 0.07}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    recordFoam(*context, foam, t, lambda, gpu, FoamHistory::Replay);
    EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
    std::vector<float> got = foam.readMap();
    ASSERT_EQ(got.size(), 64u * 64u);
    for (float v : got) ASSERT_TRUE(std::isfinite(v));
    std::vector<double> want = ocean_test::referenceFoam(cascade, lambda, f, t);
    const auto partial = std::count_if(want.begin(), want.end(), [](double v) { return v > 0.01 && v < 0.99; });
    EXPECT_GT(partial, static_cast<long>(want.size() / 100));
    const double error = ocean_test::worstDifference(got, want), bound = ocean_test::foamBound(cascade, lambda, f, t);
    std::printf("  vk450 foam t = %.2f: max error %.3e, bound %.3e (%.1f%%)\n", t, error, bound, 100 * error / bound);
    EXPECT_LE(error, bound);
  }
}

// GL's foam history (ocean_gpu_foam_test.cpp): an animation runs the steps since its last
// frame, a still frame or a jump back replays.
TEST(VkOcean, AnAnimationContinuesItsStepsInsteadOfReplaying) {
  auto context = validatingContext();
  VkOceanPasses passes(*context);
  const double lambda = 2.5;
  ocean::FoamSettings f;
  ocean::OceanCascade cascade = ocean_test::storm(64);
  VkOceanCascade gpu(passes, cascade, false, true);
  VkOceanFoam foam(passes, 64, f);
  recordFoam(*context, foam, 10.02, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
  recordFoam(*context, foam, 10.05, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), 0);
  recordFoam(*context, foam, 10.27, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), 2);
  std::vector<double> want = ocean_test::referenceFoam(cascade, lambda, f, 10.27);
  EXPECT_LE(ocean_test::worstDifference(foam.readMap(), want),
            std::pow(ocean::foamKeep(f), ocean::historySteps(f)) + ocean_test::foamBound(cascade, lambda, f, 10.27));
  recordFoam(*context, foam, 3.0, lambda, gpu, FoamHistory::Continue);
  EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
  recordFoam(*context, foam, 3.15, lambda, gpu, FoamHistory::Replay);
  EXPECT_EQ(foam.lastSteps(), ocean::historySteps(f) + 1);
}

Manifest seaManifest(const std::string& color) {
  Diagnostics diags;
  auto graph = parseGraph(R"({"version": 1, "name": "vk_sea", "nodes": [
      {"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [100, 10], "foam_cascades": 1,
                                                     "foam_decay": 0.3}},
      {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
      {"id": "foam", "type": "ocean_foam", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}}],
      "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": ")" + color + R"("}}})",
                          "vk_sea.json", diags);
  CompileOptions o;
  o.targets = {Target::Vk450};
  auto result = graph ? compileGraph(*graph, defaultRegistry(), o, diags) : std::nullopt;
  if (!result) throw std::runtime_error("the test graph does not compile");
  return result->manifest;
}

// Slopes where a slope map is read, foam where a foam map is read (the first foam_cascades
// only), one record per time and foam history.
TEST(VkOcean, TheSimulationComputesOnlyWhatTheShadersReadOncePerTime) {
  auto context = validatingContext();
  Manifest positionOnly = seaManifest("moved.position");
  VkOceanSimulation displacement(*context, positionOnly.oceans, positionOnly.textures);
  for (int c : {0, 1}) {
    EXPECT_FALSE(displacement.computesSlopes(0, c)) << "cascade " << c;
    EXPECT_FALSE(displacement.computesFoam(0, c)) << "cascade " << c;
  }
  EXPECT_THROW(displacement.map({0, 0, ocean::kSlopeMap}), RuntimeError);
  EXPECT_THROW(displacement.map({0, 2, ocean::kDisplacementMap}), RuntimeError);
  Manifest withNormal = seaManifest("moved.normal");
  VkOceanSimulation slopes(*context, withNormal.oceans, withNormal.textures);
  for (int c : {0, 1}) EXPECT_TRUE(slopes.computesSlopes(0, c)) << "cascade " << c;
  Manifest withFoam = seaManifest("foam.foam");
  VkOceanSimulation foam(*context, withFoam.oceans, withFoam.textures);
  EXPECT_TRUE(foam.computesFoam(0, 0));
  EXPECT_FALSE(foam.computesFoam(0, 1));  // foam_cascades 1
  auto record = [&](VkOceanSimulation& s, double t) {
    context->submit([&](VkCommandBuffer cmd) { s.record(cmd, t); });
    context->throwOnValidationMessages("simulating the oceans");
  };
  record(foam, 2.0);
  EXPECT_EQ(foam.lastFoamSteps(), 16);  // K = 15 (5 x 0.3 s / 0.1 s) + 1, one cascade
  EXPECT_EQ(foam.updatesRecorded(), 1);
  record(foam, 2.0);  // the maps hold t = 2 already
  EXPECT_EQ(foam.updatesRecorded(), 1);
  EXPECT_EQ(foam.lastFoamSteps(), 0);
  foam.setFoamHistory(FoamHistory::Continue);  // another history: the foam may differ, so it runs
  record(foam, 2.0);
  EXPECT_EQ(foam.updatesRecorded(), 2);
  record(displacement, 2.0);
  EXPECT_EQ(displacement.lastFoamSteps(), 0);
}

}  // namespace vk_ocean_test
}  // namespace wg::rt
