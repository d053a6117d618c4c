#include "core/emit_context.h"
#include "nodes/screen_lookup.h"

#include "nodes/port_builders.h"
#include "nodes/screen_space_reference.h"

namespace wg::nodes {

void makeScreenLookup(NodeSpec& s, SceneResource resource, const std::string& distortionDoc,
                      const std::string& colorDoc) {
  s.inputs = {ports::fromBuiltin("screen_uv", Type::Vec2, Builtin::ScreenUv,
                                 "screen position to read, (0,0) bottom left to (1,1) top right (default: this pixel)"),
              ports::fixed("distortion", Type::Vec2, Value::vector({0, 0}), distortionDoc)};
  s.outputs = {ports::fixed("color", Type::Vec3, colorDoc),
               ports::fixed("uv", Type::Vec2, "the clamped look-up position, in [0, 1]")};
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {resource};
  s.emit = [resource](EmitContext& ctx) {
    GlslExpr uv = ctx.temporary(
        Type::Vec2, EmitContext::call("wg_scene_color_uv", {ctx.input("screen_uv"), ctx.input("distortion")}));
    ctx.output(0, ctx.sampleScene(resource, uv) + ".rgb");
    ctx.output(1, uv);
  };
  const SceneSampler sampler = sceneResourceRow(resource).sampler;
  s.eval = [sampler](EvalContext& ctx) {
    Value uv = sceneColorUvReference(ctx.input("screen_uv"), ctx.input("distortion"));
    ctx.output(0, ctx.environment().sceneAt(sampler, uv));
    ctx.output(1, uv);
  };
  s.tolerance = 1e-6;
}

}  // namespace wg::nodes
