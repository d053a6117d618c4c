// The CPU reference's read-back scene textures (core/scene_image.h): GL's nearest and
// linear rules with clamp to edge, rows bottom-up, and EvalEnvironment::sceneAt falling
// back to the pixel's one value where no image is given.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/node_spec.h"
#include "core/scene_image.h"

namespace wg {
namespace {

// 4 x 2, one channel: texel (i, j) = 10 j + i, so a blend's value names its weights.
SceneImage ramp(bool nearest) {
  SceneImage img;
  img.width = 4, img.height = 2, img.channels = 1, img.nearest = nearest;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) img.texels.push_back(static_cast<float>(10 * j + i));
  return img;
}

TEST(SceneImage, NearestReadsTheTexelUnderTheCoordinateClampedToTheEdge) {
  SceneImage img = ramp(true);
  EXPECT_EQ(img.sample(0.0, 0.0)[0], 0.0);
  EXPECT_EQ(img.sample(0.2499, 0.49)[0], 0.0);   // u * 4 = 0.9996: texel 0
  EXPECT_EQ(img.sample(0.25, 0.5)[0], 11.0);     // u * 4 = 1, v * 2 = 1: texel (1, 1)
  EXPECT_EQ(img.sample(1.0, 1.0)[0], 13.0);      // floor(4) = 4 clamps to 3
  EXPECT_EQ(img.sample(-7.0, 9.0)[0], 10.0);
}

TEST(SceneImage, LinearBlendsTheTwoByTwoAroundTheCoordinate) {
  SceneImage img = ramp(false);
  // Texel centres at (i + 0.5) / 4, (j + 0.5) / 2 return the texel exactly.
  EXPECT_DOUBLE_EQ(img.sample(2.5 / 4, 0.5 / 2)[0], 2.0);
  // Halfway between texels (1, 0), (2, 0), (1, 1), (2, 1): their mean.
  EXPECT_DOUBLE_EQ(img.sample(2.0 / 4, 1.0 / 2)[0], (1 + 2 + 11 + 12) / 4.0);
  // A quarter of the way from texel 0 to 1 in u, on row 0.
  EXPECT_DOUBLE_EQ(img.sample(0.75 / 4, 0.5 / 2)[0], 0.25);
  // Clamped at the edges: left of the first centre reads texel 0 only.
  EXPECT_DOUBLE_EQ(img.sample(0.0, 0.0)[0], 0.0);
  EXPECT_DOUBLE_EQ(img.sample(1.0, 1.0)[0], 13.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isfinite(img.sample(nan, std::numeric_limits<double>::infinity())[0]));
}

TEST(SceneImage, TheEnvironmentSamplesAnImageWhereItHasOneElseGivesItsField) {
  EvalEnvironment env;
  env.sceneDepth = Value::scalar(0.75);
  EXPECT_EQ(env.sceneAt(SceneSampler::SceneDepth, 0.1, 0.9)[0], 0.75);
  SceneImage img = ramp(true);
  env.sceneImages[static_cast<size_t>(SceneSampler::SceneDepth)] = &img;
  EXPECT_EQ(env.sceneAt(SceneSampler::SceneDepth, 0.8, 0.9)[0], 13.0);
  EXPECT_EQ(env.sceneAt(SceneSampler::SceneDepth, Value::vector({0.3, 0.1}))[0], 1.0);
  // The G-buffer is read as the surface builtins, never by look-up.
  EXPECT_THROW(env.sceneAt(SceneSampler::WaterSurface, 0.5, 0.5), std::logic_error);
}

}  // namespace
}  // namespace wg
