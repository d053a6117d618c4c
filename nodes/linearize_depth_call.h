#pragma once
// Which GLSL linearisation a depth read calls, shared by linearize_depth, water_depth and
// scene_depth so the one soundness condition lives in one place: the unguarded
// wg_linearize_depth_known needs the depth in [0, 1] and each of near/far in [1e-6, 1e30]
// (nodes/glsl/linearize_depth.glsl says why); without those facts, the guarded form.
#include "core/derive.h"
#include "core/node_spec.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

// A depth texture's values: GL clamps depth writes to the depth range.
inline constexpr ValueFact kDepthTextureFact{0, 1, false};

inline bool linearizeDepthKnown(const ValueFact& depth, const ValueFact& nearFar) {
  return depth.atLeast(0) && depth.hi <= 1 && nearFar.atLeast(1e-6) && nearFar.hi <= 1e30;
}
inline const char* linearizeDepthFunction(const ValueFact& depth, const ValueFact& nearFar) {
  return linearizeDepthKnown(depth, nearFar) ? "wg_linearize_depth_known" : "wg_linearize_depth";
}
// The same choice for a node that derives near and the ratio near / far once per draw
// (near_far_ratio): the known form needs the same facts of the near/far it came from.
inline const char* linearizeDepthRatioFunction(const ValueFact& depth, const ValueFact& nearFar) {
  return linearizeDepthKnown(depth, nearFar) ? "wg_linearize_depth_ratio_known" : "wg_linearize_depth_ratio";
}

// The derived inputs of a depth linearisation: near and near / far, computed once per draw
// by a near_far_ratio op (NodeSpec::derive) on `nearFar`.
inline std::vector<PortSpec> nearRatioPorts() {
  return {ports::derived("near", Type::Float, "near_far_ratio.near of the near/far planes: max(near, 1e-6)"),
          ports::derived("ratio", Type::Float, "near_far_ratio.ratio of the near/far planes: near / max(far, near)")};
}
inline void deriveNearRatio(DeriveContext& ctx, const ValueRef& nearFar) {
  ValueRef r = ctx.op("near_far_ratio", {nearFar});
  ctx.set("near", r);
  ctx.set("ratio", ValueRef::op(r.index, 1));
}

}  // namespace wg::nodes
