#pragma once
// The built-in scene as data, for renderers other than this runtime (clients/three builds
// it in three.js from this): the opaque scene's mesh, the camera presets, the sun, the
// environment cube's views, the water grid and the ES 3.00 shaders of the runtime's own
// passes (and under "webgpu" their WebGPU forms with declaration tables), so another
// renderer draws the same scene from one source of truth. Written by `watergraph scene`.
#include <string>

#include "runtime/scene.h"

namespace wg::rt {

inline constexpr const char* kSceneDescriptionFormat = "watergraph-scene-2";

// JSON text on one line (keys in byte order, floats as their exact doubles).
std::string sceneDescriptionJson(const SceneOptions& options);

}  // namespace wg::rt
