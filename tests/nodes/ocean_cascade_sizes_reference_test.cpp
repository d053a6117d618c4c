// The ocean readers' double reference with a resolution per cascade (cascade_sizes): each
// cascade's map is looked up with its own N (texels per metre N_c / L_c, the wrap at N_c),
// as wg_ocean_map reads it on the GPU. The bilinear blend of the cascade's own FFTW fields
// is written out here; a cascade read with another cascade's N (or fft_size) lands on
// other texels and fails.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/ocean_fft_reference.h"
#include "core/ocean_settings.h"
#include "nodes/ocean_reference.h"

namespace wg::nodes {
namespace {

// Field `f` (an N x N grid of tile L, row z) at the world point (x, z), bilinear and
// wrapped, in double throughout.
double bilinearField(const std::vector<double>& f, int n, double tile, double x, double z) {
  const double u = x * n / tile, v = z * n / tile;
  const double bu = std::floor(u), bv = std::floor(v);
  auto wrap = [n](double b) { return static_cast<int>(b - n * std::floor(b / n)); };
  const int x0 = wrap(bu), z0 = wrap(bv), x1 = (x0 + 1) % n, z1 = (z0 + 1) % n;
  auto at = [&](int jx, int jz) { return f[static_cast<size_t>(jz) * n + jx]; };
  const double fu = u - bu, fv = v - bv;
  const double bottom = at(x0, z0) + (at(x1, z0) - at(x0, z0)) * fu;
  const double top = at(x0, z1) + (at(x1, z1) - at(x0, z1)) * fu;
  return bottom + (top - bottom) * fv;
}

TEST(OceanCascadeSizesReference, EachCascadeIsReadWithItsOwnTexelScale) {
  ocean::OceanSettings s;
  s.cascades.resolution = 256;  // fft_size: no cascade uses it here
  s.cascades.tileLengths = {50, 8};
  s.cascades.sizes = {16, 64};
  s.cascades.choppiness = 1;
  const int id = oceanref::registerOcean(s);
  const double t = 1.5;
  for (int c = 0; c < 2; ++c) {
    const int n = s.cascades.sizes[static_cast<size_t>(c)];
    const double tile = s.cascades.tileLengths[static_cast<size_t>(c)];
    const ocean::OceanFields f = ocean::oceanFields(ocean::initialCascade(s.spectrum, s.cascades, c), t, 1.0);
    ASSERT_EQ(f.height.size(), static_cast<size_t>(n) * n);
    double scale = 0, slopeScale = 0;
    for (double h : f.height) scale = std::max(scale, std::abs(h));
    for (double hx : f.slopeX) slopeScale = std::max(slopeScale, std::abs(hx));
    ASSERT_GT(scale, 0);
    // Points between texels, one beyond the tile (the wrap at N_c) and one at negative x.
    for (auto [x, z] : {std::pair{3.3, 7.9}, std::pair{tile + 1.1, 0.4}, std::pair{-2.6, 5.05}}) {
      const oceanref::MapSample m = oceanref::sampleCascade(id, c, t, x, z);
      // The reference rounds N_c / L_c to float as the shader's literal: the texel
      // coordinate (under 80 here) moves by at most 2^-24 of it, 5e-6 texel, and the blend
      // by at most twice that of the field's largest value. Another N moves whole texels.
      EXPECT_NEAR(m.displacement[1], bilinearField(f.height, n, tile, x, z), 1e-5 * scale)
          << "cascade " << c << " at (" << x << ", " << z << ")";
      EXPECT_NEAR(m.slopes[0], bilinearField(f.slopeX, n, tile, x, z), 1e-5 * slopeScale)
          << "cascade " << c << " at (" << x << ", " << z << ")";
    }
  }
}

}  // namespace
}  // namespace wg::nodes
