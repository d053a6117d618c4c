#pragma once
// The built-in scene's buoys, floating on whatever water a graph makes: each at a fixed rest
// point (x0, z0) of the water, moved every frame where the graph's vertex stage moves that
// water point (heave and the orbit's sway) and tilted to the surface normal there (pitch
// and roll). The surface comes from the same double evaluation of the vertex stage the
// surface queries generate (codegen/water_surface_eval.h, docs/queries.md); the scene draws
// the buoys with its opaque shader (SceneOptions::buoys).
#include <vector>

#include <glm/glm.hpp>

#include "core/program.h"
#include "runtime/scene.h"

namespace wg::rt {

// The rest points, in the open water of the built-in scene (clear of the pillars, rocks and
// shore), metres.
const std::vector<glm::dvec2>& buoyRestPoints();

// The buoys at time t on the water of `program` (after the compiler's passes) with
// `parameters` by index, each clamped into its range as the renderer clamps the uniform
// (NaN to the lower end). The up axis is the normal of the displaced surface, from central
// differences 5 cm apart (the surface queries' normal, docs/queries.md, within 1e-3 on
// waves 4 m long).
std::vector<FloatingPose> floatingBuoys(const wg::Program& program, const std::vector<Value>& parameters, double time);

// The buoys' triangles in world space (one pose at the origin, up +y: the buoy in its own
// space, as the scene description gives it to other renderers), in the opaque scene's vertex layout (position,
// normal, material 3 for the body and 4 for the top; runtime/scene.h).
Mesh buoyMesh(const std::vector<FloatingPose>& poses);

}  // namespace wg::rt
