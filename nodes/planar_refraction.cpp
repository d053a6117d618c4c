// planar_refraction: seed 000's refraction pass — the opaque scene below the water,
// rendered through the real camera with a clip plane at the surface (so nothing above the
// water, such as pillar tops, bleeds into what is seen through it) — looked up at this
// pixel with a distortion offset. scene_color is the cheaper GrabPass alternative (a copy
// of the frame, which also holds what stands above the water).
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/screen_space_reference.h"

namespace wg::nodes {

NodeSpec planarRefractionNode() {
  NodeSpec s;
  s.type = "planar_refraction";
  s.family = "screen space";
  s.summary = "The refraction pass (the scene below the water, clipped at the surface) looked up at this pixel, "
              "with a distortion offset.";
  s.formula = "uv' = clamp(screen_uv + distortion, 0, 1); color = texture(u_refraction, uv').rgb. The runtime draws "
              "the opaque scene through the camera with gl_ClipDistance = -(y - water level), seed 000's clip plane "
              "(0, -1, 0, 0).";
  s.seed = "000 (refraction pass with clip plane (0, -1, 0, 0) into refractionTexture; distortion (dudv * 2 - 1) * "
           "0.03); 002 (refraction FBO in the multi-pass loop)";
  s.cost = "one texture fetch + 4 ALU; runs the refraction pass: a second draw of the opaque scene into an RGBA8 + "
           "depth target (8 bytes/pixel)";
  s.inputs = {ports::fromBuiltin("screen_uv", Type::Vec2, Builtin::ScreenUv,
                                 "screen position to read, (0,0) bottom left to (1,1) top right (default: this pixel)"),
              ports::fixed("distortion", Type::Vec2, Value::vector({0, 0}),
                           "offset in screen units (seed 000: (dudv * 2 - 1) * 0.03)")};
  s.outputs = {ports::fixed("color", Type::Vec3, "the scene below the surface"),
               ports::fixed("uv", Type::Vec2, "the clamped look-up position, in [0, 1]")};
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {"refraction"};
  s.emit = [](EmitContext& ctx) {
    std::string uv = ctx.temporary(
        Type::Vec2, EmitContext::call("wg_scene_color_uv", {ctx.input("screen_uv"), ctx.input("distortion")}));
    ctx.output(0, "texture(" + ctx.sceneTexture("refraction") + ", " + uv + ").rgb");
    ctx.output(1, uv);
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, ctx.environment().refractionColor);
    ctx.output(1, sceneColorUvReference(ctx.input("screen_uv"), ctx.input("distortion")));
  };
  s.tolerance = 1e-6;
  s.hardCases = {
      {"distortion far off screen", {{"distortion", Value::vector({3, -8})}}, {}, "uv clamped to (1, 0)", 0, 1, "uv"},
      {"distortion 1e30", {{"distortion", Value::vector({1e30, -1e30})}}, {}, "uv clamped to (1, 0)", 0, 1, "uv"},
  };
  return s;
}

}  // namespace wg::nodes
