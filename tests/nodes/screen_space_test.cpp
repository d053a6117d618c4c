// The screen-space and scene nodes: scene_depth, scene_color, planar_reflection,
// cubemap_reflection, ssr and underwater. Values worked out by hand (or by a few lines of
// independent double maths here) with real camera matrices; the hard inputs (sky depth
// 1.0, clip w <= 0, distortion off screen); the deferred pass's shader interface; and the
// camera specialisation of underwater (a camera above water carries no underwater branch).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "nodes/screen_space_reference.h"
#include "node_eval.h"

namespace wg {
namespace {

using test::runNode;

struct Vec3d {
  double x, y, z;
};
Vec3d sub(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot3d(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross3d(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3d normalize(Vec3d a) {
  double l = std::sqrt(dot3d(a, a));
  return {a.x / l, a.y / l, a.z / l};
}

// Column-major mat4 Values as GLSL (and glm) hold them: m[col][row] = c[col * 4 + row].
Value lookAt(Vec3d eye, Vec3d centre, Vec3d up) {
  Vec3d f = normalize(sub(centre, eye)), s = normalize(cross3d(f, up)), u = cross3d(s, f);
  Value m = Value::ofType(Type::Mat4);
  m[0] = s.x, m[4] = s.y, m[8] = s.z;
  m[1] = u.x, m[5] = u.y, m[9] = u.z;
  m[2] = -f.x, m[6] = -f.y, m[10] = -f.z;
  m[12] = -dot3d(s, eye), m[13] = -dot3d(u, eye), m[14] = dot3d(f, eye), m[15] = 1;
  return m;
}
Value perspective(double fovyDegrees, double aspect, double n, double f) {
  double t = std::tan(fovyDegrees * M_PI / 360.0);
  Value m = Value::ofType(Type::Mat4);
  m[0] = 1 / (aspect * t);
  m[5] = 1 / t;
  m[10] = -(f + n) / (f - n);
  m[11] = -1;
  m[14] = -2 * f * n / (f - n);
  return m;
}
void mulPoint(const Value& m, const double p[4], double out[4]) {
  for (int r = 0; r < 4; ++r) {
    out[r] = 0;
    for (int c = 0; c < 4; ++c) out[r] += m[c * 4 + r] * p[c];
  }
}
using test::depthOf;

EvalEnvironment cameraEnv(Vec3d eye, Vec3d centre, Vec3d up = {0, 1, 0}) {
  EvalEnvironment env;
  env.cameraPosition = Value::vector({eye.x, eye.y, eye.z});
  env.view = lookAt(eye, centre, up);
  env.projection = perspective(60, 16.0 / 9.0, 0.1, 100);
  env.cameraNearFar = Value::vector({0.1, 100});
  return env;
}

// --- scene_depth -----------------------------------------------------------------------

TEST(SceneDepth, SkyIsTheFarPlaneAndFinite) {
  auto out = runNode("scene_depth", {});  // the default environment: depth 1.0, no matrices
  EXPECT_EQ(out.scalar("depth"), 1.0);
  EXPECT_NEAR(out.scalar("linear"), 100.0, 1e-12);
  EXPECT_TRUE(out["position"].allFinite());
}

TEST(SceneDepth, LinearDepthAndPositionByHand) {
  // Camera at (1, 2, 3) looking along -z: view space is world space shifted.
  EvalEnvironment env = cameraEnv({1, 2, 3}, {1, 2, -10});
  env.projection = perspective(90, 1.0, 0.1, 100);  // P00 = P11 = 1
  env.sceneDepth = Value::scalar(depthOf(8.0, 0.1, 100));
  auto out = runNode("scene_depth", {{"screen_uv", Value::vector({0.75, 0.5})}}, {}, env);
  EXPECT_NEAR(out.scalar("linear"), 8.0, 1e-9);
  // ndc.x = 0.5 -> x_view = 0.5 * 8 = 4, z_view = -8.
  EXPECT_NEAR(out["position"][0], 5.0, 1e-9);
  EXPECT_NEAR(out["position"][1], 2.0, 1e-9);
  EXPECT_NEAR(out["position"][2], -5.0, 1e-9);
}

TEST(SceneDepth, PositionProjectsBackToItsPixel) {
  EvalEnvironment env = cameraEnv({14, 7, -12}, {-4, -1.5, 4});
  for (double u : {0.1, 0.5, 0.93})
    for (double v : {0.05, 0.6})
      for (double lin : {0.5, 7.0, 60.0}) {
        env.sceneDepth = Value::scalar(depthOf(lin, 0.1, 100));
        auto out = runNode("scene_depth", {{"screen_uv", Value::vector({u, v})}}, {}, env);
        double p[4] = {out["position"][0], out["position"][1], out["position"][2], 1}, q[4], c[4];
        mulPoint(env.view, p, q);
        mulPoint(env.projection, q, c);
        EXPECT_NEAR(-q[2], lin, 1e-9 * lin);
        EXPECT_NEAR(c[0] / c[3] * 0.5 + 0.5, u, 1e-9);
        EXPECT_NEAR(c[1] / c[3] * 0.5 + 0.5, v, 1e-9);
      }
}

// --- scene_color, planar_reflection, cubemap_reflection -----------------------------------

TEST(SceneColor, DistortionIsClampedToTheScreen) {
  EvalEnvironment env;
  env.sceneColor = Value::vector({0.2, 0.4, 0.6});
  auto out = runNode("scene_color", {{"screen_uv", Value::vector({0.5, 0.5})}, {"distortion", Value::vector({0.7, -0.9})}},
                     {}, env);
  EXPECT_EQ(out["uv"][0], 1.0);
  EXPECT_EQ(out["uv"][1], 0.0);
  EXPECT_EQ(out["color"][1], 0.4);
  auto inside = runNode("scene_color", {{"screen_uv", Value::vector({0.25, 0.5})}, {"distortion", Value::vector({0.03, -0.01})}});
  EXPECT_NEAR(inside["uv"][0], 0.28, 1e-15);
  EXPECT_NEAR(inside["uv"][1], 0.49, 1e-15);
}

TEST(PlanarReflection, NoFlipForTheRuntimeAndAFlipOnRequest) {
  EvalEnvironment env;
  env.reflectionColor = Value::vector({0.9, 0.8, 0.7});
  std::vector<std::pair<std::string, Value>> in{{"screen_uv", Value::vector({0.2, 0.3})},
                                                {"distortion", Value::vector({0.01, 0.02})}};
  auto plain = runNode("planar_reflection", in, {}, env);
  EXPECT_NEAR(plain["uv"][0], 0.21, 1e-15);
  EXPECT_NEAR(plain["uv"][1], 0.32, 1e-15);
  EXPECT_EQ(plain["color"][0], 0.9);
  auto flipped = runNode("planar_reflection", in, {{"flip_y", true}}, env);
  EXPECT_NEAR(flipped["uv"][1], 0.68, 1e-15);
  // Clamped before the flip: always inside [0, 1].
  auto far = runNode("planar_reflection", {{"distortion", Value::vector({0, 5})}}, {{"flip_y", true}});
  EXPECT_EQ(far["uv"][1], 0.0);
}

TEST(CubemapReflection, MirrorDirection) {
  double s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
  auto out = runNode("cubemap_reflection", {{"normal", Value::vector({0, 1, 0})}, {"view", Value::vector({s, c, 0})}});
  EXPECT_NEAR(out["direction"][0], -s, 1e-12);
  EXPECT_NEAR(out["direction"][1], c, 1e-12);
  EXPECT_NEAR(out["direction"][2], 0, 1e-12);
  auto zero = runNode("cubemap_reflection", {{"normal", Value::vector({0, 0, 0})}, {"view", Value::vector({0, 0, 0})}});
  EXPECT_TRUE(zero["direction"].allFinite());
}

// --- ssr --------------------------------------------------------------------------------

TEST(Ssr, EdgeFadeIsSeed001s) {
  // Centre: 1 - 0.01^(1/4); a corner (|d|^2 = 2): max(1 - 2.01^(1/4), 0) = 0.
  EXPECT_NEAR(nodes::ssrFadeReference(0.5, 0.5, 1, 20), 1 - std::pow(0.01, 0.25), 1e-15);
  EXPECT_EQ(nodes::ssrFadeReference(1, 1, 1, 20), 0.0);
  // Distance fade beyond fade_distance: 20 / 40.
  EXPECT_NEAR(nodes::ssrFadeReference(0.5, 0.5, 40, 20), 0.5 * (1 - std::pow(0.01, 0.25)), 1e-15);
}

TEST(Ssr, FindsTheSceneWhereTheRayMeetsItsDepth) {
  // Camera above and behind a water point at the origin; the reflected ray climbs away.
  Vec3d eye{0, 5, 10};
  EvalEnvironment env = cameraEnv(eye, {0, 0, 0});
  Vec3d vdir = normalize(eye);  // from the surface point to the camera
  Vec3d r{-vdir.x, vdir.y, -vdir.z};  // reflect(-V, up)
  double stride = 1.0 / std::max(0.6, r.y * r.y);
  // The 4th ray point (i = 3, t = 3.5 stride): put the scene exactly at its view depth.
  double t3 = 3.5 * stride;
  double p3[4] = {t3 * r.x, t3 * r.y, t3 * r.z, 1}, q3[4], c3[4];
  mulPoint(env.view, p3, q3);
  mulPoint(env.projection, q3, c3);
  env.sceneDepth = Value::scalar(depthOf(-q3[2], 0.1, 100));
  env.sceneColor = Value::vector({1, 0.5, 0.25});
  Value fallback = Value::vector({0, 0, 1});
  auto out = runNode("ssr", {{"position", Value::vector({0, 0, 0})}, {"view", Value::vector({vdir.x, vdir.y, vdir.z})},
                             {"fallback", fallback}, {"tolerance", Value::scalar(0.1)}},
                     {}, env);
  double u = c3[0] / c3[3] * 0.5 + 0.5, v = c3[1] / c3[3] * 0.5 + 0.5;
  EXPECT_NEAR(out["uv"][0], u, 1e-9);
  EXPECT_NEAR(out["uv"][1], v, 1e-9);
  double dist = std::sqrt(dot3d(eye, eye));  // the surface's view depth: the camera looks at it
  double conf = nodes::ssrFadeReference(u, v, dist, 20);
  EXPECT_GT(conf, 0.1);
  EXPECT_NEAR(out.scalar("confidence"), conf, 1e-12);
  EXPECT_NEAR(out["color"][0], conf * 1.0, 1e-12);
  EXPECT_NEAR(out["color"][2], (1 - conf) * 1.0 + conf * 0.25, 1e-12);
  // The march takes 4 steps to get there.
  auto m = nodes::ssrMarchReference(env.sceneDepth[0], Value::vector({0, 0, 0}), Value::vector({r.x, r.y, r.z}), r.y,
                                    env.view, env.projection, env.cameraNearFar, 10, 1.0, 0.1, 1.1);
  EXPECT_TRUE(m.hit);
  EXPECT_EQ(m.steps, 4);
}

TEST(Ssr, ToleranceGrowsPerStep) {
  // With the scene a little behind the ray everywhere, a growing tolerance eventually
  // accepts it; with growth 1 it never does.
  EvalEnvironment env = cameraEnv({0, 5, 10}, {0, 0, 0});
  Vec3d vdir = normalize({0, 5, 10});
  Value r = Value::vector({0, vdir.y, -vdir.z});
  auto run = [&](double growth) {
    return nodes::ssrMarchReference(depthOf(14.0, 0.1, 100), Value::vector({0, 0, 0}), r, r[1], env.view,
                                    env.projection, env.cameraNearFar, 10, 0.05, 0.2, growth);
  };
  EXPECT_FALSE(run(1.0).hit);
  EXPECT_TRUE(run(50.0).hit);
}

TEST(Ssr, RayBehindTheCameraNeverDividesByW) {
  // Camera at the origin looking along -z; the surface point lies behind it (z = +5) and
  // the reflected ray goes further behind: clip w < 0 at the first step.
  EvalEnvironment env = cameraEnv({0, 0, 0}, {0, 0, -1});
  env.sceneDepth = Value::scalar(0.5);
  Value fallback = Value::vector({0.1, 0.2, 0.3});
  auto out = runNode("ssr", {{"position", Value::vector({0, -1, 5})}, {"normal", Value::vector({0, 0, 1})},
                             {"view", Value::vector({0, 0, -1})}, {"fallback", fallback}},
                     {}, env);
  EXPECT_EQ(out.scalar("confidence"), 0.0);
  EXPECT_EQ(out["color"][2], 0.3);
  EXPECT_TRUE(out["uv"].allFinite());
  auto m = nodes::ssrMarchReference(0.5, Value::vector({0, -1, 5}), Value::vector({0, 0, 1}), 1.0, env.view,
                                    env.projection, env.cameraNearFar, 10, 1, 0.5, 1.1);
  EXPECT_FALSE(m.hit);
  EXPECT_EQ(m.steps, 1) << "the march stops at the first point behind the camera";
  // The ray crossing the camera plane mid-march also stops, finite.
  auto cross = runNode("ssr", {{"position", Value::vector({0, -1, -3})}, {"normal", Value::vector({0, 0, 1})},
                               {"view", Value::vector({0, 0, -1})}, {"step", Value::scalar(2)}},
                       {{"steps", 64}}, env);
  EXPECT_TRUE(cross["color"].allFinite());
  EXPECT_EQ(cross.scalar("confidence"), 0.0);
}

// --- underwater -------------------------------------------------------------------------

struct UnderwaterCase {
  EvalEnvironment env;
  std::vector<std::pair<std::string, Value>> inputs;
};

// The camera straight above or below the water point (0, 0, 0), looking along -y or +y;
// the scene point on the axis at linear depth `lin`.
UnderwaterCase verticalCase(double cameraY, double lin, bool lookUp) {
  UnderwaterCase c;
  c.env = cameraEnv({0, cameraY, 0}, {0, cameraY + (lookUp ? 1 : -1), 0}, {0, 0, -1});
  c.env.worldPosition = Value::vector({0, 0, 0});
  c.env.fragDepth = Value::scalar(0.5);  // the G-buffer: water covers this pixel
  c.env.sceneDepth = Value::scalar(lin >= 100 ? 1.0 : depthOf(lin, 0.1, 100));
  c.env.sceneColor = Value::vector({0.4, 0.5, 0.6});
  c.inputs = {{"screen_uv", Value::vector({0.5, 0.5})},
              {"surface", Value::vector({0.1, 0.1, 0.1})},
              {"transmittance", Value::scalar(0.9)},
              {"caustics", Value::scalar(0.5)},
              {"surface_below", Value::vector({0.05, 0.05, 0.05})},
              {"transmittance_below", Value::scalar(0.8)}};
  return c;
}

const double kSigma[3] = {0.340, 0.0565, 0.00922};
const double kWater[3] = {0.0, 0.1, 0.2};
const double kHaze[3] = {0.70, 0.80, 0.90};
const double kScene[3] = {0.4, 0.5, 0.6};

TEST(Underwater, Case1CameraAndPixelAboveWater) {
  auto c = verticalCase(10, 5, false);  // the scene point at y = 5, above the water
  auto out = runNode("underwater", c.inputs, {}, c.env);
  EXPECT_EQ(out.scalar("case"), 1.0);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(out["color"][i], kScene[i]);
}

TEST(Underwater, Case4CameraAboveUnderwaterPixelNear) {
  auto c = verticalCase(10, 13, false);  // the floor at y = -3: 3 m of water
  auto out = runNode("underwater", c.inputs, {}, c.env);
  EXPECT_EQ(out.scalar("case"), 4.0);
  double haze = 10.0 / 120.0;
  for (int i = 0; i < 3; ++i) {
    double t = std::exp(-kSigma[i] * 3.0);
    double body = t * (kScene[i] + 1.0 * 0.5 * 0.6) + (1 - t) * kWater[i] * 0.35;
    double lit = 0.9 * body + 0.1;
    EXPECT_NEAR(out["color"][i], lit * (1 - haze) + kHaze[i] * haze, 1e-9) << i;
  }
}

TEST(Underwater, Case5CameraAboveUnderwaterPixelFar) {
  auto c = verticalCase(10, 13, false);
  c.inputs.push_back({"haze_distance", Value::scalar(12)});  // the floor lies beyond it
  auto out = runNode("underwater", c.inputs, {}, c.env);
  EXPECT_EQ(out.scalar("case"), 5.0);
  double haze = 10.0 / 12.0;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(out["color"][i], (0.9 * kWater[i] * 0.35 + 0.1) * (1 - haze) + kHaze[i] * haze, 1e-12);
  // The sky behind the water (depth 1.0): no light comes through, case 5, finite.
  auto sky = verticalCase(10, 1000, false);
  auto s = runNode("underwater", sky.inputs, {}, sky.env);
  EXPECT_EQ(s.scalar("case"), 5.0);
  EXPECT_TRUE(s["color"].allFinite());
}

TEST(Underwater, Case2CameraAndPixelUnderWater) {
  auto c = verticalCase(-2, 1.5, false);  // camera 2 m deep looking down at the floor 1.5 m away
  auto out = runNode("underwater", c.inputs, {}, c.env);
  EXPECT_EQ(out.scalar("case"), 2.0);
  double k = std::min(1.0, 4.0 / 2.0);
  for (int i = 0; i < 3; ++i) {
    double t = std::exp(-kSigma[i] * 1.5);
    EXPECT_NEAR(out["color"][i], k * (t * (kScene[i] + 0.5 * 0.6) + (1 - t) * kWater[i] * 0.35), 1e-9);
  }
  // Deeper than depth_light, the light falls as depth_light / depth.
  auto deep = verticalCase(-8, 1.5, false);
  auto d = runNode("underwater", deep.inputs, {}, deep.env);
  EXPECT_NEAR(d["color"][2], 0.5 * out["color"][2], 1e-9);
}

TEST(Underwater, Case3CameraUnderWaterLookingUp) {
  auto c = verticalCase(-2, 10, true);  // through the surface at 2 m to a point 8 m above it
  auto out = runNode("underwater", c.inputs, {}, c.env);
  EXPECT_EQ(out.scalar("case"), 3.0);
  for (int i = 0; i < 3; ++i) {
    double t = std::exp(-kSigma[i] * 2.0);
    EXPECT_NEAR(out["color"][i], t * (0.8 * kScene[i] + 0.05) + (1 - t) * kWater[i] * 0.35, 1e-9);
  }
}

TEST(Underwater, CameraOptionPicksTheBranch) {
  auto c = verticalCase(-2, 1.5, false);
  EXPECT_EQ(runNode("underwater", c.inputs, {{"camera", "below"}}, c.env).scalar("case"), 2.0);
  // Forced above with the camera below: the above-water cases, still finite.
  auto a = runNode("underwater", c.inputs, {{"camera", "above"}}, c.env);
  EXPECT_GE(a.scalar("case"), 1.0);
  EXPECT_NE(a.scalar("case"), 2.0);
  EXPECT_TRUE(a["color"].allFinite());
}

// --- graphs: compile for every target; deferred interface; camera specialisation --------

std::optional<CompileResult> compileText(const std::string& json, std::string* messages) {
  Diagnostics diags;
  auto graph = parseGraph(json, "inline.json", diags);
  std::optional<CompileResult> r;
  if (graph) r = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  for (const auto& d : diags.all()) *messages += formatText(d) + "\n";
  return r;
}

std::string fileOf(const CompileResult& r, const std::string& suffix) {
  for (const auto& f : r.files)
    if (f.name.size() >= suffix.size() && f.name.compare(f.name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return f.contents;
  return "";
}

std::string underwaterGraph(const std::string& camera) {
  return R"({"version": 1, "name": "uw", "nodes": [
    {"id": "scene", "type": "scene_depth"},
    {"id": "caustics", "type": "texture_caustics", "inputs": {"position": "scene.position"}},
    {"id": "fresnel", "type": "fresnel"},
    {"id": "sky", "type": "cubemap_reflection"},
    {"id": "ssr", "type": "ssr", "inputs": {"fallback": "sky.color"}},
    {"id": "surface", "type": "mul", "inputs": {"a": "ssr.color", "b": "fresnel.reflectance"}},
    {"id": "uw", "type": "underwater", "options": {"camera": ")" +
         camera + R"("}, "inputs": {"surface": "surface.out", "transmittance": "fresnel.transmittance",
      "caustics": "caustics.caustics"}}],
    "outputs": {"fragment": {"color": "uw.color"}}})";
}

TEST(ScreenSpaceGraphs, EachNodeCompilesForEveryTarget) {
  std::string g = R"({"version": 1, "name": "ss", "nodes": [
    {"id": "d", "type": "scene_depth"},
    {"id": "c", "type": "scene_color", "inputs": {"distortion": [0.01, 0.02]}},
    {"id": "r", "type": "planar_reflection", "options": {"flip_y": true}},
    {"id": "e", "type": "cubemap_reflection"},
    {"id": "s", "type": "ssr", "options": {"steps": 20}, "inputs": {"fallback": "e.color"}},
    {"id": "a", "type": "add", "inputs": {"a": "c.color", "b": "r.color"}},
    {"id": "b", "type": "add", "inputs": {"a": "a.out", "b": "s.color"}},
    {"id": "f", "type": "mul", "inputs": {"a": "b.out", "b": "d.linear"}}],
    "outputs": {"fragment": {"color": "f.out"}}})";
  EXPECT_EQ(test::compileGraphText(g), "");
  std::string messages;
  auto r = compileText(g, &messages);
  ASSERT_TRUE(r) << messages;
  for (RenderPass p : {RenderPass::DepthPrepass, RenderPass::SceneColorCopy, RenderPass::PlanarReflection,
                       RenderPass::EnvironmentCubemap, RenderPass::WaterSurface})
    EXPECT_TRUE(r->manifest.lists(p)) << renderPassRow(p).name;
  EXPECT_FALSE(r->manifest.lists(RenderPass::DeferredWater));
}

TEST(ScreenSpaceGraphs, UnderwaterRunsDeferredWithoutVaryings) {
  std::string messages;
  auto r = compileText(underwaterGraph("auto"), &messages);
  ASSERT_TRUE(r) << messages;
  for (RenderPass p : {RenderPass::DepthPrepass, RenderPass::SceneColorCopy, RenderPass::DeferredWater,
                       RenderPass::WaterSurface})
    EXPECT_TRUE(r->manifest.lists(p)) << renderPassRow(p).name;
  for (const char* target : {".glsl330.frag", ".es300.frag", ".vk450.frag"}) {
    SCOPED_TRACE(target);
    std::string frag = fileOf(*r, target);
    ASSERT_FALSE(frag.empty());
    EXPECT_EQ(frag.find("\nin "), std::string::npos) << "a full-screen fragment shader has no varyings:\n" << frag;
    EXPECT_EQ(frag.find(") in "), std::string::npos) << frag;
    EXPECT_NE(frag.find("u_water_surface"), std::string::npos);
    EXPECT_NE(frag.find("u_water_normal_uv"), std::string::npos);
  }
  // The vertex shader writes what the G-buffer pass stores.
  std::string vert = fileOf(*r, ".glsl330.vert");
  for (const char* v : {"v_world_position =", "v_normal =", "v_uv ="}) EXPECT_NE(vert.find(v), std::string::npos) << v;
}

TEST(ScreenSpaceGraphs, CameraAboveCarriesNoUnderwaterBranch) {
  std::string messages;
  auto above = compileText(underwaterGraph("above"), &messages);
  auto below = compileText(underwaterGraph("below"), &messages);
  auto automatic = compileText(underwaterGraph("auto"), &messages);
  ASSERT_TRUE(above && below && automatic) << messages;
  for (const char* target : {".glsl330.frag", ".es300.frag", ".vk450.frag"}) {
    SCOPED_TRACE(target);
    std::string a = fileOf(*above, target), b = fileOf(*below, target), u = fileOf(*automatic, target);
    EXPECT_NE(a.find("wg_underwater_from_above"), std::string::npos);
    EXPECT_EQ(a.find("wg_underwater_from_below"), std::string::npos) << "camera above: no underwater cases";
    EXPECT_EQ(b.find("wg_underwater_from_above"), std::string::npos) << "camera below: no above-water cases";
    EXPECT_NE(b.find("wg_underwater_from_below"), std::string::npos);
    EXPECT_NE(u.find("wg_underwater_from_above"), std::string::npos);
    EXPECT_NE(u.find("wg_underwater_from_below"), std::string::npos);
    EXPECT_LT(a.size(), u.size());
  }
}

}  // namespace
}  // namespace wg
