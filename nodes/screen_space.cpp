// Screen space and scene: scene_depth (the depth pre-pass at this pixel: raw, linear and
// the world point), scene_color (GrabPass-style refraction with a clamped distortion),
// planar_reflection (the reflection pass at this pixel), cubemap_reflection (the sky's cube
// map along reflect(-V, N)) and ssr (the deferred water article's screen-space reflection march). All read
// scene textures the runtime renders in the passes their `resources` name; all are
// fragment-only. Their references read the EvalEnvironment's scene fields: a scene texture
// returns the same value wherever it is sampled.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/linearize_depth_call.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/screen_lookup.h"
#include "nodes/screen_space_reference.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {
namespace {

const char* const kScreenUvDoc = "screen position to read, (0,0) bottom left to (1,1) top right (default: this pixel)";

Value mixVec3(const Value& a, const Value& b, double t) {
  return Value::vector({glsl::mix(a[0], b[0], t), glsl::mix(a[1], b[1], t), glsl::mix(a[2], b[2], t)});
}

struct PlanarReflectionOptions {
  bool flipY;
};
PlanarReflectionOptions parsePlanarReflectionOptions(const OptionReader& o) { return {o.flag("flip_y")}; }

struct SsrOptions {
  int steps;
};
SsrOptions parseSsrOptions(const OptionReader& o) { return {o.integer("steps")}; }

}  // namespace

NodeSpec sceneDepthNode() {
  NodeSpec s;
  s.type = "scene_depth";
  s.family = "screen space";
  s.summary = "The opaque scene behind this pixel from the depth pre-pass: raw depth, linear view depth and its "
              "world position.";
  s.formula =
      "depth = texture(u_scene_depth, screen_uv).r (1.0 = sky); linear = n / ((1 - d) + d n / f) with "
      "u_camera_near_far (as linearize_depth: finite for the sky and f = inf, <= 1e30); position = camera + "
      "transpose(mat3(V)) * ((ndc.x + P[2][0]) / P[0][0], (ndc.y + P[2][1]) / P[1][1], -1) * linear, ndc = 2 uv - 1 "
      "(a perspective projection and a rigid view matrix; scales floored at 1e-6, result clamped to +-1e30).";
  s.source = "classic WebGL water renderer (water depth from the linearised depth texture, near 0.1, far 50); deferred water article (the scene's position "
             "G-buffer, SceneCameraSpacePosAndDepth); advanced shaders tutorial (linearizeDepth)";
  s.cost = "one depth-texture fetch (runs the depth_prepass: one extra draw of the opaque scene, 4 bytes/pixel); "
           "linear ~8 ALU; position ~25 ALU";
  s.inputs = {ports::fromBuiltin("screen_uv", Type::Vec2, Builtin::ScreenUv, kScreenUvDoc)};
  for (auto& p : nearRatioPorts()) s.inputs.push_back(p);
  // Near and near / far are the same for every pixel of a draw: a near_far_ratio op.
  s.derive = [](DeriveContext& ctx) { deriveNearRatio(ctx, ValueRef::builtin(Builtin::CameraNearFar)); };
  s.outputs = {ports::fixed("depth", Type::Float, "depth-buffer value in [0, 1]; 1.0 where only sky is behind"),
               ports::fixed("linear", Type::Float, "linear view depth of the scene point (the far plane for the sky)"),
               ports::fixed("position", Type::Vec3, "world position of the scene point (e.g. where caustics fall)")};
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {SceneResource::SceneDepth};
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{kDepthTextureFact, {}, {}};
  };
  s.emit = [](EmitContext& ctx) {
    GlslExpr uv = ctx.input("screen_uv");
    GlslExpr raw = ctx.temporary(Type::Float, ctx.sampleScene("scene_depth", uv) + ".r");
    std::string fn = linearizeDepthRatioFunction(kDepthTextureFact, ctx.knownBuiltin(Builtin::CameraNearFar));
    GlslExpr lin = ctx.temporary(Type::Float, EmitContext::call(fn, {raw, ctx.input("near"), ctx.input("ratio")}));
    ctx.output(0, raw);
    ctx.output(1, lin);
    ctx.output(2, EmitContext::call("wg_scene_depth_position", {uv, lin, ctx.builtin(Builtin::CameraPosition),
                                                                ctx.builtin(Builtin::View),
                                                                ctx.builtin(Builtin::Projection)}));
  };
  s.eval = [](EvalContext& ctx) {
    const EvalEnvironment& env = ctx.environment();
    double raw = env.sceneAt(SceneSampler::SceneDepth, ctx.input("screen_uv"))[0];
    double lin = linearizeDepthRatioReference(raw, ctx.scalar("near"), ctx.scalar("ratio"));
    ctx.output(0, Value::scalar(raw));
    ctx.output(1, Value::scalar(lin));
    ctx.output(2, sceneDepthPositionReference(ctx.input("screen_uv"), lin, env.cameraPosition, env.view, env.projection));
  };
  s.tolerance = 1e-5;  // relative, as linearize_depth
  // Zero view and projection matrices (scales floored, a finite position) need a probe
  // environment a hard case cannot set: the suite's case no_camera_matrices has them.
  s.hardCases = {
      {"sky, depth 1.0 (the default scene)", {}, {}, "linear = the far plane (100), finite", 0, 100, "linear"},
      {"screen position far outside [0, 1]", {{"screen_uv", Value::vector({1e5, -1e5})}}, {},
       "clamped to +-1e30, finite", -1e30, 1e30, "position"},
  };
  return s;
}

NodeSpec sceneColorNode() {
  NodeSpec s;
  s.type = "scene_color";
  s.family = "screen space";
  s.summary = "Refraction GrabPass-style: the opaque scene's colour behind the water at this pixel, moved by a "
              "distortion offset.";
  s.formula = "uv' = clamp(screen_uv + distortion, 0, 1); color = texture(u_scene_color, uv').rgb. The clamp keeps "
              "every distorted look-up on screen.";
  s.source = "stylized water shader (refraction from the grabbed screen, GrabPass); advanced shaders tutorial (screen-space distorted refraction); classic WebGL water renderer "
             "(distortion (dudv * 2 - 1) * 0.03)";
  s.cost = "one texture fetch + 4 ALU; runs the scene_color_copy pass (a blit of the frame, 8 bytes/pixel RGBA16F)";
  makeScreenLookup(s, SceneResource::SceneColor,
                   "offset in screen units (e.g. dudv_distortion.offset or normal.xz * 0.03)",
                   "scene colour seen through the water");
  s.hardCases = {
      {"distortion pushing far off screen", {{"distortion", Value::vector({5, -5})}}, {}, "uv clamped to (1, 0)", 0, 1,
       "uv"},
      {"distortion 1e30", {{"distortion", Value::vector({1e30, 1e30})}}, {}, "uv clamped to (1, 1)", 0, 1, "uv"},
      {"screen position outside [0, 1]", {{"screen_uv", Value::vector({-3, 7})}}, {}, "uv clamped", 0, 1, "uv"},
  };
  return s;
}

NodeSpec planarReflectionNode() {
  NodeSpec s;
  s.type = "planar_reflection";
  s.family = "screen space";
  s.summary = "The planar reflection pass (the scene mirrored about the water plane) looked up at this pixel, with "
              "a distortion offset.";
  s.formula =
      "uv' = clamp(screen_uv + distortion, 0, 1); flip_y: uv' = (uv'.x, 1 - uv'.y); color = texture(u_reflection, "
      "uv').rgb. watergraph's runtime renders the reflection through the real camera with the scene mirrored "
      "(view-projection * scale(1, -1, 1), clip plane at the water), so the mirrored image lines up with the screen "
      "and needs no flip; flip_y serves engines that render it through a mirrored camera (the classic WebGL water renderer's "
      "reflectTexCoords = (ndc.x, -ndc.y)).";
  s.source = "classic WebGL water renderer (reflection pass with the view mirrored and clip plane (0, 1, 0, 0); y-flipped look-up); advanced shaders tutorial (planar "
             "reflection with a mirrored camera); stylized water shader (reflection matrix)";
  s.cost = "one texture fetch + 4 ALU; runs the planar_reflection pass: a second draw of the opaque scene and sky "
           "into an RGBA16F + depth target (12 bytes/pixel)";
  s.inputs = {ports::fromBuiltin("screen_uv", Type::Vec2, Builtin::ScreenUv, kScreenUvDoc),
              ports::fixed("distortion", Type::Vec2, Value::vector({0, 0}),
                           "offset in screen units (the classic WebGL water renderer: (dudv * 2 - 1) * 0.03)")};
  s.outputs = {ports::fixed("color", Type::Vec3, "the reflected scene"),
               ports::fixed("uv", Type::Vec2, "the look-up position in the reflection texture, in [0, 1]")};
  s.options = {ports::flag("flip_y", false,
                           "flip v after distorting: for reflection textures rendered through a mirrored camera "
                           "(upside down); false for watergraph's runtime")};
  s.parseOptions = optionParser(parsePlanarReflectionOptions);
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {SceneResource::PlanarReflection};
  s.emit = [](EmitContext& ctx) {
    bool flip = ctx.options<PlanarReflectionOptions>().flipY;
    GlslExpr uv = ctx.temporary(
        Type::Vec2, EmitContext::call(flip ? "wg_planar_reflection_uv_flipped" : "wg_scene_color_uv",
                                      {ctx.input("screen_uv"), ctx.input("distortion")}));
    ctx.output(0, ctx.sampleScene("planar_reflection", uv) + ".rgb");
    ctx.output(1, uv);
  };
  s.eval = [](EvalContext& ctx) {
    Value uv = sceneColorUvReference(ctx.input("screen_uv"), ctx.input("distortion"));
    if (ctx.options<PlanarReflectionOptions>().flipY) uv[1] = 1.0 - uv[1];
    ctx.output(0, ctx.environment().sceneAt(SceneSampler::Reflection, uv));
    ctx.output(1, uv);
  };
  s.tolerance = 1e-6;
  s.hardCases = {
      {"distortion far off screen", {{"distortion", Value::vector({-4, 9})}}, {}, "uv clamped to (0, 1)", 0, 1, "uv"},
      {"flipped, distortion far off screen", {{"distortion", Value::vector({-4, 9})}}, {{"flip_y", true}},
       "uv clamped, then flipped: (0, 0)", 0, 1, "uv"},
  };
  return s;
}

NodeSpec cubemapReflectionNode() {
  NodeSpec s;
  s.type = "cubemap_reflection";
  s.family = "screen space";
  s.summary = "The environment cube map (the sky) along the mirror direction reflect(-V, N).";
  s.formula = "R = normalize(reflect(-normalize(V), normalize(N))) (safe normalisation: zero inputs give R = 0, "
              "never NaN); color = texture(u_environment, R).rgb.";
  s.source = "advanced shaders tutorial (cube-map reflection: textureCube(envMap, reflect(-V, N)))";
  s.cost = "one cube-map fetch + ~15 ALU; runs the environment_cubemap pass (6 faces of the sky, 128^2 RGBA16F each)";
  s.inputs = {ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "unit surface normal"),
              ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "unit vector from the surface to the viewer")};
  s.outputs = {ports::fixed("color", Type::Vec3, "the environment seen in the mirror direction"),
               ports::fixed("direction", Type::Vec3, "the unit mirror direction R")};
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {SceneResource::Environment};
  s.emit = [](EmitContext& ctx) {
    GlslExpr r = ctx.temporary(Type::Vec3, EmitContext::call("wg_reflect_dir", {ctx.input("normal"), ctx.input("view")}));
    ctx.output(0, ctx.sampleScene("environment", r) + ".rgb");
    ctx.output(1, r);
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, ctx.environment().environmentColor);
    ctx.output(1, reflectDirReference(ctx.input("normal"), ctx.input("view")));
  };
  s.tolerance = 1e-6;
  s.hardCases = {
      {"zero normal and view", {{"normal", Value::vector({0, 0, 0})}, {"view", Value::vector({0, 0, 0})}}, {},
       "R = 0, finite", -1, 1, "direction"},
      {"grazing view", {{"view", Value::vector({1, 0, 0})}}, {}, "R = (-1, 0, 0)", -1, 1, "direction"},
      {"view from below the surface", {{"view", Value::vector({0, -1, 0})}}, {}, "R unit, finite", -1, 1, "direction"},
  };
  return s;
}

NodeSpec ssrNode() {
  NodeSpec s;
  s.type = "ssr";
  s.family = "screen space";
  s.summary = "Screen-space reflection (the deferred water article): march the reflected ray through the depth buffer for N steps, "
              "fade at the screen edges and with distance, fall back to another reflection.";
  s.formula =
      "R = reflect(-V, N) (safe), c = R.N, stride = step / max(0.6, c^2); for i < steps: p = position + (i + 0.5) "
      "stride R, q = View p, clip = Projection q; stop (no hit) if clip.w <= 1e-6 (behind the camera) or uv = "
      "clip.xy / clip.w / 2 + 1/2 leaves [0, 1]; hit when (-q.z - linear(scene_depth(uv)))^2 < tolerance^2 "
      "growth^i. fade = max(1 - (0.01 + |2 uv - 1|^2)^(1/4), 0) * min(1, fade_distance / d), d = the surface's "
      "view depth; confidence = hit * fade; color = mix(fallback, scene_color(uv), confidence). The reference "
      "marches against the scene depth image where it has one (check, deferred water), else against one depth at "
      "every screen position.";
  s.source = "deferred water article (listing 8: 10 steps, step 7 / max(0.6, (R.N)^2), squared tolerance 16 growing by 1.1 per step, "
             "edge fade (0.01 + dx^2 + dy^2)^(1/4), distance fade, fall back to the background); the defaults here are "
             "scaled from the source's units (haze over 2000) to the metres of the built-in scene";
  s.cost = "per step: two mat4 products, one depth fetch, ~20 ALU (steps = 10: ~10 fetches, ~400 ALU); plus one "
           "colour fetch; runs depth_prepass and scene_color_copy. Quality levels: steps 5 (coarse, misses thin "
           "objects), 10 (the source), 20-64 (finer, linear cost)";
  s.inputs = {
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition, "world position of the reflecting surface"),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "unit surface normal"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "unit vector from the surface to the viewer"),
      ports::color(ports::fixed("fallback", Type::Vec3, Value::vector({0, 0, 0}),
                                "colour where the march finds nothing (e.g. cubemap_reflection.color or planar_reflection.color)")),
      ports::fixed("step", Type::Float, Value::scalar(1.0), "march step in metres at steep reflections (source: 7 units)"),
      ports::fixed("tolerance", Type::Float, Value::scalar(0.5),
                   "hit tolerance in metres of view depth at the first step (source: sqrt(16) = 4 units)"),
      ports::fixed("growth", Type::Float, Value::scalar(1.1), "factor on the squared tolerance per step (source: 1.1)"),
      ports::fixed("fade_distance", Type::Float, Value::scalar(20.0),
                   "view depth up to which reflections keep full strength; beyond, fade_distance / depth"),
  };
  s.outputs = {ports::fixed("color", Type::Vec3, "the reflection: the hit's scene colour blended with the fallback"),
               ports::fixed("confidence", Type::Float, "hit * fade, in [0, 1] (0: only the fallback)"),
               ports::fixed("uv", Type::Vec2, "screen position of the hit ((0.5, 0.5) when nothing was hit)")};
  s.options = {ports::knob(ports::integer("steps", 10, 1, 64, "ray-march steps (the deferred water article: 10); cost grows linearly"),
                          {4, 10, 20, 40, 64})};
  s.parseOptions = optionParser(parseSsrOptions);
  s.stages = kFragmentStage;
  s.isSource = true;
  s.resources = {SceneResource::SceneDepth, SceneResource::SceneColor};
  s.emit = [](EmitContext& ctx) {
    GlslExpr n = ctx.input("normal");
    GlslExpr r = ctx.temporary(Type::Vec3, EmitContext::call("wg_reflect_dir", {n, ctx.input("view")}));
    GlslExpr c = ctx.temporary(Type::Float, "dot(" + r + ", " + EmitContext::call("wg_safe_normalize_vec3", {n}) + ")");
    GlslExpr view = ctx.builtin(Builtin::View);
    GlslExpr pos = ctx.input("position");
    GlslExpr m = ctx.temporary(
        Type::Vec3,
        EmitContext::call("wg_ssr_march",
                          {ctx.sceneTexture("scene_depth"), pos, r, c, view, ctx.builtin(Builtin::Projection),
                           ctx.builtin(Builtin::CameraNearFar), std::to_string(ctx.options<SsrOptions>().steps),
                           ctx.input("step"), ctx.input("tolerance"), ctx.input("growth")}));
    GlslExpr dist = "(-(" + view + " * vec4(" + pos + ", 1.0)).z)";
    GlslExpr conf = ctx.temporary(
        Type::Float, m + ".z * " + EmitContext::call("wg_ssr_fade", {m + ".xy", dist, ctx.input("fade_distance")}));
    ctx.output(0, "mix(" + ctx.input("fallback") + ", textureLod(" + ctx.sceneTexture("scene_color") + ", " + m +
                      ".xy, 0.0).rgb, " + conf + ")");
    ctx.output(1, conf);
    ctx.output(2, m + ".xy");
  };
  s.eval = [](EvalContext& ctx) {
    const EvalEnvironment& env = ctx.environment();
    const Value& n = ctx.input("normal");
    const Value& pos = ctx.input("position");
    Value r = reflectDirReference(n, ctx.input("view"));
    double c = glsl::dot(r, glsl::safeNormalize(n));
    auto depthAt = [&env](double u, double v) { return env.sceneAt(SceneSampler::SceneDepth, u, v)[0]; };
    SsrMarch m = ssrMarchReference(depthAt, pos, r, c, env.view, env.projection, env.cameraNearFar,
                                   ctx.options<SsrOptions>().steps, ctx.scalar("step"), ctx.scalar("tolerance"),
                                   ctx.scalar("growth"));
    // -(View * (p, 1)).z: row 2 of the column-major view matrix.
    const Value& v = env.view;
    double dist = -(v[2] * pos[0] + v[6] * pos[1] + v[10] * pos[2] + v[14]);
    double conf = (m.hit ? 1.0 : 0.0) * ssrFadeReference(m.u, m.v, dist, ctx.scalar("fade_distance"));
    ctx.output(0, mixVec3(ctx.input("fallback"), env.sceneAt(SceneSampler::SceneColor, m.u, m.v), conf));
    ctx.output(1, Value::scalar(conf));
    ctx.output(2, Value::vector({m.u, m.v}));
  };
  s.tolerance = 1e-4;  // a hit decided by float32 depths may differ at the tolerance's edge
  // Zero view and projection matrices (clip w = 0 at every step: no hit, confidence 0) need
  // a probe environment a hard case cannot set: the suite's case no_camera_matrices has them.
  s.hardCases = {
      {"zero normal and view", {{"normal", Value::vector({0, 0, 0})}, {"view", Value::vector({0, 0, 0})}}, {},
       "R = 0: finite, no hit", 0, 1, "confidence"},
      {"zero step, negative growth, 64 steps",
       {{"step", Value::scalar(0)}, {"growth", Value::scalar(-3)}}, {{"steps", 64}}, "finite, no hit", 0, 1,
       "confidence"},
      {"huge coordinates 1e5 m", {{"position", Value::vector({1e5, 0, -1e5})}}, {}, "finite", 0, 1, "confidence"},
  };
  return s;
}

}  // namespace wg::nodes
