// A resolution per cascade (CascadeSettings::sizes, the ocean_spectrum option cascade_sizes)
// against the double reference: what a smaller grid drops of each cascade's band, measured
// from the spectrum alone (bandEnergyHeld); the waves a smaller grid keeps are the very
// waves of the larger one (same draws, same frequencies); Parseval over cascades of their
// own sizes; the settings' checks and the foam's budget counting each cascade's own grid.
// The sea is graphs/open_ocean.json's: JONSWAP, U10 = 7 m/s, 50 km fetch, tiles 120, 24, 5 m.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "core/ocean_fft_reference.h"
#include "core/ocean_settings.h"
#include "ocean_test_support.h"

namespace wg::ocean {
namespace {

using namespace test_support;

SpectrumSettings openOceanSea() {
  SpectrumSettings s;
  s.windSpeed = 7;
  s.fetch = 50e3;
  s.windDirection = 20 * kPi / 180;
  return s;
}

CascadeSettings openOceanCascades(std::vector<int> sizes = {}) {
  CascadeSettings c;
  c.resolution = 256;
  c.tileLengths = {120, 24, 5};
  c.sizes = std::move(sizes);
  return c;
}

// The largest |signed index| along either axis of a bin that holds a wave.
int widestBin(const OceanCascade& c) {
  int widest = 0;
  for (int iz = 0; iz < c.resolution; ++iz)
    for (int ix = 0; ix < c.resolution; ++ix)
      if (c.h0[static_cast<size_t>(iz) * c.resolution + ix] != std::complex<double>(0, 0))
        widest = std::max({widest, std::abs(signedIndex(ix, c.resolution)), std::abs(signedIndex(iz, c.resolution))});
  return widest;
}

TEST(OceanCascadeSizes, TheLongTilesBandsEndWithinTwelveBinsSoSixtyFourHoldsThem) {
  // Each band ends at the geometric mean of its tile's 31st bin and the next tile's first
  // (cascadeBands): sqrt(31 L_i / L_(i+1)) bins, 12.4 for 120 / 24 m and 12.2 for 24 / 5 m.
  // A grid holds |index| up to N/2 - 1: 15 at 32^2, so 32^2 and 64^2 lose nothing there;
  // 16^2 (up to 7) drops the band's outer ring; the finest cascade's band runs to its grid's
  // edge, so any smaller grid drops its shortest waves.
  const SpectrumSettings s = openOceanSea();
  for (int c : {0, 1}) {
    EXPECT_LE(widestBin(initialCascade(s, openOceanCascades(), c)), 12) << "cascade " << c;
    for (int n : {32, 64, 128})
      EXPECT_EQ(bandEnergyHeld(s, openOceanCascades({n, n, 256}), c), 1.0) << "cascade " << c << " at " << n;
    const double held16 = bandEnergyHeld(s, openOceanCascades({16, 16, 256}), c);
    std::printf("cascade %d (%g m): 16^2 holds %.4f of its band's variance\n", c, openOceanCascades().tileLengths[c],
                held16);
    EXPECT_LT(held16, 1.0) << "cascade " << c;
    EXPECT_GT(held16, 0.5) << "cascade " << c;
  }
  const double finest = bandEnergyHeld(s, openOceanCascades({64, 64, 128}), 2);
  std::printf("cascade 2 (5 m): 128^2 holds %.6f of what 512^2 holds\n", finest);
  EXPECT_LT(finest, 1.0);
}

TEST(OceanCascadeSizes, ASmallerGridDrawsTheSameWavesAsTheLargerOne) {
  // Each bin's amplitude is drawn by its signed wavenumber index, so cascade c at 64^2 holds
  // bit for bit the waves it holds at 256^2, with the same frequencies.
  const SpectrumSettings s = openOceanSea();
  for (int c : {0, 1}) {
    const OceanCascade large = initialCascade(s, openOceanCascades(), c);
    const OceanCascade small = initialCascade(s, openOceanCascades({64, 32, 256}), c);
    const int n = c == 0 ? 64 : 32;
    ASSERT_EQ(small.resolution, n);
    ASSERT_EQ(small.h0.size(), static_cast<size_t>(n) * n);
    int waves = 0;
    for (int iz = 0; iz < 256; ++iz)
      for (int ix = 0; ix < 256; ++ix) {
        const size_t i = static_cast<size_t>(iz) * 256 + ix;
        if (large.h0[i] == std::complex<double>(0, 0)) continue;
        ++waves;
        const int jx = (signedIndex(ix, 256) + n) % n, jz = (signedIndex(iz, 256) + n) % n;
        const size_t j = static_cast<size_t>(jz) * n + jx;
        ASSERT_EQ(small.h0[j], large.h0[i]) << "cascade " << c << " bin " << ix << ", " << iz;
        ASSERT_EQ(small.frequency[j], large.frequency[i]);
      }
    int smallWaves = 0;
    for (const auto& a : small.h0) smallWaves += a != std::complex<double>(0, 0);
    EXPECT_EQ(smallWaves, waves) << "cascade " << c;
    EXPECT_GT(waves, 300) << "cascade " << c;
  }
}

// The integral of E(k) over [a, b] on a logarithmic grid (no FFT, no grid).
double bandIntegral(const SpectrumSettings& s, double a, double b) {
  return simpson([&](double u) { return omnidirectionalSpectrum(s, std::exp(u)) * std::exp(u); }, std::log(a),
                 std::log(b), 40000);
}

double surfaceMeanSquare(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x * x;
  return sum / static_cast<double>(v.size());
}

TEST(OceanCascadeSizes, ParsevalHoldsOverCascadesOfTheirOwnSizes) {
  // open_ocean with its long cascades at 64^2: the surfaces' mean square, summed over the
  // three independent cascades and averaged over seas, is the spectrum's integral m0 within
  // 3 % (the Parseval bar), and the discretised spectrum is the one at 256^2 to the
  // last bits: the smaller grids hold every wave.
  const SpectrumSettings s = openOceanSea();
  CascadeSettings c = openOceanCascades({64, 64, 256});
  const double m0 = bandIntegral(s, 1e-4, 1e3);
  // What the three grids cannot hold: below the 120 m tile's first bin and beyond the 5 m
  // tile's largest whole circle.
  const double lost = bandIntegral(s, 1e-4, 2 * kPi / 120) + bandIntegral(s, 127 * 2 * kPi / 5, 1e3);
  double discretised = 0, full = 0, spreadSquared = 0;
  const int seas[3] = {256, 256, 8};  // the long tiles' few peak waves vary most; they cost little at 64^2
  for (int i = 0; i < 3; ++i) {
    const OceanCascade cascade = initialCascade(s, c, i);
    const int n = cascade.resolution;
    double sumP = 0, sumP2 = 0;
    for (int iz = 0; iz < n; ++iz)
      for (int ix = 0; ix < n; ++ix) {
        const size_t b = static_cast<size_t>(iz) * n + ix, mirror = static_cast<size_t>((n - iz) % n) * n + (n - ix) % n;
        const double p = 0.5 * (cascade.binVariance[b] + cascade.binVariance[mirror]);
        sumP += p;
        sumP2 += p * p;
      }
    discretised += sumP;
    // One sea's mean square has variance 2 sum P^2 (ocean_fft_reference_test.cpp derives it).
    spreadSquared += 2 * sumP2 / seas[i];
    for (double v : initialCascade(s, openOceanCascades(), i).binVariance) full += v;
  }
  EXPECT_NEAR(discretised, full, 1e-12 * full);
  const double spread = std::sqrt(spreadSquared) / m0;
  ASSERT_LT(lost / m0 + 3 * spread, 0.03) << lost / m0 << " " << spread;
  double surface = 0;
  for (int i = 0; i < 3; ++i)
    for (int seed = 0; seed < seas[i]; ++seed) {
      c.seed = seed;
      surface += surfaceMeanSquare(oceanHeight(initialCascade(s, c, i), 2.5)) / seas[i];
    }
  std::printf("m0 %.6f m^2, surfaces at 64, 64, 256 %.6f (%+.2f %%), loss <= %.2f %%, 1 sigma %.2f %%\n", m0, surface,
              100 * (surface / m0 - 1), 100 * lost / m0, 100 * spread);
  EXPECT_NEAR(surface, m0, 0.03 * m0);
}

TEST(OceanCascadeSizes, MeaninglessSizesAreErrorsAtCascadeSizes) {
  auto problem = [](std::vector<int> sizes) {
    auto e = validateCascades(openOceanCascades(std::move(sizes)));
    return e ? e->parameter + ": " + e->message : std::string();
  };
  EXPECT_EQ(problem({}), "");
  EXPECT_EQ(problem({16, 64, 512}), "");
  EXPECT_EQ(problem({64, 256}),
            "cascade_sizes: lists 2 sizes for 3 cascades (tile_lengths): one a cascade, or none for fft_size everywhere");
  EXPECT_EQ(problem({64, 64, 256, 256}),
            "cascade_sizes: lists 4 sizes for 3 cascades (tile_lengths): one a cascade, or none for fft_size everywhere");
  EXPECT_EQ(problem({64, 100, 256}), "cascade_sizes: cascade 1: 100 is not a power of two in [16, 512]");
  EXPECT_EQ(problem({8, 64, 256}), "cascade_sizes: cascade 0: 8 is not a power of two in [16, 512]");
  EXPECT_EQ(problem({64, 64, 1024}), "cascade_sizes: cascade 2: 1024 is not a power of two in [16, 512]");
  EXPECT_EQ(problem({0, 64, 256}), "cascade_sizes: cascade 0: 0 is not a power of two in [16, 512]");
  EXPECT_EQ(problem({-64, 64, 256}), "cascade_sizes: cascade 0: -64 is not a power of two in [16, 512]");
}

TEST(OceanCascadeSizes, EachCascadeIsBuiltAndItsFoamBudgetedOnItsOwnGrid) {
  OceanSettings o;
  o.spectrum = openOceanSea();
  o.cascades = openOceanCascades({32, 64, 512});
  o.cascades.resolution = 512;
  o.foam.cascades = 2;
  const int expected[3] = {32, 64, 512};
  for (int c = 0; c < 3; ++c) EXPECT_EQ(cascadeResolution(o.cascades, static_cast<size_t>(c)), expected[c]);
  // Two foam cascades: 32^2 + 64^2 texels a step, not 2 x 256^2 (fft_size).
  EXPECT_EQ(foamReplayTexelSteps(o), (historySteps(o.foam) + 1.0) * (32 * 32 + 64 * 64));
  // Sizes are part of the sea's identity (the reference's cache, the runtime's simulations).
  OceanSettings same = o;
  same.cascades.sizes = {32, 64, 256};
  EXPECT_NE(settingsKey(o), settingsKey(same));
  same.cascades.sizes = {};
  EXPECT_NE(settingsKey(o), settingsKey(same));
  // Without sizes every cascade is at fft_size; with them, fft_size caps each.
  EXPECT_EQ(cascadeResolution(same.cascades, 2), 512);
  same.cascades.sizes = {32, 64, 512};
  same.cascades.resolution = 128;
  EXPECT_EQ(cascadeResolution(same.cascades, 0), 32);
  EXPECT_EQ(cascadeResolution(same.cascades, 2), 128);
}

}  // namespace
}  // namespace wg::ocean
