// ocean_spectrum's cascade_count (a tune knob): the first `count` tiles of tile_lengths are
// simulated, with their cascade_sizes, and the last one kept carries every wave its own grid
// holds. So fewer cascades keep the longer cascades' waves bit for bit and lose only the
// waves shorter than the last kept grid reaches; an error in a tile the count drops is still
// reported (tests/bad/WG030_ocean_cascade_count_*.json).
#include <complex>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/node_options.h"
#include "core/ocean_fft_reference.h"
#include "core/ocean_settings.h"
#include "nodes/registry.h"

namespace wg::nodes {
namespace {

ocean::OceanSettings parsedSea(const nlohmann::json& written) {
  const NodeSpec* spec = defaultRegistry().find("ocean_spectrum");
  EXPECT_TRUE(spec);
  return parseOptions(*spec, completeOptions(*spec, written))->as<ocean::OceanSettings>();
}

// The sea's mean square slope, sum of F(k) dk^2 k^2 over every cascade's bins: a k^-3 sea's
// slopes weigh each octave of wavenumbers alike, so it measures the short waves a count drops
// (the height's variance is the long waves', which the bands' discretisation moves more).
double seaSlopeVariance(const ocean::OceanSettings& s) {
  double sum = 0;
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c) {
    const ocean::OceanCascade cascade = ocean::initialCascade(s.spectrum, s.cascades, static_cast<int>(c));
    const int n = cascade.resolution;
    const double dk = 2 * ocean::kPi / cascade.tileLength;
    for (int iz = 0; iz < n; ++iz)
      for (int ix = 0; ix < n; ++ix) {
        const double k = dk * std::hypot(ocean::signedIndex(ix, n), ocean::signedIndex(iz, n));
        sum += cascade.binVariance[static_cast<size_t>(iz) * n + static_cast<size_t>(ix)] * k * k;
      }
  }
  return sum;
}

TEST(OceanCascadeCount, KeepsTheLongestTilesWithTheirSizes) {
  const nlohmann::json tiles = {120, 24, 5};
  ocean::OceanSettings two = parsedSea({{"tile_lengths", tiles}, {"cascade_sizes", {64, 64, 256}}, {"cascade_count", 2}});
  EXPECT_EQ(two.cascades.tileLengths, (std::vector<double>{120, 24}));
  EXPECT_EQ(two.cascades.sizes, (std::vector<int>{64, 64}));
  EXPECT_FALSE(ocean::validateOcean(two));
  ocean::OceanSettings one = parsedSea({{"tile_lengths", tiles}, {"cascade_count", 1}});
  EXPECT_EQ(one.cascades.tileLengths, (std::vector<double>{120}));
  EXPECT_TRUE(one.cascades.sizes.empty());
  // More than listed (the default, 4): every tile.
  EXPECT_EQ(parsedSea({{"tile_lengths", tiles}}).cascades.tileLengths, (std::vector<double>{120, 24, 5}));
  // Lists that mean nothing as written are not cut, so their error is reported.
  ocean::OceanSettings misordered = parsedSea({{"tile_lengths", {120, 24, 30}}, {"cascade_count", 2}});
  EXPECT_EQ(misordered.cascades.tileLengths.size(), 3u);
  ASSERT_TRUE(ocean::validateOcean(misordered));
  EXPECT_EQ(ocean::validateOcean(misordered)->parameter, "tile_lengths");
}

TEST(OceanCascadeCount, FewerCascadesKeepTheLongerWavesAndTheLastKeptHoldsItsWholeGrid) {
  const nlohmann::json tiles = {120, 24, 5};
  ocean::OceanSettings all = parsedSea({{"tile_lengths", tiles}, {"fft_size", 128}});
  ocean::OceanSettings two = parsedSea({{"tile_lengths", tiles}, {"fft_size", 128}, {"cascade_count", 2}});
  ASSERT_EQ(two.cascades.tileLengths.size(), 2u);
  const ocean::OceanCascade longAll = ocean::initialCascade(all.spectrum, all.cascades, 0);
  const ocean::OceanCascade longTwo = ocean::initialCascade(two.spectrum, two.cascades, 0);
  EXPECT_EQ(longAll.h0, longTwo.h0);  // the longest cascade is untouched, bit for bit
  const ocean::OceanCascade midAll = ocean::initialCascade(all.spectrum, all.cascades, 1);
  const ocean::OceanCascade midTwo = ocean::initialCascade(two.spectrum, two.cascades, 1);
  const double bandEdge = ocean::cascadeBands(all.cascades)[1].high;  // where the 5 m tile took over
  ASSERT_TRUE(std::isfinite(bandEdge));
  EXPECT_TRUE(std::isinf(ocean::cascadeBands(two.cascades)[1].high));
  const int n = 128;
  const double dk = 2 * ocean::kPi / 24.0;
  int gained = 0;
  for (int iz = 0; iz < n; ++iz)
    for (int ix = 0; ix < n; ++ix) {
      const size_t i = static_cast<size_t>(iz) * n + static_cast<size_t>(ix);
      const double k = dk * std::hypot(ocean::signedIndex(ix, n), ocean::signedIndex(iz, n));
      if (midAll.h0[i] != std::complex<double>(0.0)) {
        ASSERT_EQ(midAll.h0[i], midTwo.h0[i]) << "bin " << ix << ", " << iz;  // the same draws
      } else if (midTwo.h0[i] != std::complex<double>(0.0)) {
        EXPECT_GE(k, bandEdge) << "a wave below the band edge the finer cascade held";
        ++gained;
      }
    }
  // The middle cascade now reaches its grid's corners: thousands of bins past the edge.
  EXPECT_GT(gained, 1000);
  // And the sea loses only short waves: the slopes' variance grows with each cascade kept, by
  // about the log of the wavenumber its grid reaches past the previous one's (each octave
  // alike): 4.7, 23.7 and 114 rad/m at the three grids' corners.
  ocean::OceanSettings one = parsedSea({{"tile_lengths", tiles}, {"fft_size", 128}, {"cascade_count", 1}});
  const double s1 = seaSlopeVariance(one), s2 = seaSlopeVariance(two), s3 = seaSlopeVariance(all);
  std::printf("mean square slope: 1 cascade %.5f, 2: %.5f, 3: %.5f\n", s1, s2, s3);
  EXPECT_LT(s1, s2);
  EXPECT_LT(s2, s3);
  // Each octave alike: the gains stand as the logs of the grids' reach (2 pi 64 / L).
  const double reach1 = 64.0 / 120, reach2 = 64.0 / 24, reach3 = 64.0 / 5;
  EXPECT_NEAR((s2 - s1) / (s3 - s2), std::log(reach2 / reach1) / std::log(reach3 / reach2), 0.05);
}

}  // namespace
}  // namespace wg::nodes
