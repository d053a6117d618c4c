// Every node's own hard case (NodeSpec::hardCases) names the region or branch it exercises
// (nodes/hard_case_regions.h), and this test proves each one reaches it, as
// hard_case_regions_test does for the suite: the case's inputs, rounded to float32 as the
// GPU sees them (inputs it does not set take the port's default or the probe's builtin),
// are shown to lie in the region by a computation written here, independently of the node
// code: float32 dot products, angles from atan2 and Snell's law in angles, sums of Q k A
// and a Gerstner surface written out with its tangent by finite differences, PCG3D and a
// brute-force Voronoi F1, the half vector and the subsurface glow's base from their
// definitions. A third test shows the checks fail: each case moved out of its region
// (a vector made unit, an angle inside the critical one, a coordinate of 1, ...) is rejected.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include <gtest/gtest.h>

#include "accuracy/probe_cases.h"
#include "codegen/cpu_backend.h"
#include "core/node_options.h"
#include "core/ocean_settings.h"
#include "nodes/hard_case_regions.h"
#include "nodes/ocean_readers.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "test_support.h"

namespace wg::accuracy::node_hard_cases {
namespace {

using nodes::HardCaseRegion;

constexpr double kWaterIor = 1.333;

// A node hard case with the region the table gives it.
struct Subject {
  const NodeSpec* spec = nullptr;
  HardCase hc;
  HardCaseRegion region;
  EvalEnvironment env = defaultProbeEnvironment();
};

// The value port `port` has in the case, rounded to float32: the case's input, else the
// port's default or the builtin the probe gives it ("scene_depth": the scene depth the
// probe binds).
Value givenInput(const Subject& s, const std::string& port) {
  if (port == "scene_depth") return toFloat32(s.env.sceneDepth);
  for (const auto& [name, v] : s.hc.inputs)
    if (name == port) return toFloat32(v);
  NodePorts ports = portsOfNode(*s.spec, s.hc.options);
  for (const auto& p : ports.inputs)
    if (p.name == port) {
      if (p.defaultValue) return toFloat32(*p.defaultValue);
      if (p.defaultBuiltin) return toFloat32(s.env.builtin(*p.defaultBuiltin));
    }
  throw std::runtime_error(s.spec->type + " has no input '" + port + "'");
}
bool hasInputPort(const Subject& s, const std::string& port) {
  NodePorts ports = portsOfNode(*s.spec, s.hc.options);
  return std::any_of(ports.inputs.begin(), ports.inputs.end(), [&](const PortSpec& p) { return p.name == port; });
}
// The case's option, else the node's default.
nlohmann::json optionOf(const Subject& s, const std::string& name) {
  if (s.hc.options.contains(name)) return s.hc.options.at(name);
  int i = s.spec->optionIndex(name);
  return i < 0 ? nlohmann::json() : s.spec->options[static_cast<size_t>(i)].defaultValue;
}

std::vector<std::string> portsOf(const Subject& s) {
  std::vector<std::string> out;
  std::string all(s.region.ports);
  for (size_t at = 0; at < all.size();) {
    size_t end = all.find(' ', at);
    if (end == std::string::npos) end = all.size();
    if (end > at) out.push_back(all.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

// float32 arithmetic as a GPU without fused operations does it.
float dotF32(const Value& a, const Value& b) {
  float sum = 0;
  for (int i = 0; i < 3; ++i) sum += static_cast<float>(a[i]) * static_cast<float>(b[i]);
  return sum;
}
std::array<double, 3> unitOf(const Value& v) {
  double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}
double lengthOf(const Value& v) {
  double sum = 0;
  for (int i = 0; i < v.size(); ++i) sum += v[i] * v[i];
  return std::sqrt(sum);
}
// The surface normal the case's directions are measured against: the node's normal input,
// or up for a node without one (a flat surface y = const).
Value surfaceNormal(const Subject& s) {
  return hasInputPort(s, "normal") ? givenInput(s, "normal") : Value::vector({0, 1, 0});
}
// The angle between the surface normal and `dir`, from atan2 of the tangential and normal parts.
double angleTo(const Subject& s, const Value& dir) {
  auto n = unitOf(surfaceNormal(s));
  double along = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2];
  double t0 = dir[0] - along * n[0], t1 = dir[1] - along * n[1], t2 = dir[2] - along * n[2];
  return std::atan2(std::sqrt(t0 * t0 + t1 * t1 + t2 * t2), along);
}

std::string unless(bool ok, const std::string& why) { return ok ? std::string() : why; }
std::string firstFailure(std::initializer_list<std::string> parts) {
  for (const auto& p : parts)
    if (!p.empty()) return p;
  return "";
}
bool everyComponent(const Value& v, const std::function<bool(double)>& f) {
  for (int i = 0; i < v.size(); ++i)
    if (!f(v[i])) return false;
  return true;
}
// Each of the region's ports satisfies `f` in every component.
std::string eachPort(const Subject& s, const std::function<bool(double)>& f, const std::string& what) {
  auto ports = portsOf(s);
  if (ports.empty()) return "the region names no port";
  for (const auto& p : ports)
    if (!everyComponent(givenInput(s, p), f)) return "'" + p + "' is not " + what + " in float32";
  return "";
}

// From below (direction water_to_air), the view facing the normal in float32, and the angle
// of incidence against the critical angle asin(1 / ior) (Snell's law in angles).
std::string fromBelowAt(const Subject& s, const std::function<std::string(double theta, double critical)>& region) {
  if (optionOf(s, "direction") != "water_to_air") return "the node does not run from below (direction = water_to_air)";
  Value v = givenInput(s, "view");
  if (!(dotF32(surfaceNormal(s), v) > 0)) return "N.V <= 0 in float32: the node clamps to grazing instead";
  double ior = optionOf(s, "ior").is_number() ? optionOf(s, "ior").get<double>() : kWaterIor;
  return region(angleTo(s, v), std::asin(1 / ior));
}

// PCG3D written out (as hard_case_regions_test): an LCG step per word, two rounds of
// cross-word mixing around an xor-shift, all modulo 2^32.
std::array<uint32_t, 3> pcgWords(uint32_t x, uint32_t y, uint32_t z) {
  uint32_t w[3] = {x, y, z};
  for (auto& u : w) u = u * 1664525u + 1013904223u;
  auto mix = [&] {
    w[0] += w[1] * w[2];
    w[1] += w[2] * w[0];
    w[2] += w[0] * w[1];
  };
  mix();
  for (auto& u : w) u ^= u >> 16u;
  mix();
  return {w[0], w[1], w[2]};
}
uint32_t latticeBits(double x) { return static_cast<uint32_t>(static_cast<int32_t>(std::floor(x))); }

// Voronoi F1 by brute force over the 5x5 cells around q, static points at
// 0.5 + jitter (h - 1/2) in their cells, h the PCG3D bits of the cell.
double bruteForceF1(double x, double y, double jitter) {
  double best = 1e30;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      double cx = std::floor(x) + i, cy = std::floor(y) + j;
      auto h = pcgWords(latticeBits(cx), latticeBits(cy), 0);
      double px = cx + 0.5 + jitter * (std::ldexp(h[0] >> 8u, -24) - 0.5);
      double py = cy + 0.5 + jitter * (std::ldexp(h[1] >> 8u, -24) - 0.5);
      best = std::min(best, std::hypot(px - x, py - y));
    }
  return best;
}

// The subsurface glow's base saturate(V.(-H)), H = normalize(L + N distortion), from its
// definition (the stylized water shader's fake subsurface), vectors normalised first.
double subsurfaceBase(const Subject& s) {
  auto l = unitOf(givenInput(s, "light")), n = unitOf(givenInput(s, "normal")), v = unitOf(givenInput(s, "view"));
  double d = givenInput(s, "distortion")[0];
  double h[3] = {l[0] + n[0] * d, l[1] + n[1] * d, l[2] + n[2] * d};
  double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (hl == 0) return 0;
  return std::clamp(-(v[0] * h[0] + v[1] * h[1] + v[2] * h[2]) / hl, 0.0, 1.0);
}

// The sea an ocean reader's case runs on, as the ocean_spectrum node parses it.
ocean::OceanSettings caseSea(const Subject& s) {
  const NodeSpec& spectrum = *defaultRegistry().find("ocean_spectrum");
  return parseOptions(spectrum, completeOptions(spectrum, s.hc.oceanOptions))->as<ocean::OceanSettings>();
}

// J of the case's sea at its point at t = 0 (the ocean_surface node's reference there).
double caseJacobian(const Subject& s) {
  TextureCache textures;
  Value sea = evaluateNode(*defaultRegistry().find("ocean_spectrum"), s.hc.oceanOptions, {}, EvalEnvironment{},
                           &textures, test::sourceDir())[0];
  const NodeSpec& surface = *defaultRegistry().find("ocean_surface");
  auto outs = evaluateNode(surface, nlohmann::json::object(), {{"ocean", sea}, {"position", givenInput(s, "position")}},
                           EvalEnvironment{}, &textures, test::sourceDir());
  return outs[static_cast<size_t>(surface.outputIndex("jacobian"))][0];
}

// The footprint (metres) ocean_surface's filter reads the case's point at (wg_ocean_footprint).
double caseFootprint(const Subject& s) {
  return nodes::oceanread::footprint(givenInput(s, "position"), givenInput(s, "camera"), givenInput(s, "pixel_angle")[0]);
}

// The wavenumber of angular frequency omega at depth d: omega^2 = g k tanh(k d), by bisection
// (the left side grows with k).
double wavenumberAt(double omega, double depth) {
  double lo = 0, hi = 1;
  while (ocean::kGravity * hi * std::tanh(hi * depth) < omega * omega) hi *= 2;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (ocean::kGravity * mid * std::tanh(mid * depth) < omega * omega ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

using RegionCheck = std::function<std::string(const Subject&)>;

const std::map<std::string, RegionCheck>& regionChecks() {
  static const std::map<std::string, RegionCheck> m = {
      {"grazing",
       [](const Subject& s) {
         std::string dir = portsOf(s).at(0);
         return unless(dotF32(surfaceNormal(s), givenInput(s, dir)) == 0.0f, "N." + dir + " is not 0 in float32");
       }},
      {"back_facing",
       [](const Subject& s) { return unless(dotF32(surfaceNormal(s), givenInput(s, portsOf(s).at(0))) < 0.0f, "N.V is not negative in float32"); }},
      {"normal_incidence_clamped",
       [](const Subject& s) { return unless(dotF32(surfaceNormal(s), givenInput(s, "view")) > 1.0f, "N.V does not exceed 1 in float32"); }},
      {"total_internal_reflection",
       [](const Subject& s) {
         return fromBelowAt(s, [](double theta, double critical) {
           return unless(theta > critical + 1e-3, "not past the critical angle (Snell: ior sin(theta) <= 1)");
         });
       }},
      {"critical_angle",
       [](const Subject& s) {
         return fromBelowAt(s, [](double theta, double critical) {
           return unless(std::abs(theta - critical) < 1e-6, "not within 1e-6 rad of the critical angle");
         });
       }},
      {"zero_vector", [](const Subject& s) { return eachPort(s, [](double x) { return x == 0; }, "the zero vector"); }},
      {"unnormalised",
       [](const Subject& s) {
         for (const auto& p : portsOf(s))
           if (!(std::abs(lengthOf(givenInput(s, p)) - 1) > 0.5)) return "'" + p + "' is not far from unit length";
         return std::string();
       }},
      {"pow_base_zero",
       [](const Subject& s) {
         if (s.spec->type == "fresnel") {
           // The rim form (1 - N.V)^strength: its base.
           if (optionOf(s, "model") != "power" || optionOf(s, "power_form") != "one_minus_cos")
             return std::string("not the power model's form (1 - N.V)^strength");
           float c = std::clamp(dotF32(surfaceNormal(s), givenInput(s, "view")), 0.0f, 1.0f);
           return unless(1.0f - c == 0.0f, "1 - N.V is not 0 in float32");
         }
         if (s.spec->type == "subsurface") return unless(subsurfaceBase(s) == 0, "the glow's base V.(-H) is not clamped to 0");
         if (s.spec->type == "pow") return unless(givenInput(s, "x")[0] == 0, "the base x is not 0");
         auto n = unitOf(givenInput(s, "normal")), v = unitOf(givenInput(s, "view"));
         if (s.spec->type == "blinn_phong") {
           // max(N.H, 0), H = normalize(V + L).
           auto l = unitOf(givenInput(s, "light"));
           double h[3] = {v[0] + l[0], v[1] + l[1], v[2] + l[2]};
           return unless(n[0] * h[0] + n[1] * h[1] + n[2] * h[2] <= 0, "N.H is not 0 or below");
         }
         if (s.spec->type == "phong_specular") {
           // max(R.S, 0), R = reflect(-V, N) = 2 (N.V) N - V.
           auto sun = unitOf(givenInput(s, "sun"));
           double nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2], rs = 0;
           for (int i = 0; i < 3; ++i) rs += (2 * nv * n[i] - v[i]) * sun[i];
           return unless(rs <= 0, "R.S is not 0 or below");
         }
         return "no pow-base oracle for " + s.spec->type;
       }},
      {"half_vector_zero",
       [](const Subject& s) {
         // The two unit vectors the half vector sums cancel exactly.
         auto ports = portsOf(s);
         auto a = unitOf(givenInput(s, ports.at(0))), b = unitOf(givenInput(s, ports.at(1)));
         double w = s.spec->type == "subsurface" ? givenInput(s, "distortion")[0] : 1.0;
         for (int i = 0; i < 3; ++i)
           if (static_cast<float>(a[i]) + static_cast<float>(b[i]) * static_cast<float>(w) != 0.0f)
             return std::string("the half vector's sum is not 0");
         return std::string();
       }},
      {"half_vector_cancelling",
       [](const Subject& s) {
         // The two unit vectors nearly cancel (but not exactly: that is half_vector_zero),
         // and their half vector lies within 2 degrees of the normal: the sharp lobe's peak.
         auto ports = portsOf(s);
         auto a = unitOf(givenInput(s, ports.at(0))), b = unitOf(givenInput(s, ports.at(1)));
         auto n = unitOf(givenInput(s, "normal"));
         double h[3] = {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
         double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
         if (!(len > 0 && len < 0.05)) return std::string("|L + V| is not in (0, 0.05)");
         double nh = (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / len;
         return unless(nh > std::cos(2 * std::numbers::pi / 180), "H is not within 2 degrees of N");
       }},
      {"mirror_highlight",
       [](const Subject& s) {
         // Roughness 0 with N = V = L: D's peak, where alpha^2 = 0 meets N.H = 1.
         if (givenInput(s, "roughness")[0] != 0) return std::string("roughness is not 0");
         auto n = unitOf(givenInput(s, "normal")), v = unitOf(givenInput(s, "view")), l = unitOf(givenInput(s, "light"));
         for (int i = 0; i < 3; ++i)
           if (n[i] != v[i] || n[i] != l[i]) return std::string("N, V and L are not one direction: not at the highlight");
         return std::string();
       }},
      {"outside_domain",
       [](const Subject& s) {
         return eachPort(s, [&](double x) { return x < s.region.lo || x > s.region.hi; }, "outside its documented domain");
       }},
      {"zero_parameter", [](const Subject& s) { return eachPort(s, [](double x) { return x == 0; }, "0"); }},
      {"huge_parameter",
       [](const Subject& s) {
         std::string why = eachPort(s, [](double x) { return std::abs(x) >= 1e3; }, "of magnitude 1e3 or more");
         if (why.empty() && s.spec->type == "flow_map" && optionOf(s, "flow_source") != "input")
           why = "the flow input is unused (flow_source is not input)";
         // The subsurface height factor saturate(2 h + 0.5) reaches the result only where the base is not 0.
         if (why.empty() && s.spec->type == "subsurface")
           why = unless(subsurfaceBase(s) > 0.1, "the glow's base is 0: the height factor does not reach the result");
         return why;
       }},
      {"negative_thickness", [](const Subject& s) { return eachPort(s, [](double x) { return x < 0; }, "negative"); }},
      {"sky_distance", [](const Subject& s) { return eachPort(s, [](double x) { return x >= 1e30; }, "1e30 or more"); }},
      {"sky_depth", [](const Subject& s) { return eachPort(s, [](double x) { return x == 1.0; }, "the sky's depth 1.0"); }},
      {"huge_far_sky",
       [](const Subject& s) {
         return firstFailure({unless(givenInput(s, "depth")[0] == 1.0, "depth is not 1.0"),
                              unless(givenInput(s, "near_far")[1] >= 1e30, "far is below 1e30")});
       }},
      {"zero_near", [](const Subject& s) { return unless(givenInput(s, "near_far")[0] == 0, "near is not 0"); }},
      {"far_below_near",
       [](const Subject& s) {
         Value nf = givenInput(s, "near_far");
         return unless(nf[1] < nf[0], "far is not below near");
       }},
      {"inverse_trig_beyond_one",
       [](const Subject& s) { return unless(std::abs(static_cast<float>(givenInput(s, "x")[0])) > 1.0f, "|x| is not above 1 in float32"); }},
      {"exponential_overflow",
       [](const Subject& s) {
         double x = std::abs(static_cast<double>(static_cast<float>(givenInput(s, "x")[0])));
         double e = s.spec->type == "exp2" ? std::exp2(x)
                    : s.spec->type == "pow" ? std::pow(x, static_cast<double>(static_cast<float>(givenInput(s, "y")[0])))
                                            : std::exp(x);
         return unless(e > std::numeric_limits<float>::max(), "the exponential does not overflow float32");
       }},
      {"exponential_underflow",
       [](const Subject& s) {
         return unless(std::exp(static_cast<double>(static_cast<float>(givenInput(s, "x")[0]))) < std::numeric_limits<float>::min(),
                       "e^x is not below the smallest normal float32");
       }},
      {"non_positive_argument", [](const Subject& s) { return unless(static_cast<float>(givenInput(s, "x")[0]) <= 0, "x is positive in float32"); }},
      {"tan_pole",
       [](const Subject& s) {
         double x = static_cast<float>(givenInput(s, "x")[0]);
         double k = (x - std::numbers::pi / 2) / std::numbers::pi;
         return unless(std::abs(k - std::round(k)) * std::numbers::pi < 1e-7, "x is not within 1e-7 of a pole");
       }},
      {"atan2_origin",
       [](const Subject& s) { return unless(givenInput(s, "x")[0] == 0 && givenInput(s, "y")[0] == 0, "(x, y) is not the origin"); }},
      {"atan2_axis",
       [](const Subject& s) {
         double x = givenInput(s, "x")[0], y = givenInput(s, "y")[0];
         // On an axis, off the origin, where the quadrant selects meet (the negative x axis: the branch cut).
         return unless((x == 0) != (y == 0), "(x, y) is not on an axis off the origin");
       }},
      {"half_integer",
       [](const Subject& s) {
         double x = static_cast<float>(givenInput(s, "x")[0]);
         return unless(x - std::floor(x) == 0.5, "x is not a whole number and a half");
       }},
      {"no_fraction_bits",
       [](const Subject& s) { return unless(std::abs(static_cast<float>(givenInput(s, "x")[0])) >= 0x1p23f, "x has fraction bits in float32"); }},
      {"tiny_negative",
       [](const Subject& s) {
         float x = static_cast<float>(givenInput(s, "x")[0]);
         return unless(x < 0 && x > -1e-6f, "x is not a tiny negative number");
       }},
      {"negative_parameter", [](const Subject& s) { return eachPort(s, [](double x) { return x < 0; }, "negative"); }},
      {"pow_negative_base", [](const Subject& s) { return unless(static_cast<float>(givenInput(s, "x")[0]) < 0, "the base is not negative in float32"); }},
      {"mod_by_zero", [](const Subject& s) { return unless(givenInput(s, "y")[0] == 0, "y is not 0"); }},
      {"quotient_overflow",
       [](const Subject& s) {
         float q = static_cast<float>(givenInput(s, "x")[0]) / static_cast<float>(givenInput(s, "y")[0]);
         return unless(std::isinf(q), "x / y does not overflow float32");
       }},
      {"equal_operands",
       [](const Subject& s) {
         auto ports = portsOf(s);
         Value a = givenInput(s, ports.at(0)), b = givenInput(s, ports.at(1));
         for (int i = 0; i < a.size(); ++i)
           if (a[i] != b[i]) return std::string("the operands differ");
         return std::string();
       }},
      {"inverse_mix_empty_range",
       [](const Subject& s) {
         auto ports = portsOf(s);
         return unless(givenInput(s, ports.at(0))[0] == givenInput(s, ports.at(1))[0], "the range is not empty");
       }},
      {"smoothstep_equal_edges",
       [](const Subject& s) { return unless(givenInput(s, "edge0")[0] == givenInput(s, "edge1")[0], "the edges differ"); }},
      {"reversed_range",
       [](const Subject& s) {
         auto ports = portsOf(s);
         return unless(givenInput(s, ports.at(0))[0] > givenInput(s, ports.at(1))[0], "the range is not reversed");
       }},
      {"smoothstep_reversed_edges",
       [](const Subject& s) { return unless(givenInput(s, "edge0")[0] > givenInput(s, "edge1")[0], "the edges are not reversed"); }},
      {"underflowing_length",
       [](const Subject& s) {
         Value x = givenInput(s, "x");
         return firstFailure({unless(dotF32(x, x) < std::numeric_limits<float>::min(), "the squared length does not underflow float32"),
                              unless(lengthOf(x) > 0, "the vector is zero, not tiny")});
       }},
      {"perpendicular",
       [](const Subject& s) {
         auto ports = portsOf(s);
         return unless(dotF32(givenInput(s, ports.at(0)), givenInput(s, ports.at(1))) == 0.0f, "the vectors are not perpendicular in float32");
       }},
      {"head_on",
       [](const Subject& s) {
         auto i = unitOf(givenInput(s, "incident")), n = unitOf(givenInput(s, "normal"));
         return unless(i[0] == -n[0] && i[1] == -n[1] && i[2] == -n[2], "the incident ray is not against the normal");
       }},
      {"refract_total_internal_reflection",
       [](const Subject& s) {
         // Snell in angles: eta sin(i) beyond 1 has no transmitted ray.
         auto i = unitOf(givenInput(s, "incident")), n = unitOf(givenInput(s, "normal"));
         double c = std::abs(i[0] * n[0] + i[1] * n[1] + i[2] * n[2]);
         double sinI = std::sqrt(std::max(0.0, 1 - c * c));
         return unless(givenInput(s, "eta")[0] * sinI > 1 + 1e-6, "eta sin(i) is not beyond 1: the ray refracts");
       }},
      {"below_threshold",
       [](const Subject& s) {
         auto ports = portsOf(s);
         return unless(givenInput(s, ports.at(0))[0] < givenInput(s, ports.at(1))[0], "'" + ports.at(0) + "' is not below '" + ports.at(1) + "'");
       }},
      {"texel_edge",
       [](const Subject& s) {
         // The built-in textures are 256 x 256 (nodes/builtin_textures.cpp): uv * 256 whole
         // is a boundary between texels, where nearest filtering picks a side.
         return eachPort(s, [](double x) { return x * 256 == std::floor(x * 256); }, "on a texel boundary of a 256-texel texture");
       }},
      {"mixed_sign_coordinates",
       [](const Subject& s) {
         // Coordinates on both sides of 0: cells whose floor is negative beside positive ones.
         Value p = givenInput(s, portsOf(s).at(0));
         bool negative = false, positive = false;
         for (int i = 0; i < p.size(); ++i) {
           negative = negative || p[i] < 0;
           positive = positive || p[i] > 0;
         }
         return unless(negative && positive, "the coordinates are not of both signs");
       }},
      {"uv_boundary", [](const Subject& s) { return eachPort(s, [](double x) { return x == 0 || x == 1; }, "0 or 1"); }},
      // The sRGB curve's two segments meet at 0.04045 (IEC 61966-2-1).
      {"srgb_knee",
       [](const Subject& s) { return eachPort(s, [](double x) { return std::abs(x - 0.04045) <= 1e-3; }, "within 1e-3 of 0.04045"); }},
      {"unit_value", [](const Subject& s) { return eachPort(s, [](double x) { return x == 1; }, "exactly 1"); }},
      {"above_one", [](const Subject& s) { return eachPort(s, [](double x) { return x > 1 && x < 1e3; }, "in (1, 1e3)"); }},
      {"screen_offset_outside",
       [](const Subject& s) {
         // screen uv + distortion, in float32, leaves [0, 1] in some component (the clamp acts).
         Value uv = hasInputPort(s, "screen_uv") ? givenInput(s, "screen_uv") : toFloat32(s.env.screenUv);
         Value d = givenInput(s, "distortion");
         for (int i = 0; i < 2; ++i) {
           float u = static_cast<float>(uv[i]) + static_cast<float>(d[i]);
           if (u < 0 || u > 1) return std::string();
         }
         return std::string("screen uv + distortion stays on screen");
       }},
      {"camera_at_water_level",
       [](const Subject& s) {
         return unless(optionOf(s, "camera") == "below" && givenInput(s, "water_level")[0] == s.env.cameraPosition[1],
                       "the camera (below) is not at the water level");
       }},
      {"screen_uv_outside",
       [](const Subject& s) {
         Value uv = givenInput(s, "screen_uv");
         return unless(!everyComponent(uv, [](double x) { return x >= 0 && x <= 1; }), "screen uv inside [0, 1]");
       }},
      {"huge_coordinates",
       [](const Subject& s) {
         double m = 0;
         for (const auto& p : portsOf(s)) {
           Value v = givenInput(s, p);
           for (int i = 0; i < v.size(); ++i) m = std::max(m, std::abs(v[i]));
         }
         // float32 spacing 2^-7 or more: a phase k x of a 10 m wave keeps about 5 digits.
         return unless(m >= 1e5, "no coordinate of 1e5 or more");
       }},
      {"beyond_int_range",
       [](const Subject& s) {
         Value p = givenInput(s, portsOf(s).at(0));
         return unless(!everyComponent(p, [](double x) { return std::abs(x) < 2147483648.0; }), "no coordinate beyond the int32 range");
       }},
      {"negative_cells",
       [](const Subject& s) { return eachPort(s, [](double x) { return std::floor(x) < 0; }, "in a negative cell"); }},
      {"hash_bit_pattern",
       [](const Subject& s) {
         Value p = givenInput(s, "p");
         if (!(std::abs(p[0]) >= 1e7)) return std::string("the cell is not at 1e7");
         auto w = pcgWords(latticeBits(p[0]), latticeBits(p[1]), p.size() > 2 ? latticeBits(p[2]) : 0u);
         auto out = evaluateNode(*s.spec, s.hc.options, {{"p", p}}, s.env)[1];
         for (int i = 0; i < 3; ++i)
           if (out[i] != std::ldexp(static_cast<double>(w[i] >> 8u), -24)) return std::string("the hash bits differ from PCG3D's");
         return std::string();
       }},
      {"huge_time",
       [](const Subject& s) {
         if (hasInputPort(s, "time") && s.spec->optionIndex("animation") >= 0 && optionOf(s, "animation") != "time_input")
           return std::string("the time input is unused (animation is not time_input)");
         float t = static_cast<float>(givenInput(s, "time")[0]);
         return unless(std::nextafter(std::abs(t), INFINITY) - std::abs(t) >= 0x1p-10f, "time too small to lose float32 digits");
       }},
      {"empty_spectrum",
       [](const Subject& s) {
         ocean::OceanSettings sea = caseSea(s);
         for (size_t c = 0; c < sea.cascades.tileLengths.size(); ++c)
           for (const auto& a : ocean::initialCascade(sea.spectrum, sea.cascades, static_cast<int>(c)).h0)
             if (a != 0.0) return "cascade " + std::to_string(c) + " has a wave (an amplitude is not 0)";
         return std::string();
       }},
      {"surface_folds",
       [](const Subject& s) {
         double j = caseJacobian(s);
         return unless(j < 0, "J = " + std::to_string(j) + " at the point: the surface does not fold there");
       }},
      {"footprint_past_tiles",
       [](const Subject& s) {
         const ocean::OceanSettings sea = caseSea(s);
         const double f = caseFootprint(s);
         for (size_t c = 0; c < sea.cascades.tileLengths.size(); ++c) {
           const int n = ocean::cascadeResolution(sea.cascades, c);
           const int levels = std::countr_zero(static_cast<unsigned>(n));
           if (nodes::oceanread::lodOf(f, static_cast<float>(n / sea.cascades.tileLengths[c]), levels) < levels)
             return "cascade " + std::to_string(c) + " is read below its 1 x 1 level (footprint " + std::to_string(f) + " m)";
         }
         return std::string();
       }},
      {"footprint_zero", [](const Subject& s) { return unless(caseFootprint(s) == 0, "the footprint is not 0"); }},
      {"tile_corner",
       [](const Subject& s) {
         // wg_ocean_map_cubic reads texels a - 1 .. a + 2 around a = floor(u) mod n: they wrap
         // when a is 0, n - 2 or n - 1.
         const ocean::OceanSettings sea = caseSea(s);
         const Value p = givenInput(s, "position");
         for (size_t c = 0; c < sea.cascades.tileLengths.size(); ++c) {
           const int n = ocean::cascadeResolution(sea.cascades, c);
           const double k = static_cast<float>(n / sea.cascades.tileLengths[c]);
           auto wraps = [n, k](double x) {
             const double b = std::floor(x * k);
             const int a = static_cast<int>(b - n * std::floor(b / n));
             return a == 0 || a >= n - 2;
           };
           if (wraps(p[0]) && wraps(p[2])) return std::string();
         }
         return std::string("no cascade's 4 x 4 texels around the point wrap on both axes");
       }},
      {"level_boundary",
       [](const Subject& s) {
         const ocean::OceanSettings sea = caseSea(s);
         const double f = caseFootprint(s);
         for (size_t c = 0; c < sea.cascades.tileLengths.size(); ++c) {
           const int n = ocean::cascadeResolution(sea.cascades, c);
           const double texels = f * static_cast<float>(n / sea.cascades.tileLengths[c]);
           if (texels >= 1 && std::log2(texels) == std::floor(std::log2(texels))) return std::string();
         }
         return std::string("no cascade's footprint is a whole power of two texels");
       }},
      {"shallow_water",
       [](const Subject& s) {
         ocean::OceanSettings sea = caseSea(s);
         if (sea.spectrum.model != ocean::SpectrumModel::Tma) return std::string("not a TMA sea");
         double kd = wavenumberAt(ocean::spectrumPeak(sea.spectrum), sea.spectrum.depth) * sea.spectrum.depth;
         return unless(kd < 0.1, "k d = " + std::to_string(kd) + " at the peak: not shallow water");
       }},
      {"voronoi_2x2_search", [](const Subject& s) { return unless(optionOf(s, "search") == "2x2", "not the 2x2 search"); }},
      {"voronoi_f1_above_one",
       [](const Subject& s) {
         if (optionOf(s, "animation") != "static") return std::string("animated: the points move from where F1 was found");
         Value p = givenInput(s, "p");
         double scale = givenInput(s, "scale")[0], jitter = givenInput(s, "jitter")[0];
         return unless(bruteForceF1(p[0] * scale, p[1] * scale, jitter) > 1, "F1 (brute force) is not above 1");
       }},
      {"gerstner_cusp",
       [](const Subject& s) {
         // Sum Q k A = 1 over the waves (A = Q / k by default), all along x here, and the
         // written-out surface (x0 + sum Q A cos th, sum A sin th), th = k x0 - omega t + phi,
         // has a vanishing tangent at the case's point: the fold.
         const auto& waves = s.hc.options.at("waves");
         double sum = 0;
         struct W {
           double k, q, a, omega, phi;
         };
         std::vector<W> ws;
         for (const auto& w : waves) {
           if (w.at("direction") != nlohmann::json::array({1, 0})) return std::string("a wave is not along x");
           double k = 2 * std::numbers::pi / w.at("wavelength").get<double>(), q = w.at("steepness");
           double a = w.value("amplitude", q / k);
           ws.push_back({k, q, a, std::sqrt(9.81 * k), w.value("phase", 0.0)});
           sum += q * k * a;
         }
         if (std::abs(sum - 1) > 1e-12) return std::string("sum Q k A is not 1: not at the cusp limit");
         double t = s.env.time[0], x0 = givenInput(s, "position")[0], h = 1e-5;
         auto at = [&](double x) {
           double px = x, py = 0;
           for (const auto& w : ws) {
             double th = w.k * x - w.omega * t + w.phi;
             px += w.q * w.a * std::cos(th);
             py += w.a * std::sin(th);
           }
           return std::array<double, 2>{px, py};
         };
         auto a = at(x0 + h), b = at(x0 - h);
         double tangent = std::hypot(a[0] - b[0], a[1] - b[1]) / (2 * h);
         return unless(tangent < 1e-4, "the surface does not fold at the point (|dP/dx| = " + std::to_string(tangent) + ")");
       }},
      {"camera_below_surface",
       [](const Subject& s) {
         double surface = givenInput(s, "surface_height")[0];
         return firstFailure({unless(givenInput(s, "origin")[1] < surface, "the origin is not below the surface"),
                              unless(-givenInput(s, "view")[1] > 0, "the ray (-view) does not rise towards the surface")});
       }},
  };
  return m;
}

std::vector<Subject> subjects() {
  std::vector<Subject> out;
  for (const auto& r : nodes::hardCaseRegions()) {
    const NodeSpec* spec = defaultRegistry().find(std::string(r.type));
    if (!spec) throw std::runtime_error("no node " + std::string(r.type));
    auto hc = std::find_if(spec->hardCases.begin(), spec->hardCases.end(), [&](const HardCase& h) { return h.name == r.hardCase; });
    if (hc == spec->hardCases.end()) throw std::runtime_error(std::string(r.type) + " has no hard case '" + std::string(r.hardCase) + "'");
    Subject s;
    s.spec = spec;
    s.hc = *hc;
    s.region = r;
    out.push_back(std::move(s));
  }
  return out;
}

std::string reaches(const Subject& s) {
  auto check = regionChecks().find(std::string(s.region.region));
  if (check == regionChecks().end()) return "no check for region '" + std::string(s.region.region) + "'";
  return check->second(s);
}

TEST(NodeHardCaseRegions, EveryNodeHardCaseNamesARegion) {
  std::vector<Subject> all = subjects();  // throws for an entry naming no case
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto& s : all) EXPECT_TRUE(seen.emplace(s.spec->type, s.hc.name).second) << "twice: " << s.spec->type << " '" << s.hc.name << "'";
  int uncovered = 0;
  for (const NodeSpec* spec : defaultRegistry().all()) {
    for (const auto& hc : spec->hardCases) {
      if (seen.count({spec->type, hc.name})) continue;
      ++uncovered;
      ADD_FAILURE() << spec->type << " hard case '" << hc.name << "' names no region (nodes/hard_case_regions.cpp)";
    }
  }
  std::printf("[ regions  ] %zu node hard cases with a region, %d without\n", all.size(), uncovered);
}

TEST(NodeHardCaseRegions, EveryNodeHardCaseReachesItsRegion) {
  for (const auto& s : subjects()) {
    std::string why = reaches(s);
    EXPECT_EQ(why, "") << s.spec->type << " hard case '" << s.hc.name << "' does not reach region " << s.region.region;
  }
}

// A scalar or vector of `n` components, each x.
Value filled(int n, double x) {
  if (n == 1) return Value::scalar(x);
  if (n == 2) return Value::vector({x, x});
  if (n == 3) return Value::vector({x, x, x});
  return Value::vector({x, x, x, x});
}

// Moves case `s` out of its region by one input (or option): the check must reject it.
std::optional<Subject> movedOut(Subject s) {
  auto set = [&](const std::string& port, Value v) {
    for (auto& [name, value] : s.hc.inputs)
      if (name == port) {
        value = v;
        return;
      }
    s.hc.inputs.emplace_back(port, v);
  };
  std::string region(s.region.region);
  auto ports = portsOf(s);
  std::string first = ports.empty() ? "" : ports.front();
  double at40 = 40 * std::numbers::pi / 180;
  if (region == "grazing" || region == "back_facing" || region == "normal_incidence_clamped" ||
      region == "total_internal_reflection" || region == "critical_angle" ||
      (region == "pow_base_zero" && s.spec->type != "pow") || region == "half_vector_zero" ||
      region == "half_vector_cancelling") {
    // A view (or light) 40 degrees off the normal: in front, refracting, no cancellation.
    auto n = unitOf(surfaceNormal(s));
    Value tilted = Value::vector({std::sin(at40), std::cos(at40), 0});
    if (region == "pow_base_zero" && s.spec->type == "blinn_phong") {
      set("normal", Value::vector({0, 1, 0}));  // N = H
    } else if (region == "pow_base_zero" && s.spec->type == "phong_specular") {
      set("sun", Value::vector({0, 1, 0}));  // along the reflection
    } else if (region == "pow_base_zero" && s.spec->type == "subsurface") {
      Value l = givenInput(s, "light");
      set("view", Value::vector({-l[0], -l[1], -l[2]}));  // looking into the light: V.(-H) near 1
    } else {
      if (n[1] != 1) return std::nullopt;
      set(region == "half_vector_zero" && s.spec->type == "subsurface" ? "light" : ports.back(), tilted);
    }
  } else if (region == "zero_vector" || region == "unnormalised") {
    set(first, Value::vector({0, 1, 0}));
  } else if (region == "sky_distance" || region == "sky_depth" || region == "negative_thickness" || region == "huge_parameter" ||
             region == "zero_parameter" || region == "outside_domain" || region == "srgb_knee" || region == "unit_value" ||
             region == "above_one") {
    if (first == "scene_depth") {
      s.env.sceneDepth = Value::scalar(0.5);
      return s;
    }
    set(first, filled(givenInput(s, first).size(), 0.5));
  } else if (region == "huge_coordinates" || region == "beyond_int_range" || region == "negative_cells" || region == "mixed_sign_coordinates" ||
             region == "hash_bit_pattern") {
    set(first, filled(givenInput(s, first).size(), 1.25));
  } else if (region == "inverse_trig_beyond_one" || region == "exponential_overflow" || region == "exponential_underflow" ||
             region == "non_positive_argument" || region == "tan_pole" || region == "half_integer" ||
             region == "no_fraction_bits" || region == "tiny_negative" || region == "negative_parameter" ||
             region == "pow_negative_base" || (region == "pow_base_zero" && s.spec->type == "pow")) {
    set(first, filled(givenInput(s, first).size(), 0.3));  // positive, inside [-1, 1], far from poles and overflow
  } else if (region == "mod_by_zero" || region == "quotient_overflow") {
    set("y", Value::scalar(1));
  } else if (region == "atan2_origin" || region == "atan2_axis") {
    set("x", Value::scalar(1));
    set("y", Value::scalar(1));
  } else if (region == "equal_operands" || region == "inverse_mix_empty_range" || region == "smoothstep_equal_edges") {
    set(ports.at(1), filled(givenInput(s, ports.at(1)).size(), 7));
  } else if (region == "reversed_range" || region == "smoothstep_reversed_edges") {
    set(ports.at(0), Value::scalar(0));
    set(ports.at(1), Value::scalar(1));
  } else if (region == "underflowing_length") {
    set(first, Value::vector({1, 0, 0}));
  } else if (region == "perpendicular") {
    set(first, Value::vector({0.6, -0.8, 0}));
  } else if (region == "head_on") {
    set("incident", Value::vector({0.6, -0.8, 0}));
  } else if (region == "refract_total_internal_reflection") {
    set("eta", Value::scalar(0.75));
  } else if (region == "below_threshold") {
    set(ports.at(0), Value::scalar(0.9));
  } else if (region == "texel_edge" || region == "uv_boundary") {
    set(first, Value::vector({0.3, 0.7}));
  } else if (region == "screen_offset_outside") {
    set("distortion", Value::vector({0.01, -0.02}));
  } else if (region == "camera_at_water_level") {
    set("water_level", Value::scalar(3));
  } else if (region == "huge_time") {
    set("time", Value::scalar(3.5));
  } else if (region == "voronoi_f1_above_one") {
    set("p", Value::vector({0.5, 0.5}));  // beside the cell's own point
  } else if (region == "gerstner_cusp") {
    set("position", Value::vector({0, 0, 0}));  // a trough: the surface does not fold there
  } else if (region == "camera_below_surface") {
    set("origin", Value::vector({0, 5, 0}));
  } else if (region == "mirror_highlight") {
    set("roughness", Value::scalar(0.5));
  } else if (region == "huge_far_sky" || region == "zero_near" || region == "far_below_near") {
    set("near_far", Value::vector({0.1, 100}));
  } else if (region == "screen_uv_outside") {
    set("screen_uv", Value::vector({0.5, 0.5}));
  } else if (region == "empty_spectrum") {
    s.hc.oceanOptions["wind_speed"] = 10;
  } else if (region == "surface_folds") {
    set("position", Value::vector({11, 0, 5}));  // J = 0.18 there at t = 0
  } else if (region == "shallow_water") {
    s.hc.oceanOptions["depth"] = 100;
  } else if (region == "footprint_past_tiles" || region == "footprint_zero") {
    Value p = givenInput(s, "position");
    set("camera", Value::vector({p[0], p[1] + 40, p[2]}));  // straight above: a footprint of 4 cm
  } else if (region == "level_boundary") {
    set("pixel_angle", Value::scalar(1.37 / 64));
  } else if (region == "tile_corner") {
    set("position", Value::vector({3, 0, -7}));  // texels 3 .. 6 and 54 .. 57 of the 50 m tile
  } else if (region == "voronoi_2x2_search") {
    s.hc.options["search"] = "3x3";
  } else {
    return std::nullopt;
  }
  return s;
}

TEST(NodeHardCaseRegions, CasesMovedOutOfTheirRegionAreRejected) {
  int tried = 0;
  for (const auto& s : subjects()) {
    auto moved = movedOut(s);
    if (!moved) continue;
    ++tried;
    EXPECT_NE(reaches(*moved), "") << s.spec->type << " hard case '" << s.hc.name << "' moved out of region "
                                   << s.region.region << " still passes its check";
  }
  EXPECT_GE(tried, static_cast<int>(nodes::hardCaseRegions().size()) - 2);
}

}  // namespace
}  // namespace wg::accuracy::node_hard_cases
