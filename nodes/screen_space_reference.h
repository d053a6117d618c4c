#pragma once
// Double-precision references of the screen-space and scene nodes (scene_depth,
// scene_color, planar_reflection, ssr, underwater). Each mirrors its GLSL function in
// nodes/glsl/ line for line (same clamps, same guards). Texture look-ups of scene
// resources go through EvalEnvironment::sceneAt: the read-back image where `check` has
// one, else the one value the environment gives for this pixel.
#include <functional>

#include "core/value.h"

namespace wg::nodes {

// wg_scene_depth_position: world point at screen uv with linear view depth `lin`
// (column-major view and projection matrices, as GLSL).
Value sceneDepthPositionReference(const Value& uv, double lin, const Value& camera, const Value& view,
                                  const Value& proj);

// wg_scene_color_uv: clamp(uv + offset, 0, 1).
Value sceneColorUvReference(const Value& uv, const Value& offset);

struct SsrMarch {
  double u = 0.5, v = 0.5;
  bool hit = false;
  int steps = 0;  // steps taken before the hit or the end (for tests)
};
// A scene texture look-up at screen position (u, v).
using SceneDepthAt = std::function<double(double u, double v)>;
using SceneColorAt = std::function<Value(double u, double v)>;

// wg_ssr_march against the scene depth `depthAt` gives at each step's screen position.
SsrMarch ssrMarchReference(const SceneDepthAt& depthAt, const Value& origin, const Value& dir, double cosRn,
                           const Value& view, const Value& proj, const Value& nearFar, int steps, double stepLength,
                           double tolerance, double growth);
// Against a scene depth texture that holds `sceneDepth` everywhere.
SsrMarch ssrMarchReference(double sceneDepth, const Value& origin, const Value& dir, double cosRn, const Value& view,
                           const Value& proj, const Value& nearFar, int steps, double stepLength, double tolerance,
                           double growth);
// wg_ssr_fade.
double ssrFadeReference(double u, double v, double dist, double fadeDistance);

struct UnderwaterInputs {
  Value uv, water /* vec4 */, scene, camera, normal;
  double sky = 0;
  Value surface, waterColor, sigma, causticsColor, hazeColor;
  double transmittance = 1, diffuse = 0.35, strength = 0.03, caustics = 0, hazeDistance = 120, level = 0,
         depthLight = 4;
  SceneColorAt sceneColorAt;  // a look-up of u_scene_color at (u, v)
};
// wg_underwater_from_above / _from_below: colour (vec3) and the case taken (1..5).
struct UnderwaterResult {
  Value color;
  int which = 0;
};
UnderwaterResult underwaterFromAboveReference(const UnderwaterInputs& in);
// `surface` and `transmittance` of the inputs act as surface_below / transmittance_below.
UnderwaterResult underwaterFromBelowReference(const UnderwaterInputs& in);

}  // namespace wg::nodes
