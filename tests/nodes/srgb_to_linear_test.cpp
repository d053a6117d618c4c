// srgb_to_linear: the IEC 61966-2-1 decoding (c / 12.92 up to 0.04045, ((c + 0.055) /
// 1.055)^2.4 above), mirrored for negative values, continued past 1; a vec4's alpha passes;
// its value facts hold; and the texture decode uses the same curve (core/color_space.h).
#include <cmath>

#include <gtest/gtest.h>

#include "core/color_space.h"
#include "node_eval.h"

namespace wg {
namespace {

using test::runNode;

double curve(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

Value linearOf(const Value& x) { return runNode("srgb_to_linear", {{"x", x}})["out"]; }

TEST(SrgbToLinear, FollowsTheStandardCurveOnBothSegments) {
  for (double c : {0.0, 0.01, 0.04, 0.04045, 0.0405, 0.1, 0.5, 0.73, 0.99})
    EXPECT_NEAR(linearOf(Value::scalar(c))[0], curve(c), 1e-15) << c;
  EXPECT_NEAR(linearOf(Value::scalar(0.5))[0], 0.21404114048223255, 1e-15);
  EXPECT_EQ(linearOf(Value::scalar(1))[0], 1.0);  // white stays white, never an ulp above
  EXPECT_EQ(linearOf(Value::scalar(0))[0], 0.0);
}

TEST(SrgbToLinear, MirrorsNegativesAndContinuesPastOne) {
  EXPECT_NEAR(linearOf(Value::scalar(-0.5))[0], -curve(0.5), 1e-15);
  EXPECT_NEAR(linearOf(Value::scalar(-0.02))[0], -0.02 / 12.92, 1e-15);
  EXPECT_NEAR(linearOf(Value::scalar(4))[0], std::pow(4.055 / 1.055, 2.4), 1e-12);
  EXPECT_EQ(linearOf(Value::scalar(1e30))[0], 0x1p127);  // capped as the GLSL's guarded pow
  EXPECT_EQ(linearOf(Value::scalar(-1e30))[0], -0x1p127);
}

TEST(SrgbToLinear, IsMonotonicAcrossTheKneeAndOne) {
  double previous = -INFINITY;
  for (double c = -1.5; c <= 1.5; c += 1.0 / 4096) {
    double v = linearOf(Value::scalar(c))[0];
    EXPECT_GE(v, previous) << c;
    previous = v;
  }
}

TEST(SrgbToLinear, Vec3ConvertsEveryComponentAndVec4KeepsAlpha) {
  Value v3 = linearOf(Value::vector({0.5, 0.2, 1}));
  EXPECT_NEAR(v3[0], curve(0.5), 1e-15);
  EXPECT_NEAR(v3[1], curve(0.2), 1e-15);
  EXPECT_EQ(v3[2], 1.0);
  Value v4 = linearOf(Value::vector({0.5, 0.5, 0.5, 0.5}));
  EXPECT_NEAR(v4[2], curve(0.5), 1e-15);
  EXPECT_EQ(v4[3], 0.5);
}

TEST(SrgbToLinear, ValueFactsHoldAtTheirBounds) {
  const NodeSpec* s = defaultRegistry().find("srgb_to_linear");
  ASSERT_TRUE(s && s->facts);
  ParsedOptions none;
  auto unit = s->facts({ValueFact{0, 1}}, none).at(0);
  EXPECT_EQ(unit.lo, 0);
  EXPECT_EQ(unit.hi, 1);
  auto signedUnit = s->facts({ValueFact{-1, 1}}, none).at(0);
  EXPECT_EQ(signedUnit.lo, -1);
  EXPECT_EQ(signedUnit.hi, 1);
  auto hdr = s->facts({ValueFact{0, 4}}, none).at(0);
  EXPECT_EQ(hdr.lo, 0);
  EXPECT_GE(hdr.hi, curve(4));
}

TEST(SrgbToLinear, TheTextureDecodeUsesTheSameCurve) {
  for (int byte : {0, 10, 11, 128, 255}) EXPECT_EQ(srgbToLinear(byte / 255.0), curve(byte / 255.0) > 1 ? 1.0 : curve(byte / 255.0));
}

}  // namespace
}  // namespace wg
