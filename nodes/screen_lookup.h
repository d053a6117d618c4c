#pragma once
// The shape shared by nodes that read a screen-aligned scene texture at this pixel, moved
// by a distortion offset: scene_color (the GrabPass copy) and planar_refraction (the
// refraction pass). Ports screen_uv + distortion in, color + the clamped uv out; the
// reference returns the EvalEnvironment's value for that texture.
#include <string>

#include "core/node_spec.h"

namespace wg::nodes {

// Fills inputs, outputs, stages, resources, emit, eval and tolerance of `s` for the scene
// texture `resource` (the reference reads it through EvalEnvironment::sceneAt).
void makeScreenLookup(NodeSpec& s, SceneResource resource, const std::string& distortionDoc,
                      const std::string& colorDoc);

}  // namespace wg::nodes
