// The CPU side of GL_LINEAR + GL_REPEAT sampling stays defined for any coordinate: huge
// ones (a world position of 1e5 m scaled into texture space) and non-finite ones.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

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
