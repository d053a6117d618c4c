// The ocean readers' double reference with a resolution per cascade (cascade_sizes): each
// cascade's map is looked up with its own N (texels per metre N_c / L_c, the wrap at N_c),
// as wg_ocean_map (the fragment stage) and wg_ocean_map_cubic (the vertex stage) read it on
// the GPU. The bilinear and bicubic (Catmull-Rom) blends of the cascade's own FFTW fields are
// written out here; a cascade read with another cascade's N (or
// fft_size) lands on other texels and fails. And what the vertex stage's bicubic read is
// for: a long cascade on a coarser grid of the same waves reads as on the fine one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/ocean_fft_reference.h"
#include "core/ocean_settings.h"
#include "nodes/ocean_reference.h"

namespace wg::nodes {
namespace {

// Field `f` (an N x N grid of tile L, row z) at the world point (x, z), wrapped, in double
// throughout: bilinear between the 2 x 2 texels around it, or Catmull-Rom's cubic (the cubic
// through the middle two texels of 4 with central differences as its slopes) over 4 x 4.
double fieldAt(const std::vector<double>& f, int n, double tile, double x, double z, bool cubic) {
  const double u = x * n / tile, v = z * n / tile;
  const double bu = std::floor(u), bv = std::floor(v);
  auto wrap = [n](double b) { return static_cast<int>(b - n * std::floor(b / n)) % n; };
  const int x0 = wrap(bu), z0 = wrap(bv);
  auto at = [&](int jx, int jz) { return f[static_cast<size_t>((jz + n) % n) * n + static_cast<size_t>((jx + n) % n)]; };
  auto weights = [cubic](double t) -> std::vector<double> {
    if (!cubic) return {1 - t, t};
    // From the cubic Hermite basis with p(0) = p1, p(1) = p2, p'(0) = (p2 - p0) / 2 and
    // p'(1) = (p3 - p1) / 2 (written apart from the reference's expanded weights).
    const double h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t;
    const double h01 = -2 * t * t * t + 3 * t * t, h11 = t * t * t - t * t;
    return {-0.5 * h10, h00 - 0.5 * h11, h01 + 0.5 * h10, 0.5 * h11};
  };
  const std::vector<double> wx = weights(u - bu), wz = weights(v - bv);
  const int first = cubic ? -1 : 0;
  double sum = 0;
  for (size_t j = 0; j < wz.size(); ++j)
    for (size_t i = 0; i < wx.size(); ++i)
      sum += wz[j] * wx[i] * at(x0 + first + static_cast<int>(i), z0 + first + static_cast<int>(j));
  return sum;
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
    for (auto [x, z] : {std::pair{3.3, 7.9}, std::pair{tile + 1.1, 0.4}, std::pair{-2.6, 5.05}})
      for (bool cubic : {false, true}) {
        const oceanref::MapSample m = oceanref::sampleCascade(id, c, t, x, z, cubic);
        // The reference rounds N_c / L_c to float as the shader's literal: the texel
        // coordinate (under 80 here) moves by at most 2^-24 of it, 5e-6 texel, and the read
        // (its slope in the coordinate at most 1.5 steps between texels, each at most twice the
        // field's largest value) by at most 1.5e-5 of that value. Another N moves whole texels.
        EXPECT_NEAR(m.displacement[1], fieldAt(f.height, n, tile, x, z, cubic), 2e-5 * scale)
            << "cascade " << c << " at (" << x << ", " << z << "), bicubic " << cubic;
        EXPECT_NEAR(m.slopes[0], fieldAt(f.slopeX, n, tile, x, z, cubic), 2e-5 * slopeScale)
            << "cascade " << c << " at (" << x << ", " << z << "), bicubic " << cubic;
      }
  }
}

// open_ocean's sea (JONSWAP, 7 m/s, 50 km of fetch; tiles 120, 24 and 5 m) with the long
// cascades at 128^2 against every cascade at 256^2. The long tiles' bands end near their
// 12.4th bin (docs/ocean.md, "Cascades"), so both grids hold the same waves; only the read
// between texels differs. At 128^2 the shortest of them spans 10.3 texels (w h = 0.61): a
// bilinear read misses a sinusoid by up to (w h)^2 / 8 = 4.6 % of its amplitude, Catmull-Rom
// by 3 (w h / 2)^4 / 8 = 0.3 % (and at 256^2 both by a sixteenth and a quarter as much). Over
// 2,000 points of the 120 m tile the two grids' height and slope reads differ, rms, by under
// a fifth of what the bilinear reads differ by (the spectrum weights the band's edge less
// than its worst case: measured 0.08-0.1), and by under 0.2 % of the field's rms.
TEST(OceanCascadeSizesReference, ALongCascadeOnACoarserGridReadsAsOnTheFineOne) {
  auto sea = [](std::vector<int> sizes) {
    ocean::OceanSettings s;
    s.spectrum.windSpeed = 7;
    s.spectrum.fetch = 50e3;
    s.spectrum.windDirection = 20 * ocean::kPi / 180;
    s.cascades.resolution = 256;
    s.cascades.tileLengths = {120, 24, 5};
    s.cascades.sizes = std::move(sizes);
    s.cascades.choppiness = 1;
    return s;
  };
  const ocean::OceanSettings coarse = sea({128, 128, 256}), fine = sea({});
  const int coarseId = oceanref::registerOcean(coarse), fineId = oceanref::registerOcean(fine);
  const double t = 20;
  for (int c = 0; c < 2; ++c) {
    const double tile = coarse.cascades.tileLengths[static_cast<size_t>(c)];
    const ocean::OceanFields fc = ocean::oceanFields(ocean::initialCascade(coarse.spectrum, coarse.cascades, c), t, 1.0);
    const ocean::OceanFields ff = ocean::oceanFields(ocean::initialCascade(fine.spectrum, fine.cascades, c), t, 1.0);
    double cubicH = 0, bilinearH = 0, cubicS = 0, bilinearS = 0, fieldH = 0, fieldS = 0;
    const int points = 2000;
    for (int p = 0; p < points; ++p) {
      // A low-discrepancy spread over the tile, off the texels of both grids.
      const double x = tile * std::fmod(0.5 + p * 0.6180339887498949, 1.0), z = tile * std::fmod(0.25 + p * 0.7548776662466927, 1.0);
      const oceanref::MapSample a = oceanref::sampleCascade(coarseId, c, t, x, z, true),
                                b = oceanref::sampleCascade(fineId, c, t, x, z, true);
      cubicH += std::pow(a.displacement[1] - b.displacement[1], 2);
      cubicS += std::pow(a.slopes[0] - b.slopes[0], 2) + std::pow(a.slopes[1] - b.slopes[1], 2);
      bilinearH += std::pow(fieldAt(fc.height, 128, tile, x, z, false) - fieldAt(ff.height, 256, tile, x, z, false), 2);
      bilinearS += std::pow(fieldAt(fc.slopeX, 128, tile, x, z, false) - fieldAt(ff.slopeX, 256, tile, x, z, false), 2) +
                   std::pow(fieldAt(fc.slopeZ, 128, tile, x, z, false) - fieldAt(ff.slopeZ, 256, tile, x, z, false), 2);
      fieldH += b.displacement[1] * b.displacement[1];
      fieldS += b.slopes[0] * b.slopes[0] + b.slopes[1] * b.slopes[1];
    }
    std::printf("  cascade %d: rms difference 128^2 against 256^2, height: bicubic %.3g, bilinear %.3g (field %.3g); "
                "slopes: bicubic %.3g, bilinear %.3g (field %.3g)\n",
                c, std::sqrt(cubicH / points), std::sqrt(bilinearH / points), std::sqrt(fieldH / points),
                std::sqrt(cubicS / points), std::sqrt(bilinearS / points), std::sqrt(fieldS / points));
    ASSERT_GT(bilinearS, 0);
    EXPECT_LT(cubicH, 0.2 * 0.2 * bilinearH) << "cascade " << c;
    EXPECT_LT(cubicS, 0.2 * 0.2 * bilinearS) << "cascade " << c;
    EXPECT_LT(cubicH, 0.002 * 0.002 * fieldH) << "cascade " << c;
    EXPECT_LT(cubicS, 0.002 * 0.002 * fieldS) << "cascade " << c;
  }
}

}  // namespace
}  // namespace wg::nodes
