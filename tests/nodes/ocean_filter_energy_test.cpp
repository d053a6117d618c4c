// ocean_surface's filter keeps the slopes' energy: over a region, the filtered normal's
// squared slope plus the variance it hands to the roughness averages to what point samples
// of the unfiltered maps average to over the same pixels' sub-pixel offsets. The region is
// one whole tile (8 m, 64^2 texels), its pixels the centres of level l's texels with the
// footprint of 2^l texels (levels of detail 0 to 6, and between levels), and each pixel's
// sub-pixel offsets the 2^l x 2^l level-0 texel centres it covers: the maps' own samples,
// which the unfiltered reader returns exactly. A box mean keeps a mean, and M - |S|^2 + |S|^2
// = M, so the two agree to double rounding: 1e-12 of the energy (about 4^6 additions of
// terms of one sign, each rounding 2^-53). Without the variance the filtered energy falls
// short by the slope variance within each footprint, which the test also measures.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/ocean_settings.h"
#include "nodes/ocean_readers.h"
#include "nodes/ocean_reference.h"

namespace wg::nodes {
// Named, not anonymous: the unity build joins this file with the other tests.
namespace ocean_filter_energy_test {

constexpr int kN = 64;
constexpr double kTile = 8;  // 8 texels per metre: the shader's float literal is exact

int oneCascadeSea() {
  ocean::OceanSettings s;
  s.spectrum.windSpeed = 12;
  s.cascades.resolution = kN;
  s.cascades.tileLengths = {kTile};
  s.cascades.choppiness = 1;
  return oceanref::registerOcean(s);
}

struct Energy {
  double filtered = 0, meanSquaredOnly = 0, supersampled = 0;
};

// The region's energies at level l, the pixels on the level's texel centres, with the fade
// weight `weight`.
Energy energyAt(int id, int level, double weight, double t) {
  const int size = kN >> level, block = 1 << level;
  const double texel = kTile / kN;
  Energy e;
  for (int jz = 0; jz < size; ++jz)
    for (int jx = 0; jx < size; ++jx) {
      // Level l's texel (jx, jz) sits at level-0 coordinate j 2^l + (2^l - 1) / 2.
      const double cx = jx * block + 0.5 * (block - 1), cz = jz * block + 0.5 * (block - 1);
      oceanread::EvalPoint at;
      at.id = id;
      at.position = Value::vector({cx * texel, 0, cz * texel});
      at.time = t;
      at.weights = {weight};
      const oceanread::FilteredSum f = oceanread::sumFiltered(at, block * texel);
      const double sx = f.sums.slopes[0], sz = f.sums.slopes[1];
      e.filtered += sx * sx + sz * sz + f.variance;
      e.meanSquaredOnly += sx * sx + sz * sz;
      // The unfiltered reader at each sub-pixel offset: the level-0 texel centres of the block.
      double sum = 0;
      for (int bz = 0; bz < block; ++bz)
        for (int bx = 0; bx < block; ++bx) {
          const double px = jx * block + bx, pz = jz * block + bz;
          oceanref::MapSample m = oceanref::sampleCascade(id, 0, t, px * texel, pz * texel, false);
          sum += m.slopes[0] * m.slopes[0] + m.slopes[1] * m.slopes[1];
        }
      e.supersampled += sum / (block * block);
    }
  e.filtered /= size * size;
  e.meanSquaredOnly /= size * size;
  e.supersampled /= size * size;
  return e;
}

TEST(OceanFilterEnergy, TheFilteredSlopeEnergyEqualsTheSupersampledPointSamples) {
  const int id = oneCascadeSea();
  for (double t : {2.5, 1e6})
    for (int level = 0; level <= 6; ++level) {
      const Energy e = energyAt(id, level, 1, t);
      std::printf("  t %g level %d: filtered %.9g, supersampled %.9g, mean slope alone %.4g\n", t, level, e.filtered,
                  e.supersampled, e.meanSquaredOnly);
      ASSERT_GT(e.supersampled, 1e-4);  // a sea with slopes
      EXPECT_NEAR(e.filtered, e.supersampled, 1e-12 * e.supersampled) << "t " << t << " level " << level;
      // The variance carries the energy the footprint averages away: at level 2 and above
      // most of it (the short waves' slopes average out over 4 texels and more).
      if (level >= 2) {
        EXPECT_LT(e.meanSquaredOnly, 0.9 * e.supersampled) << "level " << level;
      }
    }
}

// A faded cascade hands its slopes to the roughness: the same energy at fade weights 0.5
// and 0, with the normal keeping w^2 of the mean slope's share.
TEST(OceanFilterEnergy, AFadedCascadeKeepsItsEnergyInTheVariance) {
  const int id = oneCascadeSea();
  for (double weight : {0.5, 0.0}) {
    const Energy full = energyAt(id, 3, 1, 2.5), faded = energyAt(id, 3, weight, 2.5);
    // The normal keeps w S, |w S|^2 = w^2 |S|^2; the variance the rest.
    EXPECT_NEAR(faded.meanSquaredOnly, weight * weight * full.meanSquaredOnly, 1e-12);
    EXPECT_NEAR(faded.filtered, full.supersampled, 1e-12 * full.supersampled) << "weight " << weight;
  }
}

}  // namespace ocean_filter_energy_test
}  // namespace wg::nodes
