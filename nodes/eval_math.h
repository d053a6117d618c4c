#pragma once
// GLSL semantics in double precision for the node references: component-wise maps with
// float splatting, and the built-ins whose GLSL definition differs from <cmath>
// (mod floors, pow is exp2(y*log2 x), smoothstep's Hermite, clamp's order).
#include <algorithm>
#include <cmath>

#include "core/value.h"

namespace wg::glsl {

inline constexpr double kTau = 6.283185307179586;  // 2 pi, the period of GLSL's sin and cos

template <class F>
Value map1(const Value& a, Type out, F f) {
  Value r = Value::ofType(out);
  bool splat = a.size() == 1;
  for (int i = 0; i < r.size(); ++i) r[i] = f(a[splat ? 0 : i]);
  return r;
}

template <class F>
Value map2(const Value& a, const Value& b, Type out, F f) {
  Value r = Value::ofType(out);
  for (int i = 0; i < r.size(); ++i) r[i] = f(a[a.size() == 1 ? 0 : i], b[b.size() == 1 ? 0 : i]);
  return r;
}

template <class F>
Value map3(const Value& a, const Value& b, const Value& c, Type out, F f) {
  Value r = Value::ofType(out);
  for (int i = 0; i < r.size(); ++i)
    r[i] = f(a[a.size() == 1 ? 0 : i], b[b.size() == 1 ? 0 : i], c[c.size() == 1 ? 0 : i]);
  return r;
}

inline double mod(double x, double y) { return x - y * std::floor(x / y); }
inline double fract(double x) { return x - std::floor(x); }
inline double clamp(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }
inline double saturate(double x) { return clamp(x, 0.0, 1.0); }
inline double mix(double a, double b, double t) { return a * (1.0 - t) + b * t; }
inline double step(double edge, double x) { return x < edge ? 0.0 : 1.0; }
// exp2(y log2 x) with the exponent capped at 127 (2^127 = 1.70e38), as the library's pow.
inline double rawPow(double x, double y) { return std::exp2(std::min(y * std::log2(x), 127.0)); }

inline double dot(const Value& a, const Value& b) {
  double s = 0;
  for (int i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
inline double length(const Value& a) { return std::sqrt(dot(a, a)); }
inline Value scale(const Value& a, double k) { return map1(a, a.type, [k](double x) { return x * k; }); }
inline Value sub(const Value& a, const Value& b) { return map2(a, b, a.type, [](double x, double y) { return x - y; }); }

// The library's safe variants (nodes/glsl/common.glsl), same constants.
inline constexpr double kNormalizeFloor = 1e-30;  // squared length below which a vector is zero
inline Value safeNormalize(const Value& a) {
  double l2 = dot(a, a);
  return scale(a, 1.0 / std::sqrt(std::max(l2, kNormalizeFloor)));
}
// pow with the base clamped at 0: 0^y is 0 for y > 0 and 1 for y <= 0.
inline double safePow(double x, double y) {
  if (x > 0.0) return rawPow(x, y);
  return y > 0.0 ? 0.0 : 1.0;
}
// smoothstep that is defined for equal edges (a step at the edge) and reversed edges.
inline double safeSmoothstep(double e0, double e1, double x) {
  if (e0 == e1) return x < e0 ? 0.0 : 1.0;
  double t = saturate((x - e0) / (e1 - e0));
  return t * t * (3.0 - 2.0 * t);
}

// The vocabulary's guarded forms (nodes/glsl/math_*.glsl), same constants. Each is the
// GLSL built-in wherever GLSL defines a finite result, and a documented finite value
// where the built-in would give inf or NaN.
inline constexpr double kFloatMin = 0x1p-126;          // FLT_MIN: floor of log's and inversesqrt's argument
inline constexpr double kModQuotientMax = 1e38;        // mod: a quotient x / y beyond it (or inf, NaN) gives 0
inline constexpr double kExpArgMax = 88.0;             // exp(88) = 1.65e38, below FLT_MAX = 3.40e38
inline constexpr double kExp2ArgMax = 127.0;           // 2^127 = 1.70e38
inline constexpr double kHyperbolicArgMax = 88.0;      // sinh, cosh: e^88 / 2 = 8.26e37
inline constexpr double kTanhArgMax = 10.0;            // tanh(10) = 1 - 4e-9: 1 in float32
inline constexpr double kTanCosFloor = 1e-30;          // |cos| floor in tan = sin / cos

inline double roundEven(double x) { return std::nearbyint(x); }  // the default rounding mode: halves to even
inline double sign(double x) { return x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0; }
inline double safeLog(double x) { return std::log(std::max(x, kFloatMin)); }
inline double safeLog2(double x) { return std::log2(std::max(x, kFloatMin)); }
inline double safeSqrt(double x) { return std::sqrt(std::max(x, 0.0)); }
inline double safeInverseSqrt(double x) { return 1.0 / std::sqrt(std::max(x, kFloatMin)); }
inline double safeExp(double x) { return std::exp(std::min(x, kExpArgMax)); }
inline double safeExp2(double x) { return std::exp2(std::min(x, kExp2ArgMax)); }
// mod whose quotient x / y overflows or nearly (y = 0, or y tiny against x) gives 0: the
// limit of mod(x, y) as y goes to 0, and within |y| of the true value otherwise.
inline double safeMod(double x, double y) {
  return std::abs(x) < kModQuotientMax * std::abs(y) ? x - y * std::floor(x / y) : 0.0;
}
// sin / cos with |cos| floored at 1e-30 (keeping its sign): at most 1e30 in magnitude.
inline double safeTan(double x) {
  double c = std::cos(x);
  double d = c < 0.0 ? std::min(c, -kTanCosFloor) : std::max(c, kTanCosFloor);
  return std::sin(x) / d;
}
inline double safeAsin(double x) { return std::asin(clamp(x, -1.0, 1.0)); }
inline double safeAcos(double x) { return std::acos(clamp(x, -1.0, 1.0)); }
// atan(y, x) with the origin, which GLSL leaves undefined, at angle 0. y = -0 counts as
// +0 (the negative x axis is pi): GPUs do not all keep the sign of a zero.
inline double safeAtan2(double y, double x) {
  if (y == 0.0) return x < 0.0 ? 3.14159265358979323846 : 0.0;
  return std::atan2(y, x);
}
inline double safeSinh(double x) { return std::sinh(clamp(x, -kHyperbolicArgMax, kHyperbolicArgMax)); }
inline double safeCosh(double x) { return std::cosh(clamp(x, -kHyperbolicArgMax, kHyperbolicArgMax)); }
inline double safeTanh(double x) { return std::tanh(clamp(x, -kTanhArgMax, kTanhArgMax)); }
// Where x lies between a and b as a fraction (unclamped); 0 for an empty range a == b.
inline double inverseMix(double a, double b, double x) { return b == a ? 0.0 : (x - a) / (b - a); }

}  // namespace wg::glsl
