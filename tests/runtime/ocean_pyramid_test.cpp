// The filtered ocean's pyramids (ocean_surface's `filter`): each cascade's slope and moments
// maps, level l the 2x2 box mean of level l - 1 (the runtime's own downsample pass, never
// the driver's mipmap filter), on desktop GL 4.5, ES 3.2 and Vulkan (lavapipe, under the
// validation layer):
// - every level against the exact box means of the GPU's own level 0 within float rounding
//   (ocean_pyramid_bound.h derives the bound);
// - the moments map's level 0 from the slope map's level 0 (one rounded product each) and
//   lambda dDx/dz equal to the displacement map's;
// - the slopes' pyramid against the double reference's (nodes/ocean_reference.cpp, which the
//   reader's eval reads) within the transform's bound, which a box mean can only shrink: the
//   mean of four errors is at most their root mean square, so ||box(e)||_2 <= ||e||_2 / 2.
// At t = 3.7 s and 1e6 s.
#include <bit>
#include <cmath>
#include <algorithm>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/ocean_fft_reference.h"
#include "core/ocean_settings.h"
#include "nodes/ocean_reference.h"
#include "runtime/egl_context.h"
#include "runtime/ocean_gpu_cascade.h"
#include "runtime/vk_ocean_cascade.h"
#include "ocean_pyramid_bound.h"
#include "ocean_transform_bound.h"

namespace wg::rt {
// Named, not anonymous: the unity build joins this file with the other ocean tests.
namespace ocean_pyramid_test {

constexpr int kN = 64;

ocean::OceanSettings pyramidSea() {
  ocean::OceanSettings s;  // JONSWAP, U10 = 10 m/s, 100 km
  s.cascades.resolution = kN;
  s.cascades.tileLengths = {40};
  s.cascades.choppiness = 0.8;
  s.cascades.seed = 3;
  return s;
}

std::vector<double> channelOf(const std::vector<float>& map, int c) {
  std::vector<double> out(map.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = map[i * 4 + static_cast<size_t>(c)];
  return out;
}

// Everything the file checks of one cascade's read-back pyramids at time t; `read(moments,
// level)` reads a level, `displacement` is the displacement map.
template <class Read>
void checkPyramids(Read read, const std::vector<float>& displacement, double t) {
  const ocean::OceanSettings sea = pyramidSea();
  const int levels = std::countr_zero(static_cast<unsigned>(kN)) + 1;
  std::vector<std::vector<float>> slopes, moments;
  for (int l = 0; l < levels; ++l) {
    slopes.push_back(read(false, l));
    moments.push_back(read(true, l));
    ASSERT_EQ(slopes.back().size(), static_cast<size_t>(kN >> l) * (kN >> l) * 4);
    for (float v : slopes.back()) ASSERT_TRUE(std::isfinite(v)) << "slopes level " << l;
    for (float v : moments.back()) ASSERT_TRUE(std::isfinite(v)) << "moments level " << l;
  }
  // Each level the box mean of the one above, within rounding.
  for (const auto* pyramid : {&slopes, &moments}) {
    ocean_test::PyramidCheck check = ocean_test::checkPyramid(*pyramid, kN);
    std::printf("  %s pyramid: worst error / bound %.3g\n", pyramid == &slopes ? "slopes" : "moments", check.worst);
    EXPECT_TRUE(check.failure.empty()) << (pyramid == &slopes ? "slopes " : "moments ") << check.failure;
  }
  // Level 0 of the moments from level 0 of the slopes, one rounding each; lambda dDx/dz as
  // the displacement map holds it.
  const double u = ocean_test::kUnitRoundoff, flush = std::ldexp(1.0, -126);
  for (size_t i = 0; i < slopes[0].size() / 4; ++i) {
    const double sx = slopes[0][i * 4], sz = slopes[0][i * 4 + 1];
    const double want[3] = {sx * sx, sz * sz, sx * sz};
    for (int c = 0; c < 3; ++c)
      ASSERT_LE(std::abs(moments[0][i * 4 + c] - want[c]), u * std::abs(want[c]) + flush) << "texel " << i << " moment " << c;
    ASSERT_EQ(moments[0][i * 4 + 3], displacement[i * 4 + 3]) << "texel " << i;
  }
  // The slopes' levels against the double reference's pyramid.
  const int id = nodes::oceanref::registerOcean(sea);
  ocean::OceanCascade cascade = ocean::initialCascade(sea.spectrum, sea.cascades, 0);
  ocean::OceanFields f = ocean::oceanFields(cascade, t, sea.cascades.choppiness);
  const double bound = ocean_test::transformBound(kN);
  // As ocean_gpu_cascade_test: dh/dx shares its transform with Dz, dh/dz with dDx/dx.
  const double level0[2] = {bound * std::hypot(ocean_test::norm(f.displacementZ), ocean_test::norm(f.slopeX)),
                            bound * std::hypot(ocean_test::norm(f.slopeZ), ocean_test::norm(f.dDxdx))};
  for (int l = 0; l < levels; ++l) {
    const auto& want = nodes::oceanref::pyramidLevel(id, 0, t, false, l);
    for (int c = 0; c < 2; ++c) {
      std::vector<double> got = channelOf(slopes[static_cast<size_t>(l)], c);
      double largest = 0;  // of level 0: each texel's block mean of magnitudes is at most this
      for (double v : channelOf(slopes[0], c)) largest = std::max(largest, std::abs(v));
      double error = 0;
      for (size_t i = 0; i < got.size(); ++i) error += (got[i] - want[i][c]) * (got[i] - want[i][c]);
      // The level-0 error halved per level, and level l's own rounding (ocean_pyramid_bound.h).
      const double gamma3 = 3 * u / (1 - 3 * u);
      const double rounding = std::sqrt(static_cast<double>(got.size())) * l * gamma3 * (1 + l * gamma3) * largest;
      const double allowed = level0[c] / std::ldexp(1.0, l) + rounding + l * flush;
      std::printf("  slopes level %d channel %d: ||error|| %.3e, bound %.3e\n", l, c, std::sqrt(error), allowed);
      EXPECT_LE(std::sqrt(error), allowed) << "slopes level " << l << " channel " << c;
    }
  }
}

class OceanPyramidGl : public ::testing::TestWithParam<GlApi> {};

TEST_P(OceanPyramidGl, EachLevelIsTheBoxMeanOfTheOneAboveAndMatchesTheReference) {
  auto ctx = EglContext::create(GetParam());
  const SceneShaderApi api = GetParam() == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
  const ocean::OceanSettings sea = pyramidSea();
  const ocean::OceanCascade cascade = ocean::initialCascade(sea.spectrum, sea.cascades, 0);
  OceanGpuCascade filtered(cascade, api, true, false, true), plain(cascade, api, true, false, false);
  ASSERT_TRUE(filtered.filtered());
  ASSERT_EQ(filtered.levels(), 7);
  ASSERT_NE(filtered.momentsMap(), 0u);
  EXPECT_EQ(plain.momentsMap(), 0u);
  EXPECT_THROW(plain.readLevel(true, 0), std::logic_error);
  for (double t : {3.7, 1e6}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    filtered.update(t, sea.cascades.choppiness);
    plain.update(t, sea.cascades.choppiness);
    // The filtered pack writes the same maps as the plain one, bit for bit.
    std::vector<float> a = filtered.readSlopes(), b = plain.readSlopes();
    ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
    checkPyramids([&](bool moments, int level) { return filtered.readLevel(moments, level); }, filtered.readDisplacement(), t);
  }
}

INSTANTIATE_TEST_SUITE_P(Apis, OceanPyramidGl, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return info.param == GlApi::Es32 ? std::string("es32") : std::string("gl45"); });

TEST(OceanPyramidVk, EachLevelIsTheBoxMeanOfTheOneAboveAndMatchesTheReference) {
  auto context = VkContext::create({.validation = true});
  VkOceanPasses passes(*context);
  const ocean::OceanSettings sea = pyramidSea();
  VkOceanCascade filtered(passes, ocean::initialCascade(sea.spectrum, sea.cascades, 0), true, false, true);
  ASSERT_TRUE(filtered.filtered());
  ASSERT_EQ(filtered.levels(), 7);
  for (double t : {3.7, 1e6}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    context->submit([&](VkCommandBuffer cmd) { filtered.record(cmd, t, sea.cascades.choppiness); });
    context->throwOnValidationMessages("the filtered ocean cascade");
    checkPyramids([&](bool moments, int level) { return filtered.readLevel(moments, level); }, filtered.readDisplacement(), t);
    context->throwOnValidationMessages("reading the pyramids back");
  }
}

}  // namespace ocean_pyramid_test
}  // namespace wg::rt
