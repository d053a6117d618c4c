// The CPU side of GL_LINEAR + GL_REPEAT sampling stays defined for any coordinate: huge
// ones (a world position of 1e5 m scaled into texture space) and non-finite ones.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "nodes/texture_sampling.h"
#include "nodes/texture_source.h"

namespace wg {
namespace {

TEST(TextureSample, HugeAndNonFiniteCoordinatesGiveTexelValues) {
  std::string why;
  auto img = loadTexture("builtin:height", "", &why);
  ASSERT_TRUE(img) << why;
  const double inf = std::numeric_limits<double>::infinity();
  for (double u : {2.7e31, -2.7e31, 1e7 + 0.25, inf, -inf, std::nan("")}) {
    Value v = img->sample(u, 0.5);
    for (int c = 0; c < 4; ++c) {
      EXPECT_TRUE(std::isfinite(v[c])) << "u = " << u;
      EXPECT_GE(v[c], 0.0);
      EXPECT_LE(v[c], 1.0);
    }
  }
  // Wrapping is exact in double: one period further reads the same texels.
  Value a = img->sample(0.3, 0.7), b = img->sample(1024.3, -511.3);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 1e-9);
}

}  // namespace
}  // namespace wg

namespace wg {
namespace {

// The filter precision check allows a look-up the reference filters itself: 2^-7 times the
// spread of the 2x2 footprint plus 2^-9, none for nearest filtering.
TEST(TextureSample, FilterUncertaintyFollowsTheFootprintsSpread) {
  TextureImage img;
  img.width = 2, img.height = 2;
  // Texel (x, y): red 0 or 255 by column, the rest 128: the footprint at the centre spans 1.
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int c = 0; c < 4; ++c) img.rgba.push_back(static_cast<std::uint8_t>(c == 0 ? 255 * x : 128));
  SamplerState linear;
  linear.wrap = TextureWrap::Clamp;
  EXPECT_DOUBLE_EQ(filterUncertainty(img, 0.5, 0.5, linear), std::ldexp(1.0, -7) + std::ldexp(1.0, -9));
  // At the corner the footprint clamps to texel (0, 0) alone: no spread, the rounding only.
  EXPECT_DOUBLE_EQ(filterUncertainty(img, 0.0, 0.0, linear), std::ldexp(1.0, -9));
  SamplerState nearest = linear;
  nearest.filter = TextureFilter::Nearest;
  EXPECT_EQ(filterUncertainty(img, 0.5, 0.5, nearest), 0.0);
}

}  // namespace
}  // namespace wg
