// The generated shader relies on parameter ranges (value facts, docs/architecture.md):
// the renderer clamps what it uploads, so values outside the
// range, NaN included, still render a finite image. Without the clamps classic_webgl's
// native pow (fresnel_strength, shine_damper <= 0) and its unguarded remap (edge_softness
// 0: 0 / 0) would give NaN and inf.
#include <limits>

#include <gtest/gtest.h>

#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime_test_support.h"

namespace wg::rt {
namespace {

TEST(ParameterRange, OutOfRangeValuesAreClampedOnUpload) {
  CompileResult r = test::compileExample("classic_webgl");
  auto context = EglContext::create(apiFor(Target::Glsl330));
  RenderSettings s = test::smallSettings();
  s.floatColor = true;
  Renderer renderer(r.manifest, waterShaderSources(r, Target::Glsl330), s, context->isEs(), textureOrigins(r));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(renderer.setParameter("fresnel_strength", {-4.0f}));
  EXPECT_TRUE(renderer.setParameter("shine_damper", {nan}));
  EXPECT_TRUE(renderer.setParameter("edge_softness", {0.0f}));
  EXPECT_TRUE(renderer.setParameter("tint_depth", {-1.0f}));
  renderer.renderFrame();
  Image img = renderer.readRgba32f();
  ASSERT_FALSE(img.rgba32f.empty());
  EXPECT_EQ(countNonFinite(img), 0u);
}

}  // namespace
}  // namespace wg::rt
