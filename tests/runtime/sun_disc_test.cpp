// The sun's disc band-limited to the pixel's footprint (runtime/sky_model.h, sunDiscShape and
// sunDiscWeight, which the sky pass's GLSL follows): its energy, radiance times solid angle,
// is the sharp disc's pi c^2 L at every footprint (the weight integrated over the sphere
// numerically, not through the closed form the scale comes from); summed over the texels of
// a 128-texel cube face it is that energy wherever the disc's centre falls among the texel
// centres (the aliasing the band limit removes: the sharp disc's sums scatter from nothing
// to several times the energy); and its peak stays within what an RGBA16F target holds.
// The GPU's drawing of it: tests/runtime/sky_model_test.cpp (SkyGpu).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "runtime/sky_model.h"

namespace wg::rt {
namespace {

using namespace sky;

glm::dvec3 sunAt(double elevationDegrees, double azimuthDegrees) {
  double e = elevationDegrees * kPi / 180.0, a = azimuthDegrees * kPi / 180.0;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

double chordSquared(glm::dvec3 a, glm::dvec3 b) {
  glm::dvec3 v = a - b;
  return glm::dot(v, v);
}

// The weight integrated over the sphere by the midpoint rule on the plane tangent to the
// sphere at the sun (direction normalize(s + u t1 + v t2), solid angle du dv / (1 + u^2 +
// v^2)^(3/2)), n x n cells over the weight's whole support.
double integratedWeight(glm::dvec3 s, double footprint, int n) {
  glm::dvec3 t1 = glm::normalize(glm::cross(s, glm::dvec3(0, 1, 0))), t2 = glm::cross(t1, s);
  double outerAngle = 2.0 * std::asin(std::sqrt(sunDiscShape(footprint).outer) / 2.0);
  double extent = std::tan(outerAngle) * 1.02, h = 2.0 * extent / n, sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double u = -extent + (i + 0.5) * h, v = -extent + (j + 0.5) * h, r2 = 1.0 + u * u + v * v;
      glm::dvec3 d = glm::normalize(s + u * t1 + v * t2);
      sum += sunDiscWeight(chordSquared(d, s), footprint) * h * h / (r2 * std::sqrt(r2));
    }
  return sum;
}

TEST(SunDisc, ItsEnergyIsTheSharpDiscsAtEveryFootprint) {
  // pi c^2 is the disc's solid angle 2 pi (1 - cos r): the energy the weight must hold.
  EXPECT_NEAR(kPi * sunDiscChord() * sunDiscChord(), sunSolidAngle(), 1e-15);
  const glm::dvec3 sun = sunAt(30, 110);
  // From a frame's pixel much smaller than the disc (the sharp disc, its edge a few pixels
  // wide) through the disc's own size to a 128-texel cube face's texel (0.0156 at a face's
  // centre) and past the largest edge (0.5, the clamp).
  for (double footprint : {0.0, 2e-4, 1e-3, 1.86e-3, 4e-3, 0.0156, 0.05, 0.3}) {
    SCOPED_TRACE(footprint);
    // 600^2 cells: the midpoint rule's error on the weight's kink at q_in is ~1e-5.
    EXPECT_NEAR(integratedWeight(sun, footprint, 600) / sunSolidAngle(), 1.0, 2e-4);
  }
}

// A face of a cube map of size N (the +z face: texel (i, j) looks along normalize(x, y, 1),
// x and y the texel centre's in [-1, 1]), with each texel's exact solid angle and the
// footprint the sky pass measures there: the chord to the neighbouring texel's direction
// across the 2 x 2 quad the texel shares (GL's coarse derivatives).
struct CubeFace {
  int n;
  glm::dvec3 direction(double i, double j) const {
    return glm::normalize(glm::dvec3(2.0 * (i + 0.5) / n - 1.0, 2.0 * (j + 0.5) / n - 1.0, 1.0));
  }
  double solidAngle(int i, int j) const {
    // The solid angle of the rectangle [0, x] x [0, y] of the plane z = 1 is
    // atan(x y / sqrt(x^2 + y^2 + 1)); a texel's is the four corners' signed sum.
    auto corner = [](double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0)); };
    double x0 = 2.0 * i / n - 1.0, x1 = 2.0 * (i + 1) / n - 1.0, y0 = 2.0 * j / n - 1.0, y1 = 2.0 * (j + 1) / n - 1.0;
    return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
  }
  double footprint(int i, int j) const {
    int qi = i & ~1, qj = j & ~1;
    glm::dvec3 d = direction(qi, qj);
    return std::max(glm::length(direction(qi + 1, qj) - d), glm::length(direction(qi, qj + 1) - d));
  }
};

// The disc's energy summed over the face's texels (radiance at each texel centre times the
// texel's solid angle), over that of the sharp disc; `bandLimited` false draws the sharp
// disc in every texel (footprint 0) instead of one band-limited to the texel.
double energyOnTheFace(const CubeFace& face, glm::dvec3 sun, bool bandLimited) {
  double sum = 0.0;
  for (int i = 0; i < face.n; ++i)
    for (int j = 0; j < face.n; ++j) {
      double footprint = bandLimited ? face.footprint(i, j) : 0.0;
      sum += sunDiscWeight(chordSquared(face.direction(i, j), sun), footprint) * face.solidAngle(i, j);
    }
  return sum / sunSolidAngle();
}

TEST(SunDisc, ItsEnergyInACubeFaceDoesNotDependOnWhereItFallsAmongTexelCentres) {
  const CubeFace face{128};
  // The sun at a texel centre, a quarter and half a texel off in each axis, near the face's
  // centre (texels of 0.0156) and near a corner (texels down to ~0.0067 across, and not
  // square): 2 x 9 positions.
  double lowest = 1e30, highest = 0.0, sharpLowest = 1e30, sharpHighest = 0.0;
  for (double centre : {64.0, 112.0})
    for (double du : {0.0, 0.25, 0.5})
      for (double dv : {0.0, 0.25, 0.5}) {
        glm::dvec3 sun = face.direction(centre + du, centre - 6.0 + dv);
        double e = energyOnTheFace(face, sun, true), sharp = energyOnTheFace(face, sun, false);
        SCOPED_TRACE(testing::Message() << "texel " << centre + du << ", " << centre - 6.0 + dv);
        EXPECT_NEAR(e, 1.0, 5e-3);
        lowest = std::min(lowest, e);
        highest = std::max(highest, e);
        sharpLowest = std::min(sharpLowest, sharp);
        sharpHighest = std::max(sharpHighest, sharp);
      }
  std::printf("disc energy over a 128-texel cube face / pi c^2 L: band-limited %.4f to %.4f, sharp %.3f to %.3f\n",
              lowest, highest, sharpLowest, sharpHighest);
  // What the band limit is there for: the sharp disc, smaller than a texel, is one texel's
  // worth (a texel's solid angle over the disc's: ~3.6 at the face's centre) or nothing.
  EXPECT_LT(sharpLowest, 0.1);
  EXPECT_GT(sharpHighest, 2.0);
}

TEST(SunDisc, ItsPeakStaysWithinWhatAHalfFloatTargetHolds) {
  // The weight is largest inside q_in, where it is the scale; the capped disc times it must
  // stay below RGBA16F's 65504 at every footprint. From the sharp disc's scale (the edge
  // (1 - t)^3 holds less than a symmetric edge: 1.08) the scale rises while the flat top
  // shrinks, then falls as the disc spreads.
  double largest = 0.0;
  for (double footprint = 0.0; footprint < 0.05; footprint += 1e-5) largest = std::max(largest, sunDiscShape(footprint).scale);
  EXPECT_GT(largest, 1.2);
  EXPECT_LT(largest * kSunDiscCap, 65504.0);
  // The sharp limit is the disc: weight 1 at its centre (to the scale's 8 %) and 0 beyond
  // its edge.
  EXPECT_NEAR(sunDiscWeight(0.0, 0.0), 1.0, 0.08);
  double justOutside = 2.0 * std::sin((kSunAngularRadius + kSunEdgeHalfWidth * 1.01) / 2.0);
  EXPECT_EQ(sunDiscWeight(justOutside * justOutside, 0.0), 0.0);
}

}  // namespace
}  // namespace wg::rt
