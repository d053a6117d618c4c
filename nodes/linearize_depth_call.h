#pragma once
// Which GLSL linearisation a depth read calls, shared by linearize_depth, water_depth and
// scene_depth so the one soundness condition lives in one place: the unguarded
// wg_linearize_depth_known needs the depth in [0, 1] and each of near/far in [1e-6, 1e30]
// (nodes/glsl/linearize_depth.glsl says why); without those facts, the guarded form.
#include "core/node_spec.h"

namespace wg::nodes {

// A depth texture's values: GL clamps depth writes to the depth range.
inline constexpr ValueFact kDepthTextureFact{0, 1, false};

inline const char* linearizeDepthFunction(const ValueFact& depth, const ValueFact& nearFar) {
  bool known = depth.atLeast(0) && depth.hi <= 1 && nearFar.atLeast(1e-6) && nearFar.hi <= 1e30;
  return known ? "wg_linearize_depth_known" : "wg_linearize_depth";
}

}  // namespace wg::nodes
