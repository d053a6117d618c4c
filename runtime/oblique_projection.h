#pragma once
// Oblique near-plane clipping (E. Lengyel, "Oblique View Frustum Depth Projection and
// Clipping", Journal of Game Development 1(2), 2005), the alternative to a user clip plane
// that the stylized water shader uses for planar reflection: the projection's near plane is replaced by the
// water plane, so geometry on the far side of the water is clipped by the rasteriser
// itself, with no gl_ClipDistance and no discard.
#include <glm/glm.hpp>

namespace wg::rt {

// `projection` with its near plane moved onto `eyePlane` (a, b, c, d in eye space: points p
// with dot(plane, (p, 1)) >= 0 are kept). The camera must lie on the negative side
// (eyePlane.w < 0); x, y and w of clip space are unchanged, only depth is skewed.
glm::mat4 obliqueProjection(const glm::mat4& projection, const glm::vec4& eyePlane);

// A world-space plane (kept side positive) in the eye space of `view` (world -> eye).
glm::vec4 planeToEye(const glm::mat4& view, const glm::vec4& worldPlane);

}  // namespace wg::rt
