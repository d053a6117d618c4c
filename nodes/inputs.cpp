// Input nodes: values the stage provides (mesh attributes, camera, time, screen). They
// are sources: never folded, and each one declares only the attribute, varying or
// uniform it reads.
#include "core/emit_context.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

NodeSpec builtinInput(std::string type, Builtin b, std::string summary, std::string formula,
                      unsigned stages = kAnyStage) {
  NodeSpec s;
  s.type = std::move(type);
  s.family = "inputs";
  s.summary = std::move(summary);
  s.formula = std::move(formula);
  s.stages = stages;
  s.isSource = true;
  s.recomputeInFragment = true;
  s.outputs = {ports::fixed("out", builtinType(b), "the value")};
  s.facts = [b](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{builtinFact(b)}; };
  s.emit = [b](EmitContext& ctx) { ctx.output(0, ctx.builtin(b)); };
  s.eval = [b](EvalContext& ctx) { ctx.output(0, ctx.environment().builtin(b)); };
  s.cost = "free: an attribute, varying or uniform read";
  s.tolerance = 1e-6;
  return s;
}

NodeSpec uniformInput(std::string type, Builtin b, std::string summary, std::string formula) {
  NodeSpec s = builtinInput(std::move(type), b, std::move(summary), std::move(formula));
  s.isUniformSource = true;
  return s;
}

}  // namespace

NodeSpec uvNode() {
  return builtinInput("uv", Builtin::Uv, "The mesh texture coordinate.",
                      "out = a_uv (vertex stage), interpolated in the fragment stage");
}
NodeSpec worldPositionNode() {
  return builtinInput("world_position", Builtin::WorldPosition,
                      "The surface point in world space; in the fragment stage, after vertex displacement.",
                      "out = (u_model * vec4(a_position, 1)).xyz, or the vertex position output when connected");
}
NodeSpec normalNode() {
  return builtinInput("normal", Builtin::Normal,
                      "The unit surface normal in world space (the object normal through the model matrix; "
                      "in the fragment stage, the vertex normal output when connected).",
                      "out = safe_normalize(mat3(u_model) * a_normal), re-normalised after interpolation");
}
NodeSpec viewDirectionNode() {
  return builtinInput("view_direction", Builtin::ViewDirection,
                      "The unit vector from the surface point towards the camera.",
                      "out = safe_normalize(u_camera_position - world_position)");
}
NodeSpec cameraPositionNode() {
  return uniformInput("camera_position", Builtin::CameraPosition, "The camera position in world space.",
                      "out = u_camera_position");
}
NodeSpec timeNode() {
  return uniformInput("time", Builtin::Time, "Time in seconds.", "out = u_time");
}
NodeSpec sunDirectionNode() {
  return uniformInput("sun_direction", Builtin::SunDirection,
                      "The unit vector towards the scene's sun, as the runtime lights the scene (render --sun-azimuth, "
                      "--sun-elevation), so the water's highlights match the sky.",
                      "out = u_sun_direction");
}
NodeSpec screenUvNode() {
  return builtinInput("screen_uv", Builtin::ScreenUv,
                      "The fragment's position on screen, (0,0) bottom left to (1,1) top right.",
                      "out = gl_FragCoord.xy / u_viewport_size", kFragmentStage);
}

}  // namespace wg::nodes
