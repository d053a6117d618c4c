// camera_forward: the camera's unit forward axis, read from the view matrix. The same for
// every pixel of a draw (a uniform source): water_depth derives its ray factor's axis from
// it (NodeSpec::derive), so the normalisation that used to run per pixel inside the ray
// factor is an op of its own that the frequency analysis classifies per-draw.
#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

NodeSpec cameraForwardNode() {
  NodeSpec s;
  s.type = "camera_forward";
  s.family = "inputs";
  s.summary = "The camera's forward axis in world space, unit length, from the view matrix (the zero vector for a "
              "degenerate view matrix).";
  s.formula =
      "f = -(row 2 of u_view) = -(u_view[0][2], u_view[1][2], u_view[2][2]); out = |f|^2 < 0.5 ? (0, 0, 0) : "
      "safe_normalize(f). A rigid view matrix has |f| = 1; the zero vector marks a degenerate (e.g. all-zero) one.";
  s.cost = "~7 ALU, the same for every pixel of a draw";
  s.outputs = {ports::fixed("forward", Type::Vec3, "unit camera axis (the direction the camera looks), or zero")};
  s.isSource = true;
  s.isUniformSource = true;     // reads only the view uniform: per-draw
  s.recomputeInFragment = true;  // as the other uniform inputs: no varying for a uniform
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{ValueFact{-1, 1, true}};  // safe-normalised or zero
  };
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("wg_camera_forward", {ctx.builtin(Builtin::View)})); };
  s.eval = [](EvalContext& ctx) {
    const Value& view = ctx.environment().view;  // column-major: view[col * 4 + row]
    Value f = Value::vector({-view[2], -view[6], -view[10]});
    ctx.output(0, glsl::dot(f, f) < 0.5 ? Value::vector({0, 0, 0}) : glsl::safeNormalize(f));
  };
  s.tolerance = 1e-6;
  return s;
}

}  // namespace wg::nodes
