#include "runtime/oblique_projection.h"

#include <cmath>

namespace wg::rt {

glm::mat4 obliqueProjection(const glm::mat4& projection, const glm::vec4& eyePlane) {
  auto sign = [](float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); };
  // The corner of the view frustum opposite the plane, in eye space; scaling the plane so
  // that it maps there to clip z = w keeps the far plane as close as possible to the
  // original one.
  glm::vec4 q = glm::inverse(projection) * glm::vec4(sign(eyePlane.x), sign(eyePlane.y), 1.0f, 1.0f);
  glm::vec4 c = eyePlane * (2.0f / glm::dot(eyePlane, q));
  glm::mat4 p = projection;
  // Third row (clip z) = c - fourth row (clip w); glm is column-major: p[column][row].
  for (int column = 0; column < 4; ++column) p[column][2] = c[column] - p[column][3];
  return p;
}

glm::vec4 planeToEye(const glm::mat4& view, const glm::vec4& worldPlane) {
  // Planes transform by the inverse transpose of the point transform.
  return glm::transpose(glm::inverse(view)) * worldPlane;
}

}  // namespace wg::rt
