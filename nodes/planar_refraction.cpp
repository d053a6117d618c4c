// planar_refraction: the classic WebGL water renderer's refraction pass — the opaque scene below the water,
// rendered through the real camera with a clip plane at the surface (so nothing above the
// water, such as pillar tops, bleeds into what is seen through it) — looked up at this
// pixel with a distortion offset. scene_color is the cheaper GrabPass alternative (a copy
// of the frame, which also holds what stands above the water).
#include "nodes/node_library.h"
#include "nodes/screen_lookup.h"

namespace wg::nodes {

NodeSpec planarRefractionNode() {
  NodeSpec s;
  s.type = "planar_refraction";
  s.family = "screen space";
  s.summary = "The refraction pass (the scene below the water, clipped at the surface) looked up at this pixel, "
              "with a distortion offset.";
  s.formula = "uv' = clamp(screen_uv + distortion, 0, 1); color = texture(u_refraction, uv').rgb. The runtime draws "
              "the opaque scene through the camera with gl_ClipDistance = -(y - water level), the classic WebGL water renderer's clip plane "
              "(0, -1, 0, 0).";
  s.source = "classic WebGL water renderer (refraction pass with clip plane (0, -1, 0, 0) into refractionTexture; distortion (dudv * 2 - 1) * "
             "0.03); advanced shaders tutorial (refraction FBO in the multi-pass loop)";
  s.cost = "one texture fetch + 4 ALU; runs the refraction pass: a second draw of the opaque scene into an RGBA16F + "
           "depth target (12 bytes/pixel)";
  makeScreenLookup(s, SceneResource::Refraction,
                   "offset in screen units (the classic WebGL water renderer: (dudv * 2 - 1) * 0.03)", "the scene below the surface");
  s.hardCases = {
      {"distortion far off screen", {{"distortion", Value::vector({3, -8})}}, {}, "uv clamped to (1, 0)", 0, 1, "uv"},
      {"distortion 1e30", {{"distortion", Value::vector({1e30, -1e30})}}, {}, "uv clamped to (1, 0)", 0, 1, "uv"},
  };
  return s;
}

}  // namespace wg::nodes
