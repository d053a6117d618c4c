// The optics nodes of the shading set: reflect_dir, refract_dir, lambert, blinn_phong,
// phong_specular, ggx_specular. Known values are computed here independently (Snell's law,
// the source formulas written out), plus the total-internal-reflection boundary and the GGX
// energy checks.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "node_eval.h"
#include "nodes/eval_math.h"
#include "nodes/shading_reference.h"

namespace wg {
namespace {

using test::runNode;

Value up() { return Value::vector({0, 1, 0}); }
// A unit vector in the x/y plane at `degrees` from the +y normal.
Value at(double degrees) {
  double r = degrees * std::numbers::pi / 180.0;
  return Value::vector({std::sin(r), std::cos(r), 0});
}
void expectVec(const Value& v, double x, double y, double z, double tol) {
  EXPECT_NEAR(v[0], x, tol);
  EXPECT_NEAR(v[1], y, tol);
  EXPECT_NEAR(v[2], z, tol);
}
double len(const Value& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

TEST(ReflectDir, MirrorsTheViewRay) {
  auto r = runNode("reflect_dir", {{"normal", up()}, {"view", at(30)}});
  // 2 (N.V) N - V: (-sin 30, cos 30, 0)
  expectVec(r["direction"], -0.5, std::sqrt(3.0) / 2, 0, 1e-12);
  // Unnormalised inputs give the same unit direction.
  auto r2 = runNode("reflect_dir", {{"normal", Value::vector({0, 7, 0})}, {"view", glsl::scale(at(30), 3)}});
  expectVec(r2["direction"], -0.5, std::sqrt(3.0) / 2, 0, 1e-12);
  // A tilted normal: independent formula.
  Value n = Value::vector({0.3, 0.9, -0.2}), v = Value::vector({-0.4, 0.5, 0.7});
  Value nn = glsl::safeNormalize(n), vv = glsl::safeNormalize(v);
  double d = glsl::dot(nn, vv);
  auto r3 = runNode("reflect_dir", {{"normal", n}, {"view", v}});
  expectVec(r3["direction"], 2 * d * nn[0] - vv[0], 2 * d * nn[1] - vv[1], 2 * d * nn[2] - vv[2], 1e-12);
  EXPECT_NEAR(len(r3["direction"]), 1.0, 1e-12);
}

TEST(RefractDir, SnellFromAir) {
  for (double deg : {0.0, 10.0, 30.0, 60.0, 89.0}) {
    SCOPED_TRACE(deg);
    auto r = runNode("refract_dir", {{"normal", up()}, {"view", at(deg)}});
    double sinT = std::sin(deg * std::numbers::pi / 180) / 1.333;
    // The transmitted ray goes down, keeping the tangential direction of -V.
    expectVec(r["direction"], -sinT, -std::sqrt(1 - sinT * sinT), 0, 1e-12);
    EXPECT_EQ(r.scalar("tir"), 0.0);
  }
}

TEST(RefractDir, SnellFromBelowAndTheCriticalAngle) {
  double critical = std::asin(1.0 / 1.333) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(critical, 48.6066, 5e-5);
  nlohmann::json below{{"direction", "water_to_air"}};
  // Below the critical angle, Snell with the viewer in water: sin(t) = 1.333 sin(i). (The
  // normal faces the viewer; the frame is the same as from air, only eta changes.)
  for (double deg : {0.0, 20.0, 40.0, 48.6}) {
    SCOPED_TRACE(deg);
    auto r = runNode("refract_dir", {{"normal", up()}, {"view", at(deg)}}, below);
    double sinT = 1.333 * std::sin(deg * std::numbers::pi / 180);
    ASSERT_LT(sinT, 1.0);
    expectVec(r["direction"], -sinT, -std::sqrt(1 - sinT * sinT), 0, 1e-9);
    EXPECT_EQ(r.scalar("tir"), 0.0);
  }
  // Past it: total internal reflection, the mirror direction, tir = 1.
  for (double deg : {48.62, 60.0, 80.0, 90.0}) {
    SCOPED_TRACE(deg);
    auto r = runNode("refract_dir", {{"normal", up()}, {"view", at(deg)}}, below);
    EXPECT_EQ(r.scalar("tir"), 1.0);
    auto m = runNode("reflect_dir", {{"normal", up()}, {"view", at(deg)}});
    expectVec(r["direction"], m["direction"][0], m["direction"][1], m["direction"][2], 1e-12);
  }
  // Just either side of the exact boundary.
  EXPECT_EQ(runNode("refract_dir", {{"normal", up()}, {"view", at(critical - 1e-6)}}, below).scalar("tir"), 0.0);
  EXPECT_EQ(runNode("refract_dir", {{"normal", up()}, {"view", at(critical + 1e-6)}}, below).scalar("tir"), 1.0);
  // From air there is never TIR, even at grazing.
  EXPECT_EQ(runNode("refract_dir", {{"normal", up()}, {"view", at(90)}}).scalar("tir"), 0.0);
}

TEST(RefractDir, IorOptionAndUnitLength) {
  auto r = runNode("refract_dir", {{"normal", up()}, {"view", at(45)}}, {{"ior", 1.5}});
  double sinT = std::sin(std::numbers::pi / 4) / 1.5;
  expectVec(r["direction"], -sinT, -std::sqrt(1 - sinT * sinT), 0, 1e-12);
  Value n = Value::vector({0.2, 1, 0.1}), v = Value::vector({0.5, 0.4, -0.3});
  EXPECT_NEAR(len(runNode("refract_dir", {{"normal", n}, {"view", v}})["direction"]), 1.0, 1e-12);
}

TEST(Lambert, CosineLaw) {
  EXPECT_NEAR(runNode("lambert", {{"normal", up()}, {"light", at(60)}}).scalar("intensity"), 0.5, 1e-12);
  EXPECT_NEAR(runNode("lambert", {{"normal", up()}, {"light", at(0)}}).scalar("intensity"), 1.0, 1e-12);
  EXPECT_EQ(runNode("lambert", {{"normal", up()}, {"light", at(120)}}).scalar("intensity"), 0.0);
  auto r = runNode("lambert", {{"normal", up()},
                               {"light", Value::vector({0, 5, 0})},
                               {"light_color", Value::vector({1, 0.5, 0.25})},
                               {"surface_color", Value::vector({0.5, 0.5, 2})}});
  expectVec(r["color"], 0.5, 0.25, 0.5, 1e-12);
}

TEST(BlinnPhong, HalfVector) {
  // V and L mirrored about N: H = N, the peak.
  EXPECT_NEAR(runNode("blinn_phong", {{"normal", up()}, {"view", at(30)}, {"light", at(-30)}}).scalar("specular"), 1.0,
              1e-12);
  // L along N, V at 60 degrees: H at 30 degrees, specular cos(30)^64.
  auto r = runNode("blinn_phong", {{"normal", up()}, {"view", at(60)}, {"light", up()}, {"strength", Value::scalar(2)}});
  EXPECT_NEAR(r.scalar("specular"), 2 * std::pow(std::cos(std::numbers::pi / 6), 64), 1e-12);
  EXPECT_NEAR(r.scalar("diffuse"), 1.0, 1e-12);
  expectVec(r["color"], r.scalar("specular"), r.scalar("specular"), r.scalar("specular"), 1e-12);
}

TEST(PhongSpecular, SeedOneSunAndEnvironment) {
  // The deferred water article: max(-dot(2 (N.L) N - L, camera-to-surface), 0)^shine, camera-to-surface = -V.
  auto seed = [](const Value& n, const Value& v, const Value& l, double shine) {
    double nl = glsl::dot(n, l);
    double s = 0;
    for (int i = 0; i < 3; ++i) s -= (2 * nl * n[i] - l[i]) * -v[i];
    return std::pow(std::max(s, 0.0), shine);
  };
  // Mirror configuration: the full highlight.
  EXPECT_NEAR(runNode("phong_specular", {{"normal", up()}, {"view", at(30)}, {"sun", at(-30)}}).scalar("sun_specular"),
              1.0, 1e-12);
  // View straight down, sun at 30 degrees: cos(30)^20 = 0.0563.
  auto r = runNode("phong_specular", {{"normal", up()}, {"view", up()}, {"sun", at(30)}});
  EXPECT_NEAR(r.scalar("sun_specular"), std::pow(std::cos(std::numbers::pi / 6), 20), 1e-12);
  EXPECT_NEAR(r.scalar("sun_specular"), seed(up(), up(), at(30), 20), 1e-12);
  // Environment from the zenith, no exponent: R = N, R.V = 1.
  EXPECT_NEAR(r.scalar("environment_specular"), 1.0, 1e-12);
  // A general configuration against the source's expression.
  Value n = glsl::safeNormalize(Value::vector({0.1, 1, 0.2})), v = glsl::safeNormalize(Value::vector({-0.3, 0.6, 0.4}));
  Value l = glsl::safeNormalize(Value::vector({0.5, 0.7, -0.6}));
  auto g = runNode("phong_specular", {{"normal", n}, {"view", v}, {"sun", l}, {"shine", Value::scalar(7)},
                                      {"environment", l}, {"environment_color", Value::vector({1, 1, 1})}});
  EXPECT_NEAR(g.scalar("sun_specular"), seed(n, v, l, 7), 1e-12);
  EXPECT_NEAR(g.scalar("environment_specular"), seed(n, v, l, 1), 1e-12);
  EXPECT_NEAR(g["color"][0], g.scalar("sun_specular") + g.scalar("environment_specular"), 1e-12);
}

// The textbook Cook-Torrance of the advanced shaders tutorial, written out.
double textbookGgx(const Value& n, const Value& v, const Value& l, double roughness, double f0) {
  Value h = glsl::safeNormalize(Value::vector({v[0] + l[0], v[1] + l[1], v[2] + l[2]}));
  double a = roughness * roughness, a2 = a * a;
  double ndoth = std::max(glsl::dot(n, h), 0.0), ndotv = std::max(glsl::dot(n, v), 0.0);
  double ndotl = std::max(glsl::dot(n, l), 0.0);
  double denom = ndoth * ndoth * (a2 - 1) + 1;
  double d = a2 / (std::numbers::pi * denom * denom);
  double f = f0 + (1 - f0) * std::pow(1 - std::max(glsl::dot(h, v), 0.0), 5);
  double k = (roughness + 1) * (roughness + 1) / 8;
  double g = ndotv / (ndotv * (1 - k) + k) * ndotl / (ndotl * (1 - k) + k);
  return d * f * g / (4 * ndotl * ndotv);
}

TEST(GgxSpecular, MatchesTheTextbookFormWhereDefined) {
  for (double r : {0.05, 0.2, 0.5, 1.0})
    for (double vd : {0.0, 40.0, 75.0})
      for (double ld : {-60.0, -10.0, 30.0}) {
        SCOPED_TRACE(std::to_string(r) + " " + std::to_string(vd) + " " + std::to_string(ld));
        Value v = at(vd), l = Value::vector({std::sin(ld * std::numbers::pi / 180) * 0.6, std::cos(ld * std::numbers::pi / 180),
                                             std::sin(ld * std::numbers::pi / 180) * 0.8});
        l = glsl::safeNormalize(l);
        auto g = runNode("ggx_specular", {{"normal", up()}, {"view", v}, {"light", l}, {"roughness", Value::scalar(r)}});
        double expect = textbookGgx(up(), v, l, r, 0.02);
        EXPECT_NEAR(g.scalar("brdf"), expect, 1e-9 * std::max(1.0, expect));
        EXPECT_NEAR(g.scalar("specular"), expect * glsl::dot(up(), l), 1e-9 * std::max(1.0, expect));
      }
  // F0 = 0.02 at normal incidence.
  auto g = runNode("ggx_specular", {{"normal", up()}, {"view", up()}, {"light", up()}});
  EXPECT_NEAR(g.scalar("fresnel"), 0.02, 1e-12);
  // D at the peak: 1 / (pi a^2), a = 0.05^2.
  EXPECT_NEAR(g.scalar("distribution"), 1 / (std::numbers::pi * std::pow(0.05, 4)), 1e-6);
}

// The GGX distribution is normalised: the projected microfacet area is 1,
// integral of D(h) (n.h) over the hemisphere = pi * integral_0^1 D(t = NdotH^2) dt = 1.
TEST(GgxSpecular, DistributionIntegratesToOne) {
  for (double r : {0.001, 0.05, 0.3, 1.0}) {
    SCOPED_TRACE(r);
    double a2 = std::pow(r * r, 2);
    // s = 1 - NdotH^2 on a log grid from 1e-14 to 1 (the peak of a smooth surface is at
    // s ~ a2, as small as 1e-12), trapezoid in ln s; [0, 1e-14] adds D(1) * 1e-14.
    const int steps = 400000;
    double lo = std::log(1e-14), sum = 0, prev = 0;
    for (int i = 0; i <= steps; ++i) {
      double s = std::exp(lo + (0 - lo) * i / steps);
      double f = std::numbers::pi * nodes::ggxDistributionReference(std::sqrt(1 - s), a2) * s;
      if (i > 0) sum += 0.5 * (f + prev) * (-lo / steps);
      prev = f;
    }
    sum += std::numbers::pi * nodes::ggxDistributionReference(1.0, a2) * 1e-14;
    EXPECT_NEAR(sum, 1.0, 5e-4);
  }
}

// Energy: the directional albedo of the specular lobe with F = 1 stays <= 1 (Smith G only
// removes energy), and every term is finite at NdotV = 0, NdotL = 0 and roughness -> 0.
TEST(GgxSpecular, EnergyAndFiniteness) {
  for (double r : {0.3, 0.6, 1.0})
    for (double vd : {0.0, 45.0, 80.0}) {
      SCOPED_TRACE(std::to_string(r) + " " + std::to_string(vd));
      Value v = at(vd);
      const int nt = 300, np = 300;
      double albedo = 0;
      for (int i = 0; i < nt; ++i) {
        double th = (i + 0.5) * (std::numbers::pi / 2) / nt;
        for (int j = 0; j < np; ++j) {
          double ph = (j + 0.5) * 2 * std::numbers::pi / np;
          Value l = Value::vector({std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)});
          nodes::GgxTerms g = nodes::ggxSpecularReference(up(), v, l, r, 1.0);
          albedo += g.brdf * g.ndotl * std::sin(th) * (std::numbers::pi / 2 / nt) * (2 * std::numbers::pi / np);
        }
      }
      EXPECT_LE(albedo, 1.0);
      EXPECT_GT(albedo, 0.3);
    }
  // Grazing view (NdotV = 0), grazing light (NdotL = 0), a mirror-smooth surface.
  for (double rough : {0.0, 1e-6, 0.001, 0.05}) {
    SCOPED_TRACE(rough);
    auto g = runNode("ggx_specular", {{"normal", up()}, {"view", at(90)}, {"light", at(-30)},
                                      {"roughness", Value::scalar(rough)}});
    for (const Value& out : g.values) EXPECT_TRUE(out.allFinite());
    auto h = runNode("ggx_specular", {{"normal", up()}, {"view", up()}, {"light", up()}, {"roughness", Value::scalar(rough)}});
    for (const Value& out : h.values) EXPECT_TRUE(out.allFinite());
    EXPECT_LE(h.scalar("distribution"), 1 / (std::numbers::pi * 1e-12) * (1 + 1e-12));
    auto k = runNode("ggx_specular", {{"normal", up()}, {"view", at(30)}, {"light", Value::vector({1, 0, 0})},
                                      {"roughness", Value::scalar(rough)}});
    EXPECT_EQ(k.scalar("specular"), 0.0);
    EXPECT_TRUE(std::isfinite(k.scalar("brdf")));
  }
  // In float32 the textbook denominator NdotH^2 (a2 - 1) + 1 cancels to 0 at NdotH = 1 for
  // a smooth surface; the library's form keeps a2.
  volatile float a2 = 1e-8f, c2 = 1.0f;
  EXPECT_EQ(c2 * (a2 - 1.0f) + 1.0f, 0.0f);
  EXPECT_GT(c2 * a2 + (1.0f - c2), 0.0f);
}

TEST(OpticsNodes, CompileTogetherForEveryTarget) {
  std::string graph = R"({
    "version": 1, "name": "optics_set",
    "nodes": [
      {"id": "r", "type": "reflect_dir"},
      {"id": "t", "type": "refract_dir", "options": {"direction": "water_to_air", "ior": 1.333}},
      {"id": "lam", "type": "lambert", "inputs": {"light": [0.3, 1, 0.2]}},
      {"id": "bp", "type": "blinn_phong", "inputs": {"shininess": 128}},
      {"id": "ph", "type": "phong_specular"},
      {"id": "gg", "type": "ggx_specular", "inputs": {"light": "r.direction", "roughness": 0.05}},
      {"id": "a", "type": "add", "inputs": {"a": "ph.color", "b": "gg.color"}},
      {"id": "b", "type": "add", "inputs": {"a": "a.out", "b": "lam.color"}},
      {"id": "c", "type": "add", "inputs": {"a": "b.out", "b": "bp.color"}},
      {"id": "d", "type": "mul", "inputs": {"a": "c.out", "b": "t.direction"}},
      {"id": "e", "type": "add", "inputs": {"a": "d.out", "b": "t.tir"}}
    ],
    "outputs": {"fragment": {"color": "e.out", "alpha": 1}}
  })";
  EXPECT_EQ(test::compileGraphText(graph), "");
}

}  // namespace
}  // namespace wg
