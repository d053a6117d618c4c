// The spectral ocean's GPU cascade (runtime/ocean_gpu_cascade.h) on desktop GL 4.5 and
// ES 3.2 (llvmpipe) against the FFTW reference in double (core/ocean_fft_reference.h),
// field by field, within the error bound of a float32 radix-2 FFT, at t = 0, 3.7 s and
// 1e6 s. No texel may be NaN or infinite.
//
// The bound (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., thm. 24.2):
// a radix-2 FFT of length n in arithmetic of unit roundoff u, with twiddles accurate to mu,
// computes y with ||y^ - y||_2 <= (log2 n) eta / (1 - (log2 n) eta) ||y||_2,
// eta = mu + gamma_4 (sqrt 2 + mu), gamma_4 = 4u / (1 - 4u). The 2-D transform is the 1-D
// one along x then along z: log2 n = 2 log2 N. The twiddles are rounded once from double
// (mu = u). The evolution pass adds its own rounding to the input spectrum, eta_in: h0
// rounded to float (u), the phase's float (2^-24 of a turn and its product: 2 pi 2^-24 + u),
// its sine and cosine (taken as 2u each), two complex products (gamma_2 sqrt 2 each) and
// the factors k/|k| (3u): 16u in all. The spectrum's 2-norm is the field's (Parseval), so
// each pair of real fields that shares a complex transform, a + i b, is held to
// ||a^ - a||, ||b^ - b|| <= (B_fft + eta_in) sqrt(||a||^2 + ||b||^2).
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "core/ocean_fft_reference.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/ocean_gpu_cascade.h"
#include "runtime/ocean_simulation.h"
#include "ocean_transform_bound.h"

namespace wg::rt {
namespace {

constexpr double u = ocean_test::kUnitRoundoff;
using ocean_test::norm;

// Channel c of a read-back map, as doubles.
std::vector<double> channel(const std::vector<float>& map, int c) {
  std::vector<double> out(map.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = map[i * 4 + static_cast<size_t>(c)];
  return out;
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

std::vector<double> scaled(const std::vector<double>& v, double s) {
  std::vector<double> out(v);
  for (double& x : out) x *= s;
  return out;
}

class OceanGpu : public ::testing::TestWithParam<GlApi> {};

TEST_P(OceanGpu, FieldsMatchTheDoubleReferenceWithinTheTransformsBound) {
  auto ctx = EglContext::create(GetParam());
  const SceneShaderApi api = GetParam() == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
  ocean::SpectrumSettings s;  // JONSWAP, U10 = 10 m/s, 100 km
  for (int resolution : {64, 256}) {
    ocean::CascadeSettings c;
    c.resolution = resolution;
    c.tileLengths = {250};
    c.seed = 3;
    ocean::OceanCascade cascade = ocean::initialCascade(s, c, 0);
    OceanGpuCascade gpu(cascade, api);
    const double lambda = 0.8, bound = ocean_test::transformBound(resolution);
    for (double t : {0.0, 3.7, 1e6}) {
      SCOPED_TRACE("N = " + std::to_string(resolution) + ", t = " + std::to_string(t));
      gpu.update(t, lambda);
      std::vector<float> displacement = gpu.readDisplacement(), slopes = gpu.readSlopes();
      for (float v : displacement) ASSERT_TRUE(std::isfinite(v));
      for (float v : slopes) ASSERT_TRUE(std::isfinite(v));
      ocean::OceanFields f = ocean::oceanFields(cascade, t, lambda);
      // The four complex transforms' norms.
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
          {"h", channel(displacement, 1), f.height, bound * z1},
          // lambda D: the pack pass's product rounds once more.
          {"lambda Dx", channel(displacement, 0), scaled(f.displacementX, lambda),
           lambda * bound * z1 + u * lambda * norm(f.displacementX)},
          {"lambda Dz", channel(displacement, 2), scaled(f.displacementZ, lambda),
           lambda * bound * z2 + u * lambda * norm(f.displacementZ)},
          {"dh/dx", channel(slopes, 0), f.slopeX, bound * z2},
          {"dh/dz", channel(slopes, 1), f.slopeZ, bound * z3},
          // lambda times the derivatives of D: one more rounding, as lambda D.
          {"l dDx/dx", channel(slopes, 2), scaled(f.dDxdx, lambda), lambda * bound * z3 + u * lambda * norm(f.dDxdx)},
          {"l dDz/dz", channel(slopes, 3), scaled(f.dDzdz, lambda), lambda * bound * z4 + u * lambda * norm(f.dDzdz)},
          {"l dDx/dz", channel(displacement, 3), scaled(f.dDxdz, lambda), lambda * bound * z4 + u * lambda * norm(f.dDxdz)},
      };
      for (const Check& check : checks) {
        double error = distance(check.got, check.want);
        std::printf("  %-9s ||error|| %.3e, bound %.3e (%.0f%%)\n", check.name, error, check.allowed,
                    100 * error / check.allowed);
        EXPECT_LE(error, check.allowed) << check.name;
      }
    }
  }
}

// Nothing reads the slopes: the first texture's two transforms alone, the same
// displacement within the same bound, w = 0, no slope map.
TEST_P(OceanGpu, ADisplacementOnlyCascadeComputesTheDisplacementAlone) {
  auto ctx = EglContext::create(GetParam());
  const SceneShaderApi api = GetParam() == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
  ocean::SpectrumSettings s;
  ocean::CascadeSettings c;
  c.resolution = 64;
  c.tileLengths = {250};
  ocean::OceanCascade cascade = ocean::initialCascade(s, c, 0);
  OceanGpuCascade gpu(cascade, api, /*slopes=*/false);
  EXPECT_FALSE(gpu.computesSlopes());
  EXPECT_EQ(gpu.slopeMap(), 0u);
  EXPECT_THROW(gpu.readSlopes(), std::logic_error);
  const double lambda = 0.8, t = 3.7, bound = ocean_test::transformBound(64);
  gpu.update(t, lambda);
  std::vector<float> displacement = gpu.readDisplacement();
  ocean::OceanFields f = ocean::oceanFields(cascade, t, lambda);
  double z1 = std::hypot(norm(f.height), norm(f.displacementX));
  double z2 = std::hypot(norm(f.displacementZ), norm(f.slopeX));
  EXPECT_LE(distance(channel(displacement, 1), f.height), bound * z1);
  EXPECT_LE(distance(channel(displacement, 0), scaled(f.displacementX, lambda)),
            lambda * bound * z1 + u * lambda * norm(f.displacementX));
  EXPECT_LE(distance(channel(displacement, 2), scaled(f.displacementZ, lambda)),
            lambda * bound * z2 + u * lambda * norm(f.displacementZ));
  for (double w : channel(displacement, 3)) ASSERT_EQ(w, 0.0);
}

// The runtime computes the slope fields of a cascade only where a shader samples its slope
// map: a graph that reads only the displaced position runs half the transforms.
TEST_P(OceanGpu, TheSimulationComputesOnlyTheMapsTheShadersRead) {
  auto ctx = EglContext::create(GetParam());
  const SceneShaderApi api = GetParam() == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
  auto compile = [](const std::string& position, const std::string& color) {
    Diagnostics diags;
    auto graph = parseGraph(R"({"version": 1, "name": "sea_test", "nodes": [
        {"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [100, 10]}},
        {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}}],
        "outputs": {"vertex": {"position": ")" + position + R"("}, "fragment": {"color": ")" + color + R"("}}})",
                            "sea.json", diags);
    CompileOptions o;
    o.targets = {Target::Glsl330};
    auto result = graph ? compileGraph(*graph, defaultRegistry(), o, diags) : std::nullopt;
    if (!result) throw std::runtime_error("the test graph does not compile");
    return result->manifest;
  };
  Manifest positionOnly = compile("moved.position", "moved.position");
  OceanSimulation displacement(positionOnly.oceans, positionOnly.textures, api);
  for (int c : {0, 1}) EXPECT_FALSE(displacement.computesSlopes(0, c)) << "cascade " << c;
  Manifest withNormal = compile("moved.position", "moved.normal");
  OceanSimulation both(withNormal.oceans, withNormal.textures, api);
  for (int c : {0, 1}) EXPECT_TRUE(both.computesSlopes(0, c)) << "cascade " << c;
  displacement.update(1.0);  // runs
  // What `render --stats` reports: per 64^2 cascade h0 and frequencies (20 B a texel), ping
  // and pong spectra and the maps (16 B a texel each; two of each with slopes, one
  // without) and 32 twiddles: 475,392 B with slopes, 278,784 B without.
  EXPECT_EQ(OceanSimulation::textureBytes(withNormal.oceans, withNormal.textures), 2u * 475392u);
  EXPECT_EQ(OceanSimulation::textureBytes(positionOnly.oceans, positionOnly.textures), 2u * 278784u);
}

// A resolution per cascade (cascade_sizes): open_ocean's tiles on grids of 16^2, 32^2 and
// 64^2, each cascade transformed on its own grid and held to FFTW on that grid within the
// bound for its own N; the simulation a manifest describes makes each cascade's textures at
// its own size.
TEST_P(OceanGpu, EachCascadeOnItsOwnGridMatchesTheReference) {
  auto ctx = EglContext::create(GetParam());
  const SceneShaderApi api = GetParam() == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
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
    ASSERT_EQ(cascade.resolution, n);
    OceanGpuCascade gpu(cascade, api);
    gpu.update(t, lambda);
    const std::vector<float> displacement = gpu.readDisplacement(), slopes = gpu.readSlopes();
    ASSERT_EQ(displacement.size(), static_cast<size_t>(n) * n * 4);
    const ocean::OceanFields f = ocean::oceanFields(cascade, t, lambda);
    const double bound = ocean_test::transformBound(n);
    const double z1 = std::hypot(norm(f.height), norm(f.displacementX));
    const double z2 = std::hypot(norm(f.displacementZ), norm(f.slopeX));
    const double z3 = std::hypot(norm(f.slopeZ), norm(f.dDxdx));
    ASSERT_GT(norm(f.height), 0) << "a cascade with waves";
    const double h = distance(channel(displacement, 1), f.height), hx = distance(channel(slopes, 0), f.slopeX),
                 hz = distance(channel(slopes, 1), f.slopeZ);
    std::printf("  N = %d: h %.0f%%, dh/dx %.0f%%, dh/dz %.0f%% of the bound\n", n, 100 * h / (bound * z1),
                100 * hx / (bound * z2), 100 * hz / (bound * z3));
    EXPECT_LE(h, bound * z1);
    EXPECT_LE(hx, bound * z2);
    EXPECT_LE(hz, bound * z3);
  }
  Diagnostics diags;
  auto graph = parseGraph(R"({"version": 1, "name": "sizes_test", "nodes": [
      {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [120, 24, 5], "cascade_sizes": [16, 32, 64]}},
      {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}}],
      "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": "moved.normal"}}})",
                          "sizes.json", diags);
  CompileOptions o;
  o.targets = {Target::Glsl330};
  auto compiled = graph ? compileGraph(*graph, defaultRegistry(), o, diags) : std::nullopt;
  ASSERT_TRUE(compiled);
  EXPECT_EQ(OceanSimulation::textureBytes(compiled->manifest.oceans, compiled->manifest.textures),
            OceanGpuCascade::textureBytes(16, true) + OceanGpuCascade::textureBytes(32, true) +
                OceanGpuCascade::textureBytes(64, true));
}

INSTANTIATE_TEST_SUITE_P(Apis, OceanGpu, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return info.param == GlApi::Es32 ? std::string("es32") : std::string("gl45"); });

}  // namespace
}  // namespace wg::rt
