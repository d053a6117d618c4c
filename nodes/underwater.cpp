// underwater: the deferred water article's deferred water in one node. Its fragment shader runs as a
// full-screen pass (the runtime's deferred_water pass: see docs/architecture.md, "Deferred
// water"): per pixel it reads the water G-buffer (the surface's position and depth), the
// scene's depth and colour, and picks one of the five camera/pixel cases. The rest of the
// graph supplies the surface shading (reflection, specular, foam) and the caustics; this
// node adds the water body: absorption, refraction, caustics, haze. The `camera` option
// specialises away the cases the scene's camera cannot reach.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/linearize_depth_call.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/screen_space_reference.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {

namespace {

enum class UnderwaterCamera { Auto, Above, Below };

struct UnderwaterOptions {
  UnderwaterCamera camera;
};
UnderwaterOptions parseUnderwaterOptions(const OptionReader& o) {
  return {o.choice<UnderwaterCamera>(
      "camera", {{"auto", UnderwaterCamera::Auto}, {"above", UnderwaterCamera::Above}, {"below", UnderwaterCamera::Below}})};
}

}  // namespace

NodeSpec underwaterNode() {
  NodeSpec s;
  s.type = "underwater";
  s.family = "screen space";
  s.summary = "The deferred water article's deferred water: one full-screen pass shading the five camera/pixel cases (camera above or "
              "below the surface, pixel above, under water near, or far).";
  s.formula =
      "Per pixel: W = water G-buffer (surface point, covered where its depth < 1), S = scene point from the scene "
      "depth (see scene_depth), sky where that depth is 1.0, h = W.y (covered) or water_level, C = camera. Camera "
      "above (C.y >= water_level): case 1 if not covered or h - S.y <= 0: the scene colour; else d_W = |W - C|, d_S "
      "= |S - C| (1e30 for the sky), T = exp(-sigma max(d_S - d_W, 0)); case 4 if max(T) > 1/256 and d_S < "
      "haze_distance: r = scene_color(clamp(uv + refraction_strength (1 - T.b) N.xz, 0, 1)), body = T (r + "
      "caustics_color caustics max(r)) + (1 - T) water_color diffuse; case 5 otherwise: body = water_color "
      "diffuse; color = mix(transmittance body + surface, haze_color, clamp(d_W / haze_distance, 0, 1)). Camera "
      "below: k = min(1, depth_light / (water_level - C.y)); case 2 if not covered or h - S.y > 0: T = exp(-sigma "
      "d_S), color = k (T (s + caustics_color caustics max(s)) + (1 - T) water_color diffuse), s = the scene "
      "colour; case 3 otherwise (looking up through the surface): T = exp(-sigma d_W), color = k (T "
      "(transmittance_below scene_color(clamp(uv + refraction_strength N.xz)) + surface_below) + (1 - T) "
      "water_color diffuse). The reference reads the G-buffer as (world_position, frag_depth) of the environment "
      "and the scene depth and colour through the environment at the look-up's position (the read-back images in "
      "check, else the one value of this pixel).";
  s.source = "deferred water article (deferred water rendering: listings 5 and 10-18, the five cases, diffuseIntensityWater 0.35, "
             "absorption over the in-water view distance, depth-dependent light, distortion by (1 - T.b) N.xz, "
             "caustics times the brightest channel, haze by the surface distance); classic WebGL water renderer (deep colour (0, 0.1, 0.2), "
             "distortion 0.03); Beer-Lambert coefficients of pure water from Pope & Fry 1997";
  s.cost = "full-screen: 3 fetches (G-buffer, scene depth, scene colour) + ~60 ALU per pixel, +1 fetch in cases 3 "
           "and 4; runs depth_prepass, scene_color_copy and deferred_water (a draw of the water grid into a "
           "2 x RGBA32F + depth G-buffer, 36 bytes/pixel). camera: above or below emits only that half of the cases "
           "(no camera branch, half the code)";
  s.inputs = {
      ports::fromBuiltin("screen_uv", Type::Vec2, Builtin::ScreenUv, "this pixel's screen position"),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal,
                         "surface normal (default: the G-buffer's), for the refraction distortion"),
      ports::color(ports::fixed("surface", Type::Vec3, Value::vector({0, 0, 0}),
                                "light the surface sends to a viewer above: reflection * Fresnel + specular + foam (the graph's "
                                "usual surface shading)")),
      ports::fixed("transmittance", Type::Float, Value::scalar(1.0),
                   "fraction of the water body's light passing the surface upwards (e.g. fresnel.transmittance)"),
      ports::color(ports::fixed("surface_below", Type::Vec3, Value::vector({0, 0, 0}),
                                "light the surface sends to a viewer below (specular, reflection under total internal reflection)")),
      ports::fixed("transmittance_below", Type::Float, Value::scalar(1.0),
                   "fraction of the light above passing down into the water (Snell's window: fresnel with direction "
                   "water_to_air, transmittance)"),
      ports::color(ports::fixed("water_color", Type::Vec3, Value::vector({0.0, 0.1, 0.2}), "the water's own colour (the classic WebGL water renderer's deep colour)")),
      ports::fixed("diffuse", Type::Float, Value::scalar(0.35), "its brightness (the deferred water article's diffuseIntensityWater 0.35)"),
      ports::fixed("sigma", Type::Vec3, Value::vector({0.340, 0.0565, 0.00922}),
                   "absorption coefficients in 1/m (R, G, B; pure water, Pope & Fry 1997)"),
      ports::fixed("refraction_strength", Type::Float, Value::scalar(0.03),
                   "screen-space distortion per unit of N.xz (the classic WebGL water renderer: 0.03)"),
      ports::fixed("caustics", Type::Float, Value::scalar(0.0),
                   "caustic intensity on the scene point (e.g. texture_caustics at scene_depth.position)"),
      ports::color(ports::fixed("caustics_color", Type::Vec3, Value::vector({1, 1, 1}), "colour of the caustic light")),
      ports::fixed("haze_distance", Type::Float, Value::scalar(120.0),
                   "distance of the water surface at which haze is complete; also the farthest scene point shaded "
                   "as case 4 (the deferred water article: 2000 units)"),
      ports::color(ports::fixed("haze_color", Type::Vec3, Value::vector({0.70, 0.80, 0.90}), "the background haze blends to")),
      ports::fixed("water_level", Type::Float, Value::scalar(0.0),
                   "height of the still water plane: the camera is under water below it"),
      ports::fixed("depth_light", Type::Float, Value::scalar(4.0),
                   "camera depth in metres down to which the light is full; deeper it falls as depth_light / depth"),
  };
  for (auto& p : nearRatioPorts()) s.inputs.push_back(p);
  // Near and near / far are the same for every pixel of a draw: a near_far_ratio op.
  s.derive = [](DeriveContext& ctx) { deriveNearRatio(ctx, ValueRef::builtin(Builtin::CameraNearFar)); };
  s.outputs = {ports::fixed("color", Type::Vec3, "the pixel's final colour"),
               ports::fixed("case", Type::Float, "which of the deferred water article's cases shaded it: 1 to 5")};
  s.options = {ports::choice("camera", {"auto", "above", "below"}, "auto",
                             "where the scene's camera can be: auto decides per frame (camera.y < water_level); above "
                             "or below emit only cases 1, 4, 5 or 2, 3 (a scene whose camera stays above water "
                             "carries no underwater branch)")};
  s.parseOptions = optionParser(parseUnderwaterOptions);
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {SceneResource::Underwater, SceneResource::SceneDepth, SceneResource::SceneColor};
  s.emit = [](EmitContext& ctx) {
    GlslExpr uv = ctx.input("screen_uv");
    GlslExpr water = ctx.temporary(Type::Vec4, ctx.sampleScene("underwater", uv));
    GlslExpr raw = ctx.temporary(Type::Float, ctx.sampleScene("scene_depth", uv) + ".r");
    GlslExpr cam = ctx.builtin(Builtin::CameraPosition);
    GlslExpr lin = EmitContext::call("wg_linearize_depth_ratio", {raw, ctx.input("near"), ctx.input("ratio")});
    GlslExpr scene = ctx.temporary(
        Type::Vec3, EmitContext::call("wg_scene_depth_position",
                                      {uv, lin, cam, ctx.builtin(Builtin::View), ctx.builtin(Builtin::Projection)}));
    GlslExpr sky = "(" + raw + " >= 1.0 ? 1.0 : 0.0)";
    GlslExpr colorTex = ctx.sceneTexture("scene_color");
    UnderwaterCamera mode = ctx.options<UnderwaterOptions>().camera;
    GlslExpr level = ctx.input("water_level");
    auto above = [&] {
      return EmitContext::call("wg_underwater_from_above",
                               {colorTex, uv, water, scene, sky, cam, ctx.input("normal"), ctx.input("surface"),
                                ctx.input("transmittance"), ctx.input("water_color"), ctx.input("diffuse"),
                                ctx.input("sigma"), ctx.input("refraction_strength"), ctx.input("caustics"),
                                ctx.input("caustics_color"), ctx.input("haze_distance"), ctx.input("haze_color"), level});
    };
    auto below = [&] {
      return EmitContext::call("wg_underwater_from_below",
                               {colorTex, uv, water, scene, sky, cam, ctx.input("normal"), ctx.input("surface_below"),
                                ctx.input("transmittance_below"), ctx.input("water_color"), ctx.input("diffuse"),
                                ctx.input("sigma"), ctx.input("refraction_strength"), ctx.input("caustics"),
                                ctx.input("caustics_color"), ctx.input("depth_light"), level});
    };
    GlslExpr r;
    if (mode == UnderwaterCamera::Above) r = ctx.temporary(Type::Vec4, above());
    else if (mode == UnderwaterCamera::Below) r = ctx.temporary(Type::Vec4, below());
    else r = ctx.temporary(Type::Vec4, "(" + cam + ".y < " + level + " ? " + below() + " : " + above() + ")");
    ctx.output(0, r + ".rgb");
    ctx.output(1, r + ".a");
  };
  s.eval = [](EvalContext& ctx) {
    const EvalEnvironment& env = ctx.environment();
    UnderwaterInputs in;
    in.uv = ctx.input("screen_uv");
    const Value& wp = env.worldPosition;
    in.water = Value::vector({wp[0], wp[1], wp[2], env.fragDepth[0]});
    double raw = env.sceneAt(SceneSampler::SceneDepth, in.uv)[0];
    double lin = linearizeDepthRatioReference(raw, ctx.scalar("near"), ctx.scalar("ratio"));
    in.camera = env.cameraPosition;
    in.scene = sceneDepthPositionReference(in.uv, lin, in.camera, env.view, env.projection);
    in.sky = raw >= 1.0 ? 1.0 : 0.0;
    in.normal = ctx.input("normal");
    in.waterColor = ctx.input("water_color");
    in.diffuse = ctx.scalar("diffuse");
    in.sigma = ctx.input("sigma");
    in.strength = ctx.scalar("refraction_strength");
    in.caustics = ctx.scalar("caustics");
    in.causticsColor = ctx.input("caustics_color");
    in.hazeDistance = ctx.scalar("haze_distance");
    in.hazeColor = ctx.input("haze_color");
    in.level = ctx.scalar("water_level");
    in.depthLight = ctx.scalar("depth_light");
    in.sceneColorAt = [&env](double u, double v) { return env.sceneAt(SceneSampler::SceneColor, u, v); };
    UnderwaterCamera mode = ctx.options<UnderwaterOptions>().camera;
    bool below = mode == UnderwaterCamera::Below || (mode == UnderwaterCamera::Auto && in.camera[1] < in.level);
    UnderwaterResult r;
    if (below) {
      in.surface = ctx.input("surface_below");
      in.transmittance = ctx.scalar("transmittance_below");
      r = underwaterFromBelowReference(in);
    } else {
      in.surface = ctx.input("surface");
      in.transmittance = ctx.scalar("transmittance");
      r = underwaterFromAboveReference(in);
    }
    ctx.output(0, r.color);
    ctx.output(1, Value::scalar(r.which));
  };
  s.tolerance = 1e-5;
  s.hardCases = {
      {"sky behind (the default scene)", {}, {}, "case 1: the scene colour, finite", 0, 1},
      {"camera fixed below, sky depth 1.0", {}, {{"camera", "below"}}, "case 2 or 3, finite", 0, 1},
      {"zero haze distance, zero absorption", {{"haze_distance", Value::scalar(0)}, {"sigma", Value::vector({0, 0, 0})}},
       {}, "finite", 0, 1},
      {"camera exactly at the water level, below", {{"water_level", Value::scalar(10)}}, {{"camera", "below"}},
       "depth floored at 1e-6: finite", 0, 1},
      {"huge coordinates 1e5 m", {{"water_level", Value::scalar(-1e5)}, {"normal", Value::vector({0, 0, 0})}}, {},
       "finite", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
