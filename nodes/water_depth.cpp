// Depth: linearize_depth (depth-buffer value -> linear view depth, the advanced shaders tutorial part 9) and
// water_depth (the water's thickness: scene depth behind the surface minus the surface's
// own depth, the classic WebGL water renderer and the advanced shaders tutorial), both finite for the sky (depth 1) and an infinite far
// plane.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/linearize_depth_call.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {

namespace {

struct WaterDepthOptions {
  bool vertical;  // the vertical thickness rather than along the view ray
};
WaterDepthOptions parseWaterDepthOptions(const OptionReader& o) { return {o.is("measure", "vertical")}; }

}  // namespace

NodeSpec linearizeDepthNode() {
  NodeSpec s;
  s.type = "linearize_depth";
  s.family = "depth and colour";
  s.summary = "Depth-buffer value to linear view depth for a perspective projection (finite for the sky and an "
              "infinite far plane).";
  s.formula =
      "The advanced shaders tutorial: z = 2d - 1, linear = 2 n f / (f + n - z (f - n)), evaluated in the algebraically identical form "
      "n / ((1 - d) + d n / f): d = 0 gives n, d = 1 gives f, f = inf gives the infinite-far-plane limit n / (1 - d). "
      "Guards: d clamped to [0, 1], n floored at 1e-6, f at n, the denominator at n * 1e-30; the result never "
      "exceeds 1e30 (the sky with f = inf or 1e38 gives 1e30).";
  s.source = "advanced shaders tutorial (linearizeDepth, part 9: depth-based effects); classic WebGL water renderer (near 0.1, far 50)";
  s.cost = "~8 ALU, one division";
  s.inputs = {
      ports::fixed("depth", Type::Float, "depth-buffer value in [0, 1] (e.g. gl_FragCoord.z or the scene depth)"),
      ports::fromBuiltin("near_far", Type::Vec2, Builtin::CameraNearFar,
                         "the projection's near and far planes; far may be inf or 1e38"),
  };
  for (auto& p : nearRatioPorts()) s.inputs.push_back(p);
  s.outputs = {ports::fixed("linear", Type::Float, "view-space depth (distance along the camera axis), <= 1e30")};
  s.derive = [](DeriveContext& ctx) { deriveNearRatio(ctx, ctx.input("near_far")); };
  // The facts of near_far still choose the form: the known one where they prove what
  // wg_linearize_depth_known needs (linearize_depth_call.h).
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call(linearizeDepthRatioFunction(ctx.inputFact("depth"), ctx.inputFact("near_far")),
                                    {ctx.input("depth"), ctx.input("near"), ctx.input("ratio")}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, Value::scalar(linearizeDepthRatioReference(ctx.scalar("depth"), ctx.scalar("near"), ctx.scalar("ratio"))));
  };
  s.tolerance = 1e-5;  // relative; near d = 1 the depth buffer's own float precision dominates
  s.hardCases = {
      {"sky, depth 1.0", {{"depth", Value::scalar(1.0)}, {"near_far", Value::vector({0.1, 100})}}, {},
       "the far plane, 100", 0, 100},
      {"sky with far = 1e38", {{"depth", Value::scalar(1.0)}, {"near_far", Value::vector({0.1, 1e38})}}, {},
       "large but finite: 1e30", 0, 1e30},
      {"near -> 0", {{"depth", Value::scalar(0.5)}, {"near_far", Value::vector({0, 100})}}, {},
       "near floored at 1e-6: finite", 0, 100},
      {"depth outside [0, 1]", {{"depth", Value::scalar(1.5)}, {"near_far", Value::vector({0.1, 50})}}, {},
       "clamped to the far plane", 0, 50},
      {"far < near", {{"depth", Value::scalar(0.5)}, {"near_far", Value::vector({1, 0.5})}}, {},
       "far raised to near: finite", 0, 1},
  };
  return s;
}

NodeSpec waterDepthNode() {
  NodeSpec s;
  s.type = "water_depth";
  s.family = "depth and colour";
  s.summary = "Thickness of water behind the surface: the scene depth minus the surface's depth, along the view ray "
              "or vertically.";
  s.formula =
      "scene = linearize(texture(u_scene_depth, screen_uv).r), surface = linearize(gl_FragCoord.z) with "
      "u_camera_near_far (see linearize_depth). dz = max(scene - surface, 0) (scene in front of the water: 0). "
      "view_ray: thickness = dz / max(cos(ray, camera axis), 0.1), the distance the view ray travels in water "
      "(cos = -V . forward, forward = -(row 2 of u_view); a degenerate view matrix counts as cos = 1). "
      "vertical: thickness = that distance * |V.y|, the vertical drop along the straight ray: the depth of the "
      "water column below the surface point if the bottom is flat over the ray's footprint (an approximation that "
      "ignores refraction and a sloping bottom). Thickness <= 1e30, so the sky stays finite.";
  s.source = "classic WebGL water renderer (water depth = floor distance - surface distance, near 0.1, far 50); advanced shaders tutorial (depth = sceneDepth - "
             "waterDepth)";
  s.cost = "one depth-texture fetch (needs the scene_depth pass), two linearisations, ~30 ALU";
  s.inputs = {
      ports::fromBuiltin("screen_uv", Type::Vec2, Builtin::ScreenUv, "where to read the scene depth (default: this "
                                                                     "pixel)"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "direction from the surface to the viewer"),
      ports::derived("camera_axis", Type::Vec3, "camera_forward.forward: the unit camera axis, zero for a degenerate view matrix"),
  };
  for (auto& p : nearRatioPorts()) s.inputs.push_back(p);
  s.outputs = {ports::fixed("thickness", Type::Float, "water thickness in world units (>= 0, <= 1e30)"),
               ports::fixed("scene_distance", Type::Float, "linear view depth of the scene behind the water"),
               ports::fixed("surface_distance", Type::Float, "linear view depth of the water surface")};
  s.options = {ports::choice("measure", {"view_ray", "vertical"}, "view_ray",
                             "distance along the view ray, or its vertical component (see formula)")};
  s.parseOptions = optionParser(parseWaterDepthOptions);
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {SceneResource::SceneDepth};
  // The per-draw parts (the camera axis, near and near / far) are ops of their own.
  s.derive = [](DeriveContext& ctx) {
    ctx.set("camera_axis", ctx.op("camera_forward", {}));
    deriveNearRatio(ctx, ValueRef::builtin(Builtin::CameraNearFar));
  };
  s.emit = [](EmitContext& ctx) {
    GlslExpr n = ctx.input("near"), r = ctx.input("ratio");
    // The scene depth is a depth texture; the surface's is gl_FragCoord.z.
    ValueFact nearFar = ctx.knownBuiltin(Builtin::CameraNearFar);
    std::string sceneFn = linearizeDepthRatioFunction(kDepthTextureFact, nearFar);
    std::string surfaceFn = linearizeDepthRatioFunction(ctx.knownBuiltin(Builtin::FragDepth), nearFar);
    GlslExpr sceneDepth = ctx.sampleScene("scene_depth", ctx.input("screen_uv")) + ".r";
    GlslExpr scene = ctx.temporary(Type::Float, EmitContext::call(sceneFn, {sceneDepth, n, r}));
    GlslExpr surface = ctx.temporary(Type::Float, EmitContext::call(surfaceFn, {ctx.builtin(Builtin::FragDepth), n, r}));
    GlslExpr view = ctx.input("view");
    GlslExpr unitView = ctx.inputFact("view").normalized ? view : EmitContext::call("wg_safe_normalize_vec3", {view});
    GlslExpr factor = EmitContext::call("wg_water_depth_ray_factor_axis", {ctx.input("camera_axis"), unitView});
    bool vertical = ctx.options<WaterDepthOptions>().vertical;
    GlslExpr v = vertical ? "abs(" + EmitContext::call("wg_safe_normalize_vec3", {view}) + ".y)" : "1.0";
    ctx.output(0, EmitContext::call("wg_water_depth_thickness", {scene, surface, factor, v}));
    ctx.output(1, scene);
    ctx.output(2, surface);
  };
  s.eval = [](EvalContext& ctx) {
    const EvalEnvironment& env = ctx.environment();
    double n = ctx.scalar("near"), r = ctx.scalar("ratio");
    double scene = linearizeDepthRatioReference(env.sceneAt(SceneSampler::SceneDepth, ctx.input("screen_uv"))[0], n, r);
    double surface = linearizeDepthRatioReference(env.fragDepth[0], n, r);
    const Value& view = ctx.input("view");
    double factor = waterDepthRayFactorAxisReference(ctx.input("camera_axis"), view);
    double v = ctx.options<WaterDepthOptions>().vertical ? std::abs(glsl::safeNormalize(view)[1]) : 1.0;
    ctx.output(0, Value::scalar(waterDepthThicknessReference(scene, surface, factor, v)));
    ctx.output(1, Value::scalar(scene));
    ctx.output(2, Value::scalar(surface));
  };
  s.tolerance = 1e-5;  // relative, as linearize_depth
  s.hardCases = {
      {"sky behind the water (scene depth 1.0, the default)", {}, {}, "large but finite", 0, 1e30},
      {"sky, vertical, grazing view", {{"view", Value::vector({1, 0, 0})}}, {{"measure", "vertical"}},
       "0 (|V.y| = 0), finite", 0, 1e30},
      {"zero-length view", {{"view", Value::vector({0, 0, 0})}}, {{"measure", "vertical"}}, "0, finite", 0, 1e30},
  };
  return s;
}

}  // namespace wg::nodes
