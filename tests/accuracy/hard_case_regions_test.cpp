// Every case of the hard-case suite names the region or branch it exercises ("region"), and
// this test proves each one reaches it: the case's inputs, rounded to float32 as the GPU
// sees them, are shown to lie in the region by a computation written here, independently
// of the node code (angles from atan2, float32 dot products, sums over the wave list), and
// where a closed form exists the double reference must equal an independent oracle:
// Fresnel from the s- and p-amplitude laws, Snell's law from angles, Gerstner normals by
// finite differences of the displacement, Beer-Lambert from tabulated coefficients, linear
// depth from the projection, the hash from its reference bit pattern, value noise, fbm and
// the Voronoi caustics from PCG3D written out here. A case at ordinary inputs also shows
// that the constant its nodes are named for (a path length, a fade, an octave offset, a
// feature point's centre) moves the result by more than the node's tolerance there. The
// suite (hard_cases_test) then holds the GPU to that reference within the error bound.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

#include <gtest/gtest.h>

#include "accuracy/probe_cases.h"
#include "codegen/cpu_backend.h"
#include "nodes/registry.h"
#include "suite_file.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

constexpr double kIor = 1.333;

struct V3 {
  double x = 0, y = 0, z = 0;
};
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(V3 a) { return std::sqrt(dot(a, a)); }
V3 scale(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
V3 add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 unit(V3 a) { return scale(a, 1.0 / length(a)); }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 v3(const Value& v) { return {v[0], v[1], v[2]}; }
Value value(V3 a) { return Value::vector({a.x, a.y, a.z}); }

// PCG3D (Jarzynski and Olano 2020) written out here: an LCG step per word, two rounds of
// cross-word mixing around an xor-shift, all modulo 2^32.
std::array<uint32_t, 3> pcg3d(uint32_t x, uint32_t y, uint32_t z) {
  uint32_t v[3] = {x, y, z};
  for (auto& w : v) w = w * 1664525u + 1013904223u;
  auto mix = [&] {
    v[0] += v[1] * v[2];
    v[1] += v[2] * v[0];
    v[2] += v[0] * v[1];
  };
  mix();
  for (auto& w : v) w ^= w >> 16u;
  mix();
  return {v[0], v[1], v[2]};
}

double hashUnit(uint32_t h) { return std::ldexp(static_cast<double>(h >> 8u), -24); }
uint32_t cellBits(double x) { return static_cast<uint32_t>(static_cast<int32_t>(std::floor(x))); }

// 2D value noise: the PCG3D lattice value of each corner (cell (x, y, 0), first word), the
// fade written as smoothstep's cubic with its leading constant `three` (3), and the four
// corners weighted bilinearly (the node nests three mixes).
double valueNoiseOracle(double x, double y, double three = 3.0) {
  double fx = x - std::floor(x), fy = y - std::floor(y);
  double ux = three * fx * fx - 2 * fx * fx * fx, uy = three * fy * fy - 2 * fy * fy * fy;
  uint32_t cx = cellBits(x), cy = cellBits(y);
  auto l = [](uint32_t i, uint32_t j) { return hashUnit(pcg3d(i, j, 0)[0]); };
  return (1 - ux) * (1 - uy) * l(cx, cy) + ux * (1 - uy) * l(cx + 1, cy) + (1 - ux) * uy * l(cx, cy + 1) +
         ux * uy * l(cx + 1, cy + 1);
}

// fbm with the node's defaults (4 octaves, lacunarity 2, gain 1/2): octave i at 2^i p
// shifted by i `offset`, weighted 2^-i, normalised by the weights' sum 15/8.
double fbmOracle(double x, double y, double offsetX = 17.31, double offsetY = 9.73) {
  double sum = 0;
  for (int i = 0; i < 4; ++i) sum += std::ldexp(valueNoiseOracle(std::ldexp(x, i) + i * offsetX, std::ldexp(y, i) + i * offsetY), -i);
  return sum / 1.875;
}

// Voronoi F1 by brute force over the 5x5 cells around p, each point orbiting its cell's
// centre `centre` (0.5) as the node's default animation does: centre + jitter/2
// (sin(phase + 2 pi h.x), cos(phase + 2 pi h.y)), h the PCG3D bits of the cell.
double voronoiF1Oracle(double x, double y, double jitter, double phase, double centre = 0.5) {
  double best = 1e30;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      double cx = std::floor(x) + i, cy = std::floor(y) + j;
      auto h = pcg3d(cellBits(cx), cellBits(cy), 0);
      double px = cx + centre + jitter * 0.5 * std::sin(phase + 2 * std::numbers::pi * hashUnit(h[0]));
      double py = cy + centre + jitter * 0.5 * std::cos(phase + 2 * std::numbers::pi * hashUnit(h[1]));
      best = std::min(best, std::hypot(px - x, py - y));
    }
  return best;
}

// The node's documented tolerance (NodeSpec::tolerance).
double toleranceOf(const std::string& type) { return defaultRegistry().find(type)->tolerance; }

// What a case gives a node's port: its "inputs" entry, else the builtin of the same meaning.
Value given(const ProbeCase& c, const std::string& port) {
  for (const auto& [name, v] : c.inputs)
    if (name == port) return v;
  if (port == "normal") return c.env.normal;
  if (port == "view") return c.env.viewDirection;
  if (port == "position") return c.env.worldPosition;
  if (port == "time") return c.env.time;
  return Value::ofType(Type::Invalid);
}
bool has(const ProbeCase& c, const std::string& port) {
  for (const auto& [name, v] : c.inputs)
    if (name == port) return true;
  return false;
}

// The float32 dot product, as a GPU without fused operations forms it.
float dot32(const Value& a, const Value& b) {
  float s = 0;
  for (int i = 0; i < 3; ++i) s += static_cast<float>(a[i]) * static_cast<float>(b[i]);
  return s;
}

// The angle between the normal and the view, from atan2 of the tangential and normal parts.
double incidence(V3 n, V3 v) {
  V3 nn = unit(n);
  double along = dot(nn, v);
  return std::atan2(length(sub(v, scale(nn, along))), along);
}

// Fresnel reflectance from the amplitude laws, in angles (not the node's cosine form).
double fresnelOracle(double thetaI, double n1, double n2) {
  if (thetaI <= 0) return std::pow((n1 - n2) / (n1 + n2), 2);
  double s = n1 / n2 * std::sin(thetaI);
  if (s >= 1) return 1.0;
  double thetaT = std::asin(s);
  double rs = -std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
  double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
  return 0.5 * (rs * rs + rp * rp);
}

// Snell's law in angles: the transmitted direction, or nullopt past the critical angle.
std::optional<V3> snellOracle(V3 n, V3 v, double n1, double n2) {
  V3 nn = unit(n), vv = unit(v);
  double thetaI = incidence(nn, vv);
  double s = n1 / n2 * std::sin(thetaI);
  if (s > 1) return std::nullopt;
  V3 tangent = sub(vv, scale(nn, dot(nn, vv)));
  double t = length(tangent);
  V3 along = t > 0 ? scale(tangent, -1.0 / t) : V3{};
  return add(scale(along, s), scale(nn, -std::sqrt(1 - s * s)));
}

std::vector<Value> eval(const std::string& type, const nlohmann::json& options, const ProbeCase& c,
                        std::vector<std::pair<std::string, Value>> inputs) {
  const NodeSpec* spec = defaultRegistry().find(type);
  if (!spec) throw std::runtime_error("no node " + type);
  return evaluateNode(*spec, options, inputs, c.env);
}

// One region: "" when the case reaches it (and its oracles hold), else why not.
using Check = std::function<std::string(const ProbeCase&)>;
std::string near(double got, double want, double tol, const std::string& what) {
  if (std::abs(got - want) <= tol) return "";
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s = %.17g, the oracle says %.17g", what.c_str(), got, want);
  return buf;
}
std::string all(std::initializer_list<std::string> parts) {
  std::string s;
  for (const auto& p : parts)
    if (!p.empty()) s += (s.empty() ? "" : "; ") + p;
  return s;
}

// The Fresnel models at (normal, view): reflectance per model and direction against F.
// `tol`: where F is ill-conditioned, what float32 rounding of the unit vectors (the node
// takes N.V as the cosine; a rounded unit vector is off by up to 1e-7) can do to it.
std::string fresnelIs(const ProbeCase& c, const std::string& direction, double exact, double schlick, double tol = 1e-9) {
  std::vector<std::pair<std::string, Value>> in = {{"normal", given(c, "normal")}, {"view", given(c, "view")}};
  std::string s;
  double e = eval("fresnel", {{"model", "exact"}, {"direction", direction}}, c, in)[0][0];
  double h = eval("fresnel", {{"model", "schlick"}, {"direction", direction}}, c, in)[0][0];
  return all({near(e, exact, tol, "fresnel exact " + direction), near(h, schlick, tol, "fresnel schlick " + direction)});
}

std::string refractIs(const ProbeCase& c, const std::string& direction, std::optional<V3> t, V3 reflection) {
  std::vector<std::pair<std::string, Value>> in = {{"normal", given(c, "normal")}, {"view", given(c, "view")}};
  auto out = eval("refract_dir", {{"direction", direction}}, c, in);
  double tir = out[1][0];
  V3 d = v3(out[0]);
  V3 want = t ? *t : unit(reflection);
  std::string why = near(tir, t ? 0 : 1, 0, "refract_dir tir");
  double err = length(sub(d, want));
  if (err > 1e-9) why = all({why, near(err, 0, 1e-9, "refract_dir |direction - Snell's|")});
  return why;
}

double schlick(double c, double f0) { return f0 + (1 - f0) * std::pow(1 - c, 5); }

// The normal faces the viewer (N.V > 0 in float32) and the angle from below is `want`.
std::string fromBelow(const ProbeCase& c, const std::function<std::string(double theta, double critical)>& region) {
  Value n = given(c, "normal"), v = given(c, "view");
  if (!(dot32(n, v) > 0)) return "N.V <= 0 in float32: the node clamps to grazing instead";
  if (c.options.value("fresnel", nlohmann::json::object()).value("direction", "") != "water_to_air" ||
      c.options.value("refract_dir", nlohmann::json::object()).value("direction", "") != "water_to_air")
    return "fresnel and refract_dir do not run from below (options direction = water_to_air)";
  return region(incidence(v3(n), v3(v)), std::asin(1 / kIor));
}


// The math vocabulary's guards, from their documented values: the float32 argument the
// GPU sees, and each node the case is limited to at it.
float f32(const ProbeCase& c, const std::string& port) { return static_cast<float>(given(c, port)[0]); }
double vocabulary(const ProbeCase& c, const std::string& type) {
  std::vector<std::pair<std::string, Value>> in;
  for (const auto& [port, v] : c.inputs) in.emplace_back(port, v);
  return eval(type, nlohmann::json::object(), c, in)[0][0];
}
bool limitedTo(const ProbeCase& c, const std::string& type) {
  return std::find(c.nodes.begin(), c.nodes.end(), type) != c.nodes.end();
}
// Each listed node of the case against what the oracle says it must give there.
std::string eachNode(const ProbeCase& c, const std::map<std::string, double>& want, double relTol) {
  std::string why;
  if (c.nodes.empty()) return "the case names no nodes";
  for (const auto& type : c.nodes) {
    auto w = want.find(type);
    if (w == want.end()) {
      why = all({why, "no oracle for node " + type});
      continue;
    }
    why = all({why, near(vocabulary(c, type), w->second, relTol * std::max(1.0, std::abs(w->second)), type)});
  }
  return why;
}

const std::map<std::string, Check>& checks() {
  static const std::map<std::string, Check> m = {
      {"grazing",
       [](const ProbeCase& c) {
         if (dot32(given(c, "normal"), given(c, "view")) != 0.0f) return std::string("N.V is not 0 in float32");
         // At 90 degrees the amplitude laws give |rs| = |rp| = 1 from either side.
         return all({fresnelIs(c, "air_to_water", fresnelOracle(std::numbers::pi / 2, 1, kIor), 1),
                     fresnelIs(c, "water_to_air", 1, 1)});
       }},
      {"back_facing",
       [](const ProbeCase& c) {
         if (!(dot32(given(c, "normal"), given(c, "view")) < 0)) return std::string("N.V is not negative in float32");
         return fresnelIs(c, "air_to_water", 1, 1);  // clamped to grazing
       }},
      {"normal_incidence_clamped",
       [](const ProbeCase& c) {
         if (!(dot32(given(c, "normal"), given(c, "view")) > 1)) return std::string("N.V does not exceed 1 in float32");
         V3 n = v3(given(c, "normal"));
         return all({fresnelIs(c, "air_to_water", fresnelOracle(0, 1, kIor), 0.02),
                     refractIs(c, "air_to_water", scale(unit(n), -1), {})});
       }},
      {"total_internal_reflection",
       [](const ProbeCase& c) {
         return fromBelow(c, [&](double theta, double critical) {
           if (!(theta > critical + 1e-3)) return std::string("not past the critical angle");
           V3 n = unit(v3(given(c, "normal"))), v = unit(v3(given(c, "view")));
           return all({fresnelIs(c, "water_to_air", 1, 1),
                       refractIs(c, "water_to_air", std::nullopt, sub(scale(n, 2 * dot(n, v)), v))});
         });
       }},
      {"critical_angle",
       [](const ProbeCase& c) {
         return fromBelow(c, [&](double theta, double critical) {
           // Within float32 rounding of the view (a few 1e-8 rad): F is 1 to within the
           // square-root conditioning there, 1e-3.
           if (!(std::abs(theta - critical) < 1e-6)) return std::string("not within 1e-6 rad of the critical angle");
           std::vector<std::pair<std::string, Value>> in = {{"normal", given(c, "normal")}, {"view", given(c, "view")}};
           double e = eval("fresnel", {{"model", "exact"}, {"direction", "water_to_air"}}, c, in)[0][0];
           return all({near(e, fresnelOracle(theta, kIor, 1), 1e-7, "fresnel exact"), near(e, 1, 2e-3, "fresnel exact")});
         });
       }},
      {"near_critical_refracting",
       [](const ProbeCase& c) {
         return fromBelow(c, [&](double theta, double critical) {
           if (!(theta < critical && theta > critical - 1e-3)) return std::string("not within 1e-3 rad inside the critical angle");
           V3 n = v3(given(c, "normal")), v = v3(given(c, "view"));
           auto schlickBelow = [](double th) { return schlick(std::sqrt(1 - std::pow(kIor * std::sin(th), 2)), 0.02); };
           double tol = 1e-9;
           for (double d : {-1e-7, 1e-7})
             tol = std::max({tol, std::abs(fresnelOracle(theta + d, kIor, 1) - fresnelOracle(theta, kIor, 1)),
                             std::abs(schlickBelow(theta + d) - schlickBelow(theta))});
           return all({fresnelIs(c, "water_to_air", fresnelOracle(theta, kIor, 1), schlickBelow(theta), tol),
                       refractIs(c, "water_to_air", snellOracle(n, v, kIor, 1), {})});
         });
       }},
      {"near_critical_reflecting",
       [](const ProbeCase& c) {
         return fromBelow(c, [&](double theta, double critical) {
           if (!(theta > critical && theta < critical + 1e-3)) return std::string("not within 1e-3 rad past the critical angle");
           V3 n = unit(v3(given(c, "normal"))), v = unit(v3(given(c, "view")));
           return all({fresnelIs(c, "water_to_air", 1, 1),
                       refractIs(c, "water_to_air", std::nullopt, sub(scale(n, 2 * dot(n, v)), v))});
         });
       }},
      {"normal_incidence_from_below",
       [](const ProbeCase& c) {
         return fromBelow(c, [&](double theta, double) {
           if (theta != 0) return std::string("not normal incidence");
           V3 v = v3(given(c, "view"));
           return all({fresnelIs(c, "water_to_air", fresnelOracle(0, kIor, 1), 0.02),
                       refractIs(c, "water_to_air", scale(unit(v), -1), {})});
         });
       }},
      {"zero_vector",
       [](const ProbeCase& c) {
         for (const char* port : {"normal", "view", "light"})
           if (has(c, port) && length(v3(given(c, port))) == 0) {
             if (std::string(port) == "light") {
               double l = eval("lambert", nlohmann::json::object(), c, {{"light", given(c, "light")}})[0][0];
               return near(l, 0, 0, "lambert with no light");
             }
             return fresnelIs(c, "air_to_water", 1, 1);  // no angle: grazing
           }
         return std::string("no normal, view or light input is the zero vector");
       }},
      {"underflowing_length",
       [](const ProbeCase& c) {
         Value n = given(c, "normal");
         float l2 = dot32(n, n);
         if (!(l2 < 1.17549435e-38f)) return std::string("the squared length does not underflow float32");
         if (length(v3(n)) == 0) return std::string("the normal is zero, not tiny");
         auto r = eval("reflect_dir", nlohmann::json::object(), c, {{"normal", n}, {"view", Value::vector({0, 1, 0})}})[0];
         return std::string(r.allFinite() ? "" : "reflect_dir not finite");
       }},
      {"gerstner_cusp",
       [](const ProbeCase& c) {
         // Sum Q k A over the waves, A = Q / k by default: the cusp limit is 1.
         const auto& waves = c.options.at("gerstner_waves").at("waves");
         double sum = 0;
         for (const auto& w : waves) {
           double q = w.at("steepness"), k = 2 * std::numbers::pi / w.at("wavelength").get<double>();
           sum += q * k * w.value("amplitude", q / k);
         }
         if (std::abs(sum - 1) > 1e-12) return std::string("sum Q k A is not 1: not at the cusp limit");
         const auto& w = waves.at(0);
         double k = 2 * std::numbers::pi / w.at("wavelength").get<double>(), q = w.at("steepness"), a = q / k;
         double omega = std::sqrt(9.81 * k);
         double t = c.env.time[0];
         auto displaced = [&](double x0, double z0) {
           double th = k * x0 - omega * t;  // direction (1, 0), phase 0
           return V3{x0 + q * a * std::cos(th), a * std::sin(th), z0};
         };
         V3 p = v3(given(c, "position"));
         auto out = eval("gerstner_waves", c.options.at("gerstner_waves"), c, {{"position", given(c, "position")}});
         V3 normal = v3(out[1]);
         if (!out[1].allFinite()) return std::string("normal not finite");
         double h = 1e-5;
         V3 dx = scale(sub(displaced(p.x + h, p.z), displaced(p.x - h, p.z)), 0.5 / h);
         V3 dz = scale(sub(displaced(p.x, p.z + h), displaced(p.x, p.z - h)), 0.5 / h);
         V3 fd = cross(dz, dx);
         if (length(fd) < 1e-6) {
           // The cusp itself: the surface folds, no normal exists; the node must stay unit.
           return near(length(normal), 1, 1e-9, "|normal| at the cusp point");
         }
         return near(length(sub(normal, unit(fd))), 0, 1e-6, "|normal - finite-difference normal|");
       }},
      {"huge_time",
       [](const ProbeCase& c) {
         double t = c.env.time[0];
         // float32 spacing at t: u_time has lost digits (>= 2^-10 s).
         float tf = static_cast<float>(t);
         if (!(std::nextafter(tf, INFINITY) - tf >= 0x1p-10f)) return std::string("time too small to lose float32 digits");
         // One Gerstner wave, phase k x - omega t taken modulo 2 pi in long double.
         nlohmann::json waves = nlohmann::json::parse(R"([{"direction": [1, 0], "steepness": 0.5, "wavelength": 10}])");
         double k = 2 * std::numbers::pi / 10, q = 0.5, a = q / k;
         long double omega = std::sqrt(9.81L * k);
         double phase = static_cast<double>(std::fmod(-omega * static_cast<long double>(t), 2 * 3.141592653589793238462643L));
         auto out = eval("gerstner_waves", {{"waves", waves}}, c, {{"position", Value::vector({3, 0, 0})}});
         V3 want{3 + q * a * std::cos(k * 3 + phase), a * std::sin(k * 3 + phase), 0};
         return near(length(sub(v3(out[0]), want)), 0, 1e-9, "|gerstner position - oracle| at the time");
       }},
      {"huge_coordinates",
       [](const ProbeCase& c) {
         double m = 0;
         for (const char* port : {"position", "p", "uv"})
           if (has(c, port)) {
             Value v = given(c, port);
             for (int i = 0; i < v.size(); ++i) m = std::max(m, std::abs(v[i]));
           }
         if (!(m >= 1e5)) return std::string("no coordinate of 1e5 or more");
         // float32 spacing at m is 2^-7 m or more: the phase of a 10 m wave keeps few digits.
         if (!has(c, "position")) return std::string();
         V3 p = v3(given(c, "position"));
         nlohmann::json waves = nlohmann::json::parse(R"([{"direction": [1, 0], "steepness": 0.5, "wavelength": 10}])");
         double k = 2 * std::numbers::pi / 10, q = 0.5, a = q / k;
         double th = std::fmod(k * p.x, 2 * std::numbers::pi);
         auto out = eval("gerstner_waves", {{"waves", waves}}, c, {{"position", value(p)}});
         V3 want{p.x + q * a * std::cos(th), a * std::sin(th), p.z};
         return near(length(sub(v3(out[0]), want)), 0, 1e-6, "|gerstner position - oracle| at 1e5 m");
       }},
      {"sky_depth",
       [](const ProbeCase& c) {
         if (given(c, "depth")[0] != 1.0 || c.env.sceneDepth[0] != 1.0) return std::string("depth is not exactly 1");
         double far = c.env.cameraNearFar[1];
         double l = eval("linearize_depth", nlohmann::json::object(), c, {{"depth", Value::scalar(1)}})[0][0];
         return near(l, far, 1e-9 * far, "linear depth of the sky");
       }},
      {"infinite_far_sky",
       [](const ProbeCase& c) {
         if (!std::isinf(c.env.cameraNearFar[1]) || c.env.sceneDepth[0] != 1.0) return std::string("not sky with an infinite far plane");
         double l = eval("linearize_depth", nlohmann::json::object(), c, {{"depth", Value::scalar(1)}})[0][0];
         return near(l, 1e30, 0, "linear depth (the documented cap)");
       }},
      {"infinite_far",
       [](const ProbeCase& c) {
         double d = given(c, "depth")[0], n = c.env.cameraNearFar[0];
         if (!std::isinf(c.env.cameraNearFar[1]) || !(d < 1)) return std::string("not an infinite far plane below the sky");
         double l = eval("linearize_depth", nlohmann::json::object(), c, {{"depth", Value::scalar(d)}})[0][0];
         return near(l, n / (1 - d), 1e-9 * l, "linear depth, n / (1 - d)");
       }},
      {"near_plane_depth",
       [](const ProbeCase& c) {
         if (given(c, "depth")[0] != 0) return std::string("depth is not 0");
         double l = eval("linearize_depth", nlohmann::json::object(), c, {{"depth", Value::scalar(0)}})[0][0];
         return near(l, c.env.cameraNearFar[0], 1e-12, "linear depth on the near plane");
       }},
      {"negative_thickness",
       [](const ProbeCase& c) {
         if (!(given(c, "distance")[0] < 0)) return std::string("distance is not negative");
         auto t = eval("absorption", nlohmann::json::object(), c, {{"distance", given(c, "distance")}})[0];
         return all({near(t[0], 1, 0, "transmittance R"), near(t[1], 1, 0, "G"), near(t[2], 1, 0, "B")});
       }},
      {"huge_thickness",
       [](const ProbeCase& c) {
         // Pope & Fry (1997) pure-water absorption at 680, 550 and 440 nm, 1/m, as tabulated.
         const double table[3] = {0.340, 0.0565, 0.00922};
         double d = given(c, "distance")[0];
         for (double a : table)
           if (!(a * d > 745)) return std::string("exp(-a d) does not underflow double: not a huge thickness");
         auto t = eval("absorption", nlohmann::json::object(), c, {{"distance", given(c, "distance")}})[0];
         std::string why;
         for (int i = 0; i < 3; ++i) why = all({why, near(t[i], std::exp(-table[i] * d), 0, "transmittance")});
         return why;
       }},
      {"beer_lambert_path",
       [](const ProbeCase& c) {
         // Pope & Fry (1997) pure-water absorption at 680, 550 and 440 nm, 1/m, as tabulated.
         const double table[3] = {0.340, 0.0565, 0.00922};
         double d = given(c, "distance")[0];
         auto t = eval("absorption", nlohmann::json::object(), c, {{"distance", given(c, "distance")}})[0];
         std::string why;
         for (int i = 0; i < 3; ++i) {
           double want = std::exp(-table[i] * d);
           if (!(want > 1e-3 && want < 0.999)) return std::string("a channel's transmittance is not strictly inside (0, 1)");
           // The path length reaches every channel: 1e-4 more of it moves T by more than 4 tolerances.
           if (!(std::abs(std::exp(-table[i] * d * 1.0001) - want) > 4 * toleranceOf("absorption")))
             return std::string("the transmittance does not depend on the path length beyond the tolerance");
           why = all({why, near(t[i], want, 1e-12, "transmittance")});
         }
         return why;
       }},
      {"noise_cell_interior",
       [](const ProbeCase& c) {
         Value p = given(c, "p");
         for (int i = 0; i < 2; ++i) {
           double f = p[i] - std::floor(p[i]);
           if (!(f > 0.05 && f < 0.95)) return std::string("p is not inside a lattice cell (fade weights near 0 or 1)");
         }
         std::vector<std::pair<std::string, Value>> in = {{"p", p}};
         double vn = eval("value_noise", nlohmann::json::object(), c, in)[0][0];
         double fb = eval("fbm", nlohmann::json::object(), c, in)[0][0];
         double ca = eval("voronoi_caustics", nlohmann::json::object(), c, in)[0][0];
         // The caustics' defaults: scale 4, jitter 1, two layers averaged, the second at
         // 1.3 q + 5 orbiting 1.2 times as fast; each (1 - clamp(F1, 0, 1))^3.
         const NodeSpec& spec = *defaultRegistry().find("voronoi_caustics");
         double speed = spec.options[static_cast<size_t>(spec.optionIndex("speed"))].defaultValue.get<double>();
         double t = c.env.time[0];
         auto caustics = [&](double centre, bool* clamped) {
           double qx = p[0] * 4, qy = p[1] * 4;
           double f1 = voronoiF1Oracle(qx, qy, 1.0, std::fmod(speed * t, 2 * std::numbers::pi), centre);
           double f2 = voronoiF1Oracle(qx * 1.3 + 5, qy * 1.3 + 5, 1.0, std::fmod(1.2 * speed * t, 2 * std::numbers::pi), centre);
           *clamped = f1 >= 1 || f2 >= 1;
           return 0.5 * (std::pow(1 - std::min(f1, 1.0), 3) + std::pow(1 - std::min(f2, 1.0), 3));
         };
         bool clamped = false, unused = false;
         double causticsWant = caustics(0.5, &clamped);
         if (clamped) return std::string("a caustic layer's F1 is 1 or more: the clamp hides the feature points");
         // The named constants reach the result: a 1e-4 change of the fade's 3, of the first
         // octave offset, of the feature points' centre moves it by more than 4 tolerances.
         if (!(std::abs(valueNoiseOracle(p[0], p[1], 3.0001) - valueNoiseOracle(p[0], p[1])) > 4 * toleranceOf("value_noise")))
           return std::string("value noise does not depend on the fade beyond its tolerance");
         if (!(std::abs(fbmOracle(p[0], p[1], 17.32) - fbmOracle(p[0], p[1])) > 4 * toleranceOf("fbm")))
           return std::string("fbm does not depend on its octave offsets beyond its tolerance");
         if (!(std::abs(caustics(0.5001, &unused) - causticsWant) > 4 * toleranceOf("voronoi_caustics")))
           return std::string("the caustics do not depend on the feature points beyond their tolerance");
         return all({near(vn, valueNoiseOracle(p[0], p[1]), 1e-12, "value_noise"), near(fb, fbmOracle(p[0], p[1]), 1e-12, "fbm"),
                     near(ca, causticsWant, 1e-12, "voronoi_caustics")});
       }},
      {"voronoi_f1_above_one",
       [](const ProbeCase& c) {
         // F1 by brute force over 5x5 cells, each point orbiting its cell centre as the
         // node's default animation does: 0.5 + jitter/2 (sin(phase + 2 pi h.x),
         // cos(phase + 2 pi h.y)), h the PCG3D bits of the cell (pcg3d above), phase =
         // speed t modulo 2 pi.
         Value p = given(c, "p");
         double jitter = has(c, "jitter") ? given(c, "jitter")[0] : 1.0;
         const NodeSpec& spec = *defaultRegistry().find("voronoi");
         double speed = spec.options[static_cast<size_t>(spec.optionIndex("speed"))].defaultValue.get<double>();
         double phase = std::fmod(speed * c.env.time[0], 2 * std::numbers::pi);
         double best = 1e30;
         for (int i = -2; i <= 2; ++i)
           for (int j = -2; j <= 2; ++j) {
             double cx = std::floor(p[0]) + i, cy = std::floor(p[1]) + j;
             auto h = pcg3d(static_cast<uint32_t>(static_cast<int32_t>(cx)), static_cast<uint32_t>(static_cast<int32_t>(cy)), 0);
             double px = cx + 0.5 + jitter * 0.5 * std::sin(phase + 2 * std::numbers::pi * std::ldexp(h[0] >> 8u, -24));
             double py = cy + 0.5 + jitter * 0.5 * std::cos(phase + 2 * std::numbers::pi * std::ldexp(h[1] >> 8u, -24));
             best = std::min(best, std::hypot(px - p[0], py - p[1]));
           }
         if (!(best > 1)) return std::string("F1 is not above 1: some point lies within distance 1");
         std::vector<std::pair<std::string, Value>> in = {{"p", p}};
         for (const char* port : {"jitter", "scale"})
           if (has(c, port)) in.emplace_back(port, given(c, port));
         double full = eval("voronoi", {{"search", "3x3"}}, c, in)[0][0];
         double block = eval("voronoi", {{"search", "2x2"}}, c, in)[0][0];
         return all({near(full, best, 1e-12, "voronoi 3x3 F1"), block >= best ? "" : "the 2x2 F1 is below the true F1"});
       }},
      {"pow_base_zero",
       [](const ProbeCase& c) {
         double x = given(c, "x")[0], y = given(c, "y")[0];
         if (x != 0) return std::string("the base is not 0");
         double r = eval("pow", nlohmann::json::object(), c, {{"x", given(c, "x")}, {"y", given(c, "y")}})[0][0];
         return near(r, y > 0 ? 0.0 : 1.0, 0, "safe pow(0, y)");
       }},
      {"pow_negative_base",
       [](const ProbeCase& c) {
         if (!(given(c, "x")[0] < 0)) return std::string("the base is not negative");
         double r = eval("pow", nlohmann::json::object(), c, {{"x", given(c, "x")}, {"y", given(c, "y")}})[0][0];
         return near(r, 0, 0, "safe pow of a negative base");
       }},
      {"smoothstep_equal_edges",
       [](const ProbeCase& c) {
         double e0 = given(c, "edge0")[0], e1 = given(c, "edge1")[0], x = given(c, "x")[0];
         if (e0 != e1) return std::string("the edges differ");
         double r = eval("smoothstep", nlohmann::json::object(), c,
                         {{"edge0", given(c, "edge0")}, {"edge1", given(c, "edge1")}, {"x", given(c, "x")}})[0][0];
         return near(r, x < e0 ? 0.0 : 1.0, 0, "smoothstep with equal edges (a step)");
       }},
      {"smoothstep_reversed_edges",
       [](const ProbeCase& c) {
         double e0 = given(c, "edge0")[0], e1 = given(c, "edge1")[0], x = given(c, "x")[0];
         if (!(e0 > e1)) return std::string("the edges are not reversed");
         double t = (x - e1) / (e0 - e1);
         double r = eval("smoothstep", nlohmann::json::object(), c,
                         {{"edge0", given(c, "edge0")}, {"edge1", given(c, "edge1")}, {"x", given(c, "x")}})[0][0];
         return near(r, 1 - t * t * (3 - 2 * t), 1e-15, "reversed smoothstep, 1 - smoothstep(e1, e0, x)");
       }},
      {"hash_bit_pattern",
       [](const ProbeCase& c) {
         // PCG3D (pcg3d above) on the int32 cell.
         Value p = given(c, "p");
         if (!(std::abs(p[0]) >= 1e7)) return std::string("the cell is not at 1e7");
         auto cell = [&](int i) { return static_cast<uint32_t>(static_cast<int32_t>(std::floor(p[i]))); };
         auto v = pcg3d(cell(0), cell(1), cell(2));
         auto out = eval("hash", nlohmann::json::object(), c, {{"p", p}})[1];
         std::string why;
         for (int i = 0; i < 3; ++i) why = all({why, near(out[i], std::ldexp(static_cast<double>(v[i] >> 8u), -24), 0, "hash bits")});
         return why;
       }},
      {"ssr_behind_camera",
       [](const ProbeCase& c) {
         // The reflected ray, in view space, heads behind the camera (z grows past 0).
         V3 p = v3(given(c, "position")), n = unit(v3(given(c, "normal")));
         V3 v = unit(sub(v3(c.env.cameraPosition), p));
         V3 r = sub(scale(n, 2 * dot(n, v)), v);
         const Value& m = c.env.view;  // column-major
         auto viewZ = [&](V3 q) { return m[2] * q.x + m[6] * q.y + m[10] * q.z + m[14]; };
         double z0 = viewZ(p), dz = viewZ(add(p, r)) - z0;
         if (!(z0 < 0 && dz > 0)) return std::string("the reflected ray does not head behind the camera");
         return std::string();
       }},
      {"ssr_toward_camera",
       [](const ProbeCase& c) {
         V3 p = v3(given(c, "position")), n = unit(v3(given(c, "normal")));
         V3 v = unit(sub(v3(c.env.cameraPosition), p));
         V3 r = sub(scale(n, 2 * dot(n, v)), v);
         return near(dot(r, v), 1, 1e-6, "R.V (the reflection goes back to the camera)");
       }},
      {"non_positive_argument",
       [](const ProbeCase& c) {
         float x = f32(c, "x");
         if (!(x <= 0)) return std::string("x is positive in float32");
         const double floor = std::numeric_limits<float>::min();  // the documented floor
         return eachNode(c, {{"log", std::log(floor)}, {"log2", -126.0}, {"sqrt", 0.0}, {"inversesqrt", std::ldexp(1.0, 63)}},
                         1e-15);
       }},
      {"inverse_trig_beyond_one",
       [](const ProbeCase& c) {
         float x = f32(c, "x");
         if (!(std::abs(x) > 1)) return std::string("|x| is not above 1 in float32");
         return eachNode(c, {{"asin", x > 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2}, {"acos", x > 0 ? 0.0 : std::numbers::pi}}, 1e-15);
       }},
      {"mod_by_zero",
       [](const ProbeCase& c) {
         if (f32(c, "y") != 0) return std::string("y is not 0");
         return eachNode(c, {{"mod", 0.0}}, 0);
       }},
      {"atan2_origin",
       [](const ProbeCase& c) {
         if (f32(c, "x") != 0 || f32(c, "y") != 0) return std::string("(x, y) is not the origin");
         return eachNode(c, {{"atan2", 0.0}}, 0);
       }},
      {"exponential_overflow",
       [](const ProbeCase& c) {
         double x = f32(c, "x");
         // e^x beyond the largest float: the raw built-ins give +inf (and sinh inf - inf).
         if (!(std::exp(x) > std::numeric_limits<float>::max())) return std::string("e^x does not overflow float32");
         if (limitedTo(c, "exp2") && !(std::exp2(x) > std::numeric_limits<float>::max()))
           return std::string("2^x does not overflow float32");
         return eachNode(c, {{"exp", std::exp(88.0)}, {"exp2", std::ldexp(1.0, 127)}, {"sinh", (std::exp(88.0) - std::exp(-88.0)) / 2},
                             {"cosh", (std::exp(88.0) + std::exp(-88.0)) / 2}, {"tanh", std::tanh(10.0)}},
                         1e-14);
       }},
      {"tan_pole",
       [](const ProbeCase& c) {
         double x = f32(c, "x");
         // Within float32 rounding of an odd multiple of pi/2: cos is (nearly) 0.
         double k = (x - std::numbers::pi / 2) / std::numbers::pi;
         if (!(std::abs(k - std::round(k)) * std::numbers::pi < 1e-7)) return std::string("x is not within 1e-7 of a pole");
         return eachNode(c, {{"tan", std::sin(x) / std::cos(x)}}, 1e-9);
       }},
      {"refract_total_internal_reflection",
       [](const ProbeCase& c) {
         V3 i = unit(v3(given(c, "incident"))), n = unit(v3(given(c, "normal")));
         double eta = given(c, "eta")[0];
         // Snell in angles: sin t = eta sin i beyond 1 has no transmitted ray.
         double sinI = length(cross(i, n));
         if (!(eta * sinI > 1 + 1e-6)) return std::string("eta sin(i) is not beyond 1: the ray refracts");
         Value t = eval("refract", nlohmann::json::object(), c,
                        {{"incident", given(c, "incident")}, {"normal", given(c, "normal")}, {"eta", given(c, "eta")}})[0];
         return near(length(v3(t)), 0, 0, "|refract| under total internal reflection");
       }},
      {"inverse_mix_empty_range",
       [](const ProbeCase& c) {
         if (f32(c, "a") != f32(c, "b")) return std::string("the range is not empty");
         return eachNode(c, {{"inverse_mix", 0.0}}, 0);
       }},
      {"no_camera_matrices",
       [](const ProbeCase& c) {
         // Every entry of both matrices is 0: no perspective scale to divide by.
         for (const Value* m : {&c.env.view, &c.env.projection})
           for (int i = 0; i < 16; ++i)
             if (m->size() != 16 || (*m)[i] != 0) return std::string("the view or projection matrix is not zero");
         return std::string();
       }},
      {"screen_uv_outside",
       [](const ProbeCase& c) {
         Value uv = has(c, "screen_uv") ? given(c, "screen_uv") : c.env.screenUv;
         for (int i = 0; i < 2; ++i)
           if (uv[i] < 0 || uv[i] > 1) return std::string();
         return std::string("screen uv inside [0, 1]");
       }},
  };
  return m;
}


// Per vocabulary region, an input value that leaves it: x = 0.5 is positive, inside
// [-1, 1], far from a pole and from overflow; y = 1 is a divisor; eta = 0.75 refracts.
const std::map<std::string, std::pair<std::string, Value>>& vocabularyMiss() {
  static const std::map<std::string, std::pair<std::string, Value>> m = {
      {"non_positive_argument", {"x", Value::scalar(0.5)}},   {"inverse_trig_beyond_one", {"x", Value::scalar(0.5)}},
      {"mod_by_zero", {"y", Value::scalar(1)}},               {"atan2_origin", {"x", Value::scalar(1)}},
      {"exponential_overflow", {"x", Value::scalar(0.5)}},    {"tan_pole", {"x", Value::scalar(0.5)}},
      {"refract_total_internal_reflection", {"eta", Value::scalar(0.75)}},
      {"inverse_mix_empty_range", {"b", Value::scalar(3)}}};
  return m;
}

using test_suite::loadSuite;

TEST(HardCaseRegions, EveryCaseNamesARegionAndReachesIt) {
  ProbeCaseFile suite = loadSuite();
  ASSERT_EQ(suite.cases.size(), 59u);
  for (const auto& c : suite.cases) {
    auto check = checks().find(c.region);
    if (check == checks().end()) {
      ADD_FAILURE() << "case '" << c.name << "' names no known region ('" << c.region << "')";
      continue;
    }
    std::string why = check->second(c);
    EXPECT_EQ(why, "") << "case '" << c.name << "' does not reach region " << c.region;
  }
}

// The checks can fail: the "from below" cases as they were (an upward normal with a
// downward view, N.V < 0, so every node clamped to grazing) are rejected, and so are a
// Gerstner wave train short of the cusp, noise on a lattice point, a path of length 0 and
// each math vocabulary case moved off its guard.
TEST(HardCaseRegions, CasesThatMissTheirRegionAreRejected) {
  ProbeCaseFile suite = loadSuite();
  int rejected = 0, tried = 0;
  for (const auto& c : suite.cases) {
    ProbeCase broken = c;
    if (c.region == "total_internal_reflection" || c.region == "critical_angle" || c.region.rfind("near_critical", 0) == 0 ||
        c.region == "normal_incidence_from_below") {
      for (auto& [port, v] : broken.inputs)
        if (port == "normal") v = Value::vector({0, 1, 0});
      broken.env.normal = Value::vector({0, 1, 0});
    } else if (c.region == "gerstner_cusp") {
      broken.options["gerstner_waves"]["waves"][0]["steepness"] = 0.9;
    } else if (c.region == "noise_cell_interior") {
      for (auto& [port, v] : broken.inputs)
        if (port == "p") v = Value::vector({3, 5});  // a lattice point: the fade weights are 0
    } else if (c.region == "no_camera_matrices") {
      broken.env.view = defaultProbeEnvironment().view;  // the probe's camera, as a node's own case gets it
    } else if (c.region == "beer_lambert_path") {
      for (auto& [port, v] : broken.inputs)
        if (port == "distance") v = Value::scalar(0);  // no path: T = 1 whatever the coefficients
    } else if (auto moved = vocabularyMiss().find(c.region); moved != vocabularyMiss().end()) {
      // The math vocabulary's cases with the input that puts them there moved off it.
      for (auto& [port, v] : broken.inputs)
        if (port == moved->second.first) v = moved->second.second;
    } else {
      continue;
    }
    ++tried;
    rejected += checks().at(c.region)(broken).empty() ? 0 : 1;
  }
  EXPECT_EQ(tried, 11 + 12);
  EXPECT_EQ(rejected, tried);
}

}  // namespace
}  // namespace wg::accuracy
