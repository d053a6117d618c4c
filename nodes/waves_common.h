#pragma once
// Shared helpers of the "waves" and "flow" node families (gerstner_waves, trochoid_wave,
// sine_normals, ripple_normals, normal_map_scroll, normal_from_height, dudv_distortion,
// flow_map): the double-precision time phase that mirrors EmitContext::timePhase, and a
// tiny vec3 for the references.
#include <cmath>
#include <string>

#include "core/emit_context.h"
#include "core/node_spec.h"
#include "nodes/eval_math.h"

namespace wg::nodes::waves {

inline constexpr double kTwoPi = 6.283185307179586476925286766559;

// What the runtime uploads for ctx.timePhase(omega): mod(omega * t, 2 pi) in double.
inline double timePhase(const EvalContext& ctx, double omega) {
  return glsl::mod(omega * ctx.environment().time[0], kTwoPi);
}

struct D3 {
  double x = 0, y = 0, z = 0;
};
inline D3 d3(const Value& v) { return {v[0], v[1], v[2]}; }
inline Value value(const D3& a) { return Value::vector({a.x, a.y, a.z}); }
inline D3 operator+(const D3& a, const D3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline D3 operator-(const D3& a, const D3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline D3 operator*(const D3& a, double k) { return {a.x * k, a.y * k, a.z * k}; }
inline double dot(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline D3 cross(const D3& a, const D3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// wg_safe_normalize_vec3: zero stays zero.
inline D3 safeNormalize(const D3& a) { return a * (1.0 / std::sqrt(std::max(dot(a, a), glsl::kNormalizeFloor))); }
// wg_waves_unit_or: the unit vector, or `fallback` when the vector is (nearly) zero
// (squared length below 1e-12), so a degenerate frame still gives a usable direction.
inline constexpr double kDegenerateLength2 = 1e-12;
inline D3 unitOr(const D3& a, const D3& fallback) {
  double l2 = dot(a, a);
  return l2 < kDegenerateLength2 ? fallback : a * (1.0 / std::sqrt(l2));
}

}  // namespace wg::nodes::waves
