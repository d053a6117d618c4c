// Oblique near-plane clipping for the planar reflection (the stylized water shader): the maths, and the
// reflection it renders against the clip-plane reflection (the classic WebGL water renderer).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "runtime/oblique_projection.h"
#include "runtime/preview.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

float ndcZ(const glm::mat4& m, glm::vec3 p) {
  glm::vec4 c = m * glm::vec4(p, 1.0f);
  return c.z / c.w;
}

TEST(ObliqueProjection, NearPlaneLiesOnTheWater) {
  // A camera mirrored below the water (y = -4) looking up and across; the water plane y = 0
  // keeps what is above it.
  glm::mat4 view = glm::lookAt(glm::vec3(0, -4, 10), glm::vec3(0, 2, -10), glm::vec3(0, 1, 0));
  glm::mat4 proj = glm::perspective(glm::radians(55.0f), 16.0f / 9.0f, 0.1f, 200.0f);
  glm::vec4 eyePlane = planeToEye(view, glm::vec4(0, 1, 0, 0));
  ASSERT_LT(eyePlane.w, 0.0f) << "the camera is on the clipped side";
  glm::mat4 oblique = obliqueProjection(proj, eyePlane) * view;
  // Points on the water map to the near plane (ndc z = -1), points above it inside the
  // depth range, points below it in front of the near plane (clipped).
  for (glm::vec3 p : {glm::vec3(0, 0, -5), glm::vec3(3, 0, -20), glm::vec3(-4, 0, -40)})
    EXPECT_NEAR(ndcZ(oblique, p), -1.0f, 1e-4f);
  for (glm::vec3 p : {glm::vec3(0, 0.5f, -5), glm::vec3(2, 3, -30)}) {
    float z = ndcZ(oblique, p);
    EXPECT_GT(z, -1.0f);
    EXPECT_LT(z, 1.0f);
  }
  EXPECT_LT(ndcZ(oblique, glm::vec3(0, -0.5f, -8)), -1.0f);
  // x, y and w of clip space are those of the plain projection.
  glm::vec4 a = obliqueProjection(proj, eyePlane) * glm::vec4(1, 2, -7, 1), b = proj * glm::vec4(1, 2, -7, 1);
  EXPECT_FLOAT_EQ(a.x, b.x);
  EXPECT_FLOAT_EQ(a.y, b.y);
  EXPECT_FLOAT_EQ(a.w, b.w);
}

TEST(ObliqueProjection, ReflectionMatchesTheClipPlaneReflection) {
  std::string graph = R"({"version": 1, "name": "mirror",
    "nodes": [{"id": "r", "type": "planar_reflection"}],
    "outputs": {"fragment": {"color": "r.color"}}})";
  Diagnostics d;
  auto g = parseGraph(graph, "mirror.json", d);
  ASSERT_TRUE(g);
  CompileOptions o;
  o.targets = {Target::Glsl330, Target::Es300};
  auto r = compileGraph(*g, defaultRegistry(), o, d);
  ASSERT_TRUE(r);
  for (Target t : {Target::Glsl330, Target::Es300}) {
    SCOPED_TRACE(targetName(t));
    for (const char* camera : {"above", "grazing"}) {
      SCOPED_TRACE(camera);
      RenderSettings s = test::smallSettings();
      s.camera = camera;
      Image clipped = renderPreview(*r, t, s).image;
      s.obliqueReflection = true;
      Image oblique = renderPreview(*r, t, s).image;
      // Same scene, same pixels; only depth precision near the water line differs.
      EXPECT_GE(psnrRgb8(clipped, oblique), 35.0);
    }
  }
}

}  // namespace
}  // namespace wg::rt
