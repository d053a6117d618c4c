// The waves and flow families: gerstner_waves (analytic frame against finite differences,
// validation, cusp, huge coordinates and times), trochoid_wave (bisection lands on the
// surface), sine_normals and ripple_normals against the seeds' formulas, and the texture
// nodes against hand computations from TextureImage::sample; graphs using them compile.
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "nodes/gerstner_waves.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "node_eval.h"
#include "test_support.h"

namespace wg {
namespace {


struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 unit(V3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }
V3 v3(const Value& v) { return {v[0], v[1], v[2]}; }
double dist(V3 a, V3 b) { return std::sqrt(dot(a - b, a - b)); }

// One node through the CPU backend's evaluateNode (defaults, builtins, port types).
std::vector<Value> evalNode(const std::string& type, const nlohmann::json& options,
                            const std::map<std::string, Value>& inputs, const EvalEnvironment& env = {}) {
  const NodeSpec* spec = defaultRegistry().find(type);
  if (!spec) throw std::runtime_error("no node " + type);
  static TextureCache textures;
  return evaluateNode(*spec, options, {inputs.begin(), inputs.end()}, env, &textures, test::sourceDir());
}

using test::atTime;

const TextureImage& builtinTexture(const std::string& name) {
  static std::map<std::string, TextureImage> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, *generateBuiltinTexture(name)).first;
  return it->second;
}

bool compiles(const std::string& text, std::string* messages) {
  Diagnostics diags;
  auto graph = parseGraph(text, "waves.json", diags);
  std::optional<CompileResult> result;
  if (graph) result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  for (const auto& d : diags.all()) *messages += formatText(d) + "\n";
  return graph && result;
}

// ---------------------------------------------------------------- gerstner_waves

// Three waves with distinct directions, one with an explicit amplitude and phase:
// sum Q k A = 0.6^2 + 0.4^2 + 0.3 * k3 * 0.2 = 0.52 + 0.3 * (2 pi / 7) * 0.2 = 0.574.
const char* kThreeWaves = R"([
  {"direction": [1, 0.3], "steepness": 0.6, "wavelength": 12},
  {"direction": [-0.4, 1], "steepness": 0.4, "wavelength": 5.5},
  {"direction": [0.7, -0.7], "steepness": 0.3, "wavelength": 7, "amplitude": 0.2, "phase": 1.3}])";

// An independent double formula of the displacement (the stylized water shader's formula section, GPU
// Gems form), with the time taken straight, not wrapped.
V3 displaced(const nlohmann::json& waves, double x, double z, double t) {
  V3 p{x, 0, z};
  for (const auto& w : waves) {
    double dx = w["direction"][0], dz = w["direction"][1];
    double len = std::hypot(dx, dz);
    dx /= len;
    dz /= len;
    double q = w["steepness"], lambda = w["wavelength"];
    double k = 2 * std::numbers::pi / lambda, omega = std::sqrt(9.81 * k);
    double a = w.contains("amplitude") ? w["amplitude"].get<double>() : q / k;
    double phi = w.contains("phase") ? w["phase"].get<double>() : 0.0;
    double theta = k * (dx * x + dz * z) - omega * t + phi;
    p = p + V3{q * a * dx * std::cos(theta), a * std::sin(theta), q * a * dz * std::cos(theta)};
  }
  return p;
}

TEST(GerstnerWaves, AnalyticFrameMatchesFiniteDifferences) {
  auto waves = nlohmann::json::parse(kThreeWaves);
  ASSERT_EQ(nodes::validateGerstnerWaves(waves), "");
  // Fourth-order central differences: h = 2e-3 keeps both the truncation (~h^4) and the
  // rounding of phases near omega t = 2.5e6 rad at t = 1e6 s (~1e-10 / h) below 1e-7.
  const double h = 2e-3;
  auto ddx = [&](double x, double z, double t) {
    return (displaced(waves, x - 2 * h, z, t) - displaced(waves, x + 2 * h, z, t) +
            (displaced(waves, x + h, z, t) - displaced(waves, x - h, z, t)) * 8.0) *
           (1.0 / (12 * h));
  };
  auto ddz = [&](double x, double z, double t) {
    return (displaced(waves, x, z - 2 * h, t) - displaced(waves, x, z + 2 * h, t) +
            (displaced(waves, x, z + h, t) - displaced(waves, x, z - h, t)) * 8.0) *
           (1.0 / (12 * h));
  };
  const V3 points[] = {{0, 0, 0}, {3.1, 0, -2.2}, {-17.5, 0, 40.25}, {123.4, 0, 56.7}, {-250, 0, -999}};
  const double times[] = {0.0, 2.75, 61.3, 1e6};
  int checked = 0;
  for (double t : times)
    for (V3 p : points) {
      SCOPED_TRACE("t = " + std::to_string(t) + ", x = " + std::to_string(p.x) + ", z = " + std::to_string(p.z));
      auto out =
          evalNode("gerstner_waves", {{"waves", waves}}, {{"position", Value::vector({p.x, p.y, p.z})}}, atTime(t));
      V3 dPdx = ddx(p.x, p.z, t), dPdz = ddz(p.x, p.z, t);
      V3 n = unit(cross(dPdz, dPdx));
      EXPECT_LE(dist(v3(out[0]), displaced(waves, p.x, p.z, t)), 1e-8);
      EXPECT_LE(dist(v3(out[1]), n), 1e-6);
      EXPECT_LE(dist(v3(out[2]), unit(dPdx)), 1e-6);
      EXPECT_LE(dist(v3(out[3]), unit(dPdz)), 1e-6);
      // The unnormalised partial derivatives of the reference, too.
      auto f = nodes::gerstnerReference(nodes::parseGerstnerWaves(waves), p.x, p.z, t);
      EXPECT_LE(dist({f.dPdx[0], f.dPdx[1], f.dPdx[2]}, dPdx), 1e-6);
      EXPECT_LE(dist({f.dPdz[0], f.dPdz[1], f.dPdz[2]}, dPdz), 1e-6);
      ++checked;
    }
  EXPECT_EQ(checked, 20);
}

// GPU Gems eq. 12 sums per-wave normal terms, N = (-sum D.x k A C, 1 - sum Q k A S, -sum D.z k A C):
// exact for one wave (the products in cross(dP/dz, dP/dx) cancel), not for several, which is
// why the node crosses the summed Jacobian instead.
TEST(GerstnerWaves, GpuGemsSimplifiedNormalIsExactOnlyForOneWave) {
  auto gems = [](const nlohmann::json& waves, double x, double z, double t) {
    V3 n{0, 1, 0};
    for (const auto& w : waves) {
      double dx = w["direction"][0], dz = w["direction"][1], len = std::hypot(dx, dz);
      dx /= len;
      dz /= len;
      double q = w["steepness"], k = 2 * std::numbers::pi / w["wavelength"].get<double>(), a = q / k;
      double theta = k * (dx * x + dz * z) - std::sqrt(9.81 * k) * t;
      n = n + V3{-dx * k * a * std::cos(theta), -q * k * a * std::sin(theta), -dz * k * a * std::cos(theta)};
    }
    return unit(n);
  };
  auto one = nlohmann::json::parse(R"([{"direction": [1, 0.5], "steepness": 0.7, "wavelength": 10}])");
  auto three = nlohmann::json::parse(R"([
    {"direction": [1, 0], "steepness": 0.5, "wavelength": 10},
    {"direction": [0, 1], "steepness": 0.5, "wavelength": 10},
    {"direction": [1, 1], "steepness": 0.4, "wavelength": 6}])");
  double worstOne = 0, worstThree = 0;
  for (double x = -5; x <= 5; x += 0.37)
    for (double z = -5; z <= 5; z += 0.41) {
      V3 exact1 =
          v3(evalNode("gerstner_waves", {{"waves", one}}, {{"position", Value::vector({x, 0, z})}}, atTime(2))[1]);
      V3 exact3 =
          v3(evalNode("gerstner_waves", {{"waves", three}}, {{"position", Value::vector({x, 0, z})}}, atTime(2))[1]);
      worstOne = std::max(worstOne, dist(exact1, gems(one, x, z, 2)));
      worstThree = std::max(worstThree, dist(exact3, gems(three, x, z, 2)));
    }
  EXPECT_LE(worstOne, 1e-9);
  EXPECT_GT(worstThree, 1e-3);
}

TEST(GerstnerWaves, ValidationReportsFoldingAndBadWaves) {
  using nodes::validateGerstnerWaves;
  // Two aligned waves with Q = 0.8 and 0.75 and default amplitudes: sum Q^2 = 0.64 + 0.5625 = 1.2025.
  auto folding = nlohmann::json::parse(R"([
    {"direction": [1, 0], "steepness": 0.8, "wavelength": 10},
    {"direction": [0, 1], "steepness": 0.4, "wavelength": 10, "amplitude": 0.7957747154594768}])");
  // 0.64 + 0.4 * (2 pi / 10) * 0.79577 = 0.64 + 0.2 = 0.84: valid.
  EXPECT_EQ(validateGerstnerWaves(folding), "");
  folding[1]["amplitude"] = 2.228169203286535;  // 0.4 k A = 0.56: sum 1.2
  EXPECT_EQ(validateGerstnerWaves(folding),
            "the waves' steepness sum \xCE\xA3 Q\xC2\xB7k\xC2\xB7"
            "A = 1.2 exceeds 1: the surface folds over");
  EXPECT_EQ(validateGerstnerWaves(nlohmann::json::parse(R"([{"direction": [1, 0], "steepness": 1, "wavelength": 3}])")),
            "")
      << "the cusp, sum = 1, is allowed";
  auto bad = [&](const char* text) { return validateGerstnerWaves(nlohmann::json::parse(text)); };
  EXPECT_NE(bad(R"([{"direction": [0, 0], "steepness": 0.5, "wavelength": 3}])").find("zero vector"),
            std::string::npos);
  EXPECT_NE(bad(R"([{"direction": [1, 0], "steepness": 1.5, "wavelength": 3}])").find("outside [0, 1]"),
            std::string::npos);
  EXPECT_NE(bad(R"([{"direction": [1, 0], "steepness": 0.5, "wavelength": 0}])").find("greater than 0"),
            std::string::npos);
  EXPECT_NE(bad(R"([{"direction": [1, 0], "steepness": 0.5}])").find("wavelength"), std::string::npos);
  EXPECT_NE(bad(R"([{"direction": [1, 0], "steepness": 0.5, "wavelength": 3, "ampltude": 1}])")
                .find("unknown key 'ampltude'"),
            std::string::npos);
  EXPECT_NE(bad(R"([])").find("at least one"), std::string::npos);
  EXPECT_NE(bad(R"({"direction": [1, 0]})").find("array"), std::string::npos);
  nlohmann::json many = nlohmann::json::array();
  for (int i = 0; i < 17; ++i) many.push_back({{"direction", {1, i}}, {"steepness", 0.01}, {"wavelength", 10}});
  EXPECT_NE(validateGerstnerWaves(many).find("at most 16"), std::string::npos);
  many.erase(many.begin());
  EXPECT_EQ(validateGerstnerWaves(many), "");
}

TEST(GerstnerWaves, FoldingGraphIsAnErrorAtTheOption) {
  std::string text = R"({"version": 1, "name": "fold", "nodes": [
    {"id": "waves", "type": "gerstner_waves", "options": {"waves": [
      {"direction": [1, 0], "steepness": 0.9, "wavelength": 10},
      {"direction": [1, 1], "steepness": 0.7, "wavelength": 20}]}}],
    "outputs": {"vertex": {"position": "waves.position"}}})";
  std::string messages;
  EXPECT_FALSE(compiles(text, &messages));
  EXPECT_NE(messages.find("option 'waves'"), std::string::npos) << messages;
  EXPECT_NE(messages.find("= 1.3 exceeds 1: the surface folds over"), std::string::npos) << messages;
}

TEST(GerstnerWaves, CuspStaysFinite) {
  // One wave at Q = 1 and two aligned waves summing to 1: at the crest both tangents vanish.
  for (const char* text : {R"([{"direction": [1, 0], "steepness": 1, "wavelength": 8}])",
                           R"([{"direction": [1, 0], "steepness": 0.8, "wavelength": 8},
                               {"direction": [1, 0], "steepness": 0.6, "wavelength": 8}])"}) {
    auto waves = nlohmann::json::parse(text);
    ASSERT_EQ(nodes::validateGerstnerWaves(waves), "");
    for (double x = 1.5; x <= 2.5; x += 0.03125)
      for (double t : {0.0, 1e6}) {
        auto out =
            evalNode("gerstner_waves", {{"waves", waves}}, {{"position", Value::vector({x, 0.5, 0})}}, atTime(t));
        for (const auto& v : out) EXPECT_TRUE(v.allFinite());
        for (int o = 1; o < 4; ++o) EXPECT_NEAR(std::sqrt(dot(v3(out[o]), v3(out[o]))), 1.0, 1e-12);
        EXPECT_GE(out[1][1], 0.0);
      }
    // Exactly on the crest (theta = pi/2 at t = 0): the degenerate frame falls back to up, +x.
    auto crest = evalNode("gerstner_waves", {{"waves", waves}}, {{"position", Value::vector({2, 0, 0})}});
    EXPECT_LE(dist(v3(crest[1]), {0, 1, 0}), 1e-6);
    EXPECT_LE(dist(v3(crest[2]), {1, 0, 0}), 1e-6);
  }
}

TEST(GerstnerWaves, HugeCoordinatesAndTimesStayAccurate) {
  auto waves = nlohmann::json::parse(kThreeWaves);
  for (double c : {1e5, -1e5})
    for (double t : {0.0, 524288.0, 1e6}) {
      auto out = evalNode("gerstner_waves", {{"waves", waves}}, {{"position", Value::vector({c, 0, -c})}}, atTime(t));
      for (const auto& v : out) EXPECT_TRUE(v.allFinite());
      EXPECT_LE(dist(v3(out[0]), displaced(waves, c, -c, t)), 1e-7);
    }
  // One wave is periodic in time with period 2 pi / omega: the wrapped phase sees that at t = 1e6.
  auto one = nlohmann::json::parse(R"([{"direction": [1, 2], "steepness": 0.7, "wavelength": 9}])");
  double period = 2 * std::numbers::pi / std::sqrt(9.81 * 2 * std::numbers::pi / 9);
  auto a = evalNode("gerstner_waves", {{"waves", one}}, {{"position", Value::vector({3, 0, 4})}}, atTime(1e6));
  auto b = evalNode("gerstner_waves", {{"waves", one}}, {{"position", Value::vector({3, 0, 4})}}, atTime(1e6 + period));
  EXPECT_LE(dist(v3(a[0]), v3(b[0])), 1e-8);
}

TEST(GerstnerWaves, VertexDisplacementWithFragmentNormalsCompiles) {
  std::string text = R"({"version": 1, "name": "ocean", "nodes": [
    {"id": "waves", "type": "gerstner_waves", "options": {"waves": [
      {"direction": [1, 0.3], "steepness": 0.6, "wavelength": 12},
      {"direction": [-0.4, 1], "steepness": 0.4, "wavelength": 5.5},
      {"direction": [0.7, -0.7], "steepness": 0.3, "wavelength": 7, "amplitude": 0.2, "phase": 1.3}]}},
    {"id": "fresnel", "type": "fresnel", "inputs": {"normal": "waves.normal"}},
    {"id": "color", "type": "mix", "inputs": {"a": [0, 0.1, 0.3], "b": [0.6, 0.7, 0.9], "t": "fresnel.reflectance"}}],
    "outputs": {"vertex": {"position": "waves.position", "normal": "waves.normal"},
                "fragment": {"color": "color.out"}}})";
  std::string messages;
  EXPECT_TRUE(compiles(text, &messages)) << messages;
}

// ---------------------------------------------------------------- trochoid_wave

struct Trochoid {
  double amplitude = 0.5, kx = 0.3, kz = 0.2, detail = 0.3, scale = 0.01, omega = 1.0;
  double height(double x, double z, double t) const {
    double phi = kx * x + kz * z + omega * t;
    double tex = builtinTexture("height").sample(scale * x + 0.5, 0.5 - scale * z)[0];
    return amplitude * (std::sin(phi - 0.5 * std::cos(phi)) + detail * (2 * tex - 1));
  }
};

TEST(TrochoidWave, BisectionLandsOnTheSurfaceAlongTheRay) {
  Trochoid w;
  // Rays steeper than |R.y| = 0.1, where the search range covers every height the wave reaches.
  const V3 origins[] = {{0, 10, 0}, {-30, 14, 12}, {5, 25, -60}};
  const V3 targets[] = {{12, 0, 7}, {-10, 0, 3}, {40, 0, -20}};
  for (double t : {0.0, 7.5, 1e6})
    for (const V3& o : origins)
      for (const V3& q : targets)
        for (int steps : {10, 24}) {
          SCOPED_TRACE("steps " + std::to_string(steps) + " t " + std::to_string(t));
          V3 view = unit(o - q);  // from the surface to the viewer
          auto out =
              evalNode("trochoid_wave", {{"steps", steps}},
                       {{"origin", Value::vector({o.x, o.y, o.z})}, {"view", Value::vector({view.x, view.y, view.z})}},
                       atTime(t));
          V3 p = v3(out[0]);
          // On the ray.
          EXPECT_LE(std::sqrt(dot(cross(p - o, view), cross(p - o, view))), 1e-9);
          // On the surface, to within the last step (at most 10 A (1 + detail) / 2^steps along the ray).
          double lastStep = 10 * w.amplitude * (1 + w.detail) / std::pow(2.0, steps);
          double h = w.height(p.x, p.z, t);
          EXPECT_LE(std::abs(p.y - h), lastStep * 4) << "p.y " << p.y << " h " << h;
          EXPECT_NEAR(out[1][0], h, 1e-9);
        }
}

TEST(TrochoidWave, NormalIsTheAnalyticDerivative) {
  // Without the texture detail the normal is exactly analytic: compare with finite differences.
  Trochoid w;
  w.detail = 0;
  const double e = 2e-3;  // fourth-order central differences (see the Gerstner test)
  for (double t : {0.0, 3.3, 1e6})
    for (double x : {-4.0, 0.5, 13.0}) {
      V3 o{x, 6, 2};
      V3 q{x + 3, 0, -1};
      V3 view = unit(o - q);
      auto out = evalNode("trochoid_wave", {{"steps", 16}},
                          {{"origin", Value::vector({o.x, o.y, o.z})},
                           {"view", Value::vector({view.x, view.y, view.z})},
                           {"detail", Value::scalar(0)}},
                          atTime(t));
      V3 p = v3(out[0]);
      auto d = [&](double ux, double uz) {
        return (w.height(p.x - 2 * e * ux, p.z - 2 * e * uz, t) - w.height(p.x + 2 * e * ux, p.z + 2 * e * uz, t) +
                8 * (w.height(p.x + e * ux, p.z + e * uz, t) - w.height(p.x - e * ux, p.z - e * uz, t))) /
               (12 * e);
      };
      double dhdx = d(1, 0), dhdz = d(0, 1);
      EXPECT_LE(dist(v3(out[2]), unit({-dhdx, 1, -dhdz})), 1e-6);
    }
}

TEST(TrochoidWave, CameraBelowAndHardRaysStayFinite) {
  Trochoid w;
  // From below, looking up through the surface: the hit still lies on the wave.
  V3 o{1, -6, 2}, q{4, 0, 3};
  V3 view = unit(o - q);
  auto out = evalNode("trochoid_wave", {{"steps", 20}},
                      {{"origin", Value::vector({o.x, o.y, o.z})}, {"view", Value::vector({view.x, view.y, view.z})}});
  V3 p = v3(out[0]);
  EXPECT_LE(std::abs(p.y - w.height(p.x, p.z, 0)), 1e-4);
  EXPECT_LT(dot(p - o, view), 0.0) << "the hit lies in front of the camera";
  for (V3 v : {V3{1, 0, 0}, V3{0, 0, 0}, V3{0.6, -0.8, 0}}) {
    auto r =
        evalNode("trochoid_wave", {},
                 {{"origin", Value::vector({1e5, 3, -1e5})}, {"view", Value::vector({v.x, v.y, v.z})}}, atTime(1e6));
    for (const auto& x : r) EXPECT_TRUE(x.allFinite());
  }
}

// ---------------------------------------------------------------- sine_normals, ripple_normals

TEST(SineNormals, MatchSeed002) {
  for (double t : {0.0, 1.7, 1e6})
    for (V3 p : {V3{0, 0, 0}, V3{2.5, 1, -3.75}, V3{-40, 0, 17}}) {
      // The advanced shaders tutorial's computeWaveNormal(pos, time) with pos = world xz, straight from the text.
      double x = p.x, y = p.z;
      V3 n{0, 1, 0};
      double wave1 = std::sin(x * 0.5 + t * 0.8) * std::cos(y * 0.3 + t * 0.6);
      n.x += wave1 * 0.3;
      n.z += std::cos(x * 0.5 + t * 0.8) * 0.2;
      double wave2 = std::sin(x * 2.0 + y * 1.5 + t * 2.0);
      n.x += wave2 * 0.15;
      n.z += std::cos(x * 1.5 - y * 2.0 + t * 1.8) * 0.1;
      double wave3 = std::sin(x * 8.0 - t * 3.0) * std::sin(y * 6.0 + t * 2.5);
      n.x += wave3 * 0.05;
      n.z += wave3 * 0.05;
      auto out = evalNode("sine_normals", {}, {{"position", Value::vector({p.x, p.y, p.z})}}, atTime(t));
      EXPECT_LE(dist(v3(out[0]), unit(n)), 1e-8);
    }
  // Fewer octaves drop the later layers: octaves = 1 at the origin, t = 0: (0, 1, 0.2).
  auto one = evalNode("sine_normals", {{"octaves", 1}}, {{"position", Value::vector({0, 0, 0})}});
  EXPECT_LE(dist(v3(one[0]), unit({0, 1, 0.2})), 1e-12);
  EXPECT_NEAR(one[1][1], 0.2, 1e-12);
}

TEST(RippleNormals, MatchSeed004) {
  for (double t : {0.0, 0.9, 524288.0})
    for (V3 p : {V3{0, 0, 0}, V3{3.2, 0, -7.5}, V3{150, 0, 80}}) {
      double u = p.x * 1.0 * 0.08, v = p.z * 1.0 * 0.08;
      double rx = std::sin(u * 23 + v * 17 + t * 2.3) * 0.5 + std::sin(u * 47 + v * 31 - t * 3.1) * 0.3 +
                  std::sin(u * 89 - v * 67 + t * 4.1) * 0.2;
      double ry = std::sin(u * 19 - v * 23 + t * 1.9) * 0.5 + std::sin(u * 37 - v * 43 + t * 2.7) * 0.3 +
                  std::sin(u * 73 + v * 61 - t * 3.7) * 0.2;
      V3 base = unit({0.1, 1, -0.2});
      auto out =
          evalNode("ripple_normals", {},
                   {{"position", Value::vector({p.x, p.y, p.z})}, {"normal", Value::vector({base.x, base.y, base.z})}},
                   atTime(t));
      EXPECT_LE(dist(v3(out[0]), unit(base + V3{rx * 0.15, 0, ry * 0.15})), 1e-8);
      EXPECT_NEAR(out[1][0], rx, 1e-8);
      EXPECT_NEAR(out[1][1], ry, 1e-8);
    }
}

// ---------------------------------------------------------------- texture nodes

V3 unpack(const Value& t) { return {t[0] * 2 - 1, t[1] * 2 - 1, t[2] * 2 - 1}; }
double fract(double x) { return x - std::floor(x); }

TEST(NormalMapScroll, MatchesHandComputationAndBlendsAreUnit) {
  const TextureImage& tex = builtinTexture("water_normal");
  for (const char* blend : {"add", "whiteout", "rnm"})
    for (double t : {0.0, 12.5, 13107.0, 524288.0, 1e6})
      for (double u : {0.0, 0.123, 0.77})
        for (double strength : {1.0, 0.4}) {
          SCOPED_TRACE(std::string(blend) + " t " + std::to_string(t));
          double v = 0.31;
          V3 a = unpack(tex.sample(u * 4 + fract(0.05 * t), v * 4 + fract(0.03 * t)));
          V3 b = unpack(tex.sample(u * 8 + fract(-0.03 * t), v * 8 + fract(0.07 * t)));
          V3 n;
          if (std::string(blend) == "add") {
            n = unit(a + b);
          } else if (std::string(blend) == "whiteout") {
            n = unit({a.x + b.x, a.y + b.y, a.z * b.z});
          } else {
            V3 tt = a + V3{0, 0, 1}, uu{-b.x, -b.y, b.z};
            n = unit(tt * (dot(tt, uu) / tt.z) - uu);
          }
          // T = +x, B = +z, N = +y.
          V3 world = unit({n.x * strength, n.z, n.y * strength});
          auto out = evalNode(
              "normal_map_scroll", {{"blend", blend}},
              {{"uv", Value::vector({u, v})}, {"time", Value::scalar(t)}, {"strength", Value::scalar(strength)}});
          EXPECT_LE(dist(v3(out[0]), world), 1e-12);
          EXPECT_LE(dist(v3(out[1]), n), 1e-12);
          EXPECT_NEAR(dot(v3(out[0]), v3(out[0])), 1.0, 1e-12);
          EXPECT_NEAR(dot(v3(out[1]), v3(out[1])), 1.0, 1e-12);
        }
}

TEST(NormalMapScroll, RnmReorientsTheDetailOntoTheBase) {
  // RNM's defining property: a flat base (0, 0, 1) leaves the detail normal unchanged; a flat detail
  // returns the base. Checked through the GLSL-mirroring formula with the extreme texels of a
  // hand-made image is not possible through the node, so use its documented formula directly.
  auto rnm = [](V3 a, V3 b) {
    V3 t = a + V3{0, 0, 1}, u{-b.x, -b.y, b.z};
    return unit(t * (dot(t, u) / std::max(t.z, 1e-6)) - u);
  };
  V3 d = unit({0.3, -0.2, 0.9}), base = unit({-0.4, 0.1, 0.8});
  EXPECT_LE(dist(rnm({0, 0, 1}, d), d), 1e-12);
  EXPECT_LE(dist(rnm(base, {0, 0, 1}), base), 1e-12);
}

TEST(NormalFromHeight, MatchesHandComputation) {
  const TextureImage& tex = builtinTexture("height");
  for (double u : {0.0, 0.25, 0.6180})
    for (double e : {1.0 / 256, 0.01}) {
      double v = 0.42, k = 0.1;
      double gx = (tex.sample(u + e, v)[0] - tex.sample(u - e, v)[0]) / (2 * e);
      double gy = (tex.sample(u, v + e)[0] - tex.sample(u, v - e)[0]) / (2 * e);
      auto out = evalNode("normal_from_height", {}, {{"uv", Value::vector({u, v})}, {"offset", Value::scalar(e)}});
      EXPECT_LE(dist(v3(out[0]), unit({-k * gx, 1, -k * gy})), 1e-12);
      EXPECT_NEAR(out[1][0], tex.sample(u, v)[0], 1e-12);
      EXPECT_NEAR(out[2][0], gx, 1e-9);
      EXPECT_NEAR(out[2][1], gy, 1e-9);
    }
}

TEST(DudvDistortion, MatchesSeed000AndWrapsWithTime) {
  const TextureImage& tex = builtinTexture("dudv");
  for (double t : {0.0, 40.0, 13107.0, 524288.0, 1e6}) {
    double u = 0.3, v = 0.65;
    double move = fract(t * 0.03);
    Value s = tex.sample(u * 4 + move, v * 4);
    auto out = evalNode(
        "dudv_distortion", {},
        {{"uv", Value::vector({u, v})}, {"time", Value::scalar(t)}, {"target_uv", Value::vector({0.5, 0.25})}});
    EXPECT_NEAR(out[0][0], (s[0] * 2 - 1) * 0.03, 1e-12);
    EXPECT_NEAR(out[0][1], (s[1] * 2 - 1) * 0.03, 1e-12);
    EXPECT_NEAR(out[1][0], 0.5 + out[0][0], 1e-12);
    EXPECT_NEAR(out[1][1], 0.25 + out[0][1], 1e-12);
    EXPECT_NEAR(out[2][0], move, 1e-12);
    EXPECT_GE(out[2][0], 0.0);
    EXPECT_LT(out[2][0], 1.0);
  }
  // Periodic: with speed 0.25 the scroll repeats every 4 s, also at 524288 s and 13107 s.
  for (double t : {13107.0, 524288.0}) {
    auto a = evalNode("dudv_distortion", {}, {{"time", Value::scalar(t)}, {"wave_speed", Value::scalar(0.25)}});
    auto b = evalNode("dudv_distortion", {}, {{"time", Value::scalar(t + 4)}, {"wave_speed", Value::scalar(0.25)}});
    EXPECT_NEAR(a[0][0], b[0][0], 1e-12);
    EXPECT_NEAR(a[0][1], b[0][1], 1e-12);
    for (const auto& x : a) EXPECT_TRUE(x.allFinite());
  }
}

TEST(FlowMap, MatchesSeed003AndWrapsWithTime) {
  const TextureImage& tex = builtinTexture("water_normal");
  const TextureImage& flowTex = builtinTexture("dudv");
  for (double t : {0.0, 0.3, 0.75, 13107.0, 524288.0, 1e6})
    for (double u : {0.1, 0.55}) {
      SCOPED_TRACE("t " + std::to_string(t));
      double v = 0.8, speed = 1.0, strength = 0.2;
      Value f = flowTex.sample(u, v);
      double fx = (f[0] * 2 - 1) * strength, fy = (f[1] * 2 - 1) * strength;
      double pa = fract(t * speed), pb = fract(t * speed + 0.5);
      double wa = 1 - std::abs(1 - 2 * pa), wb = 1 - std::abs(1 - 2 * pb);
      Value a = tex.sample(u - fx * pa, v - fy * pa), b = tex.sample(u - fx * pb, v - fy * pb);
      auto out =
          evalNode("flow_map", {},
                   {{"uv", Value::vector({u, v})}, {"time", Value::scalar(t)}, {"strength", Value::scalar(strength)}});
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(out[0][c], a[c] * wa + b[c] * wb, 1e-12);
      EXPECT_NEAR(out[1][0], wa, 1e-12);
      EXPECT_NEAR(out[2][0], wb, 1e-12);
      EXPECT_NEAR(out[1][0] + out[2][0], 1.0, 1e-12);
    }
  // The flow from an input; periodic in 1 / speed (speed 0.5: every 2 s) at 13107 s and 524288 s.
  for (double t : {13107.0, 524288.0}) {
    std::map<std::string, Value> in{
        {"flow", Value::vector({0.3, -0.6})}, {"speed", Value::scalar(0.5)}, {"time", Value::scalar(t)}};
    auto a = evalNode("flow_map", {{"flow_source", "input"}}, in);
    in["time"] = Value::scalar(t + 2);
    auto b = evalNode("flow_map", {{"flow_source", "input"}}, in);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[0][c], b[0][c], 1e-12);
    EXPECT_NEAR(a[1][0], b[1][0], 1e-12);
    for (const auto& x : a) EXPECT_TRUE(x.allFinite());
  }
  // Time 0: phase A restarts (weight 0), phase B is at its middle (weight 1).
  auto zero = evalNode("flow_map", {}, {{"time", Value::scalar(0)}});
  EXPECT_EQ(zero[1][0], 0.0);
  EXPECT_EQ(zero[2][0], 1.0);
}

// ---------------------------------------------------------------- combined

TEST(WavesFamily, CombinedSurfaceGraphCompilesForEveryTarget) {
  std::string text = R"({"version": 1, "name": "waves_all", "nodes": [
    {"id": "gerstner", "type": "gerstner_waves"},
    {"id": "scroll", "type": "normal_map_scroll", "options": {"blend": "rnm"}, "inputs": {"normal": "gerstner.normal",
      "tangent": "gerstner.tangent", "binormal": "gerstner.binormal"}},
    {"id": "ripples", "type": "ripple_normals", "inputs": {"normal": "scroll.normal"}},
    {"id": "sines", "type": "sine_normals", "options": {"octaves": 2}},
    {"id": "height", "type": "normal_from_height"},
    {"id": "dudv", "type": "dudv_distortion"},
    {"id": "flow", "type": "flow_map", "options": {"texture": "builtin:foam"}},
    {"id": "trochoid", "type": "trochoid_wave", "options": {"steps": 6}},
    {"id": "n1", "type": "add", "inputs": {"a": "ripples.normal", "b": "sines.normal"}},
    {"id": "n2", "type": "add", "inputs": {"a": "n1.out", "b": "height.normal"}},
    {"id": "n3", "type": "add", "inputs": {"a": "n2.out", "b": "trochoid.normal"}},
    {"id": "nn", "type": "normalize", "inputs": {"x": "n3.out"}},
    {"id": "fresnel", "type": "fresnel", "inputs": {"normal": "nn.out"}},
    {"id": "foam", "type": "swizzle", "options": {"mask": "xyz"}, "inputs": {"x": "flow.sample"}},
    {"id": "d", "type": "swizzle", "options": {"mask": "xyx"}, "inputs": {"x": "dudv.uv"}},
    {"id": "c1", "type": "mix", "inputs": {"a": "foam.out", "b": "d.out", "t": "fresnel.reflectance"}}],
    "outputs": {"vertex": {"position": "gerstner.position", "normal": "gerstner.normal"},
                "fragment": {"color": "c1.out"}}})";
  std::string messages;
  EXPECT_TRUE(compiles(text, &messages)) << messages;
}

}  // namespace
}  // namespace wg
