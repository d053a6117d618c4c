#pragma once
// GLSL semantics in double precision for the node references: component-wise maps with
// float splatting, and the built-ins whose GLSL definition differs from <cmath>
// (mod floors, pow is exp2(y*log2 x), smoothstep's Hermite, clamp's order).
#include <cmath>

#include "core/value.h"

namespace wg::glsl {

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
inline double rawPow(double x, double y) { return std::exp2(y * std::log2(x)); }

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

}  // namespace wg::glsl
