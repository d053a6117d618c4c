// The output transform pass on the GPU (desktop GL 4.5 and ES 3.2 on llvmpipe) against its
// double reference (core/view_transform.h): a float texture of chosen linear values is
// drawn through the runtime's shader into an RGBA8 target, every tone mapper at three
// exposures, and each byte must be the reference's rounded value within one level (the
// GPU's float32 arithmetic and its rounding to 8 bits). The values reach every branch:
// below and above the sRGB knee, inside and above AgX's window, both sides of PBR
// Neutral's knee, and NaN, +Inf, -Inf and negatives, which must come out finite. (llvmpipe's
// clamp already returns 0 for a NaN, so the shader's explicit isnan guard, kept because
// GLSL leaves min and max of a NaN undefined, is not observable on this driver.)
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/color_space.h"
#include "core/view_transform.h"
#include "runtime/egl_context.h"
#include "runtime/gl_resources.h"
#include "runtime/output_transform.h"
#include "runtime/scene.h"

namespace wg::rt {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Linear values, one texel each; r takes the value, g and b a fixed colour so the matrices
// of ACES and AgX mix channels.
const std::vector<float> kValues = {0.0f,  0.0005f, 0.002f, 0.0031308f, 0.0031309f, 0.01f, 0.18f, 0.5f,
                                    0.76f, 1.0f,    4.0f,   16.0f,      100.0f,     1e4f,  65504.0f,
                                    kInf,  kNaN,    -kInf,  -1.0f,      1e-30f};

std::vector<uint8_t> runPass(const ViewTransform& view, GlApi api) {
  const int n = static_cast<int>(kValues.size());
  std::vector<float> texels;
  for (float v : kValues) texels.insert(texels.end(), {v, 0.3f, 0.05f, 1.0f});
  Texture frame = makeTexture();
  glBindTexture(GL_TEXTURE_2D, frame.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, n, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, 1, GL_RGBA, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  Texture display = makeTexture();
  glBindTexture(GL_TEXTURE_2D, display.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, n, 1);
  Framebuffer fbo = makeFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display.id(), 0);
  const SceneShaderApi shaderApi = api == GlApi::Es32 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
  Program p = linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", sceneShaderSources(shaderApi).fullscreenVertex},
                           {GL_FRAGMENT_SHADER, "output_transform.frag", outputTransformFragment(shaderApi)}},
                          "the output transform");
  glUseProgram(p.id());
  const OutputTransformUniforms u = outputTransformUniforms(view);
  glUniform1f(glGetUniformLocation(p.id(), "u_exposure_scale"), u.exposureScale);
  glUniform1i(glGetUniformLocation(p.id(), "u_tone_mapper"), u.toneMapper);
  glUniform1i(glGetUniformLocation(p.id(), "u_frame"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, frame.id());
  VertexArray vao = makeVertexArray();
  glBindVertexArray(vao.id());
  glViewport(0, 0, n, 1);
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<uint8_t> out(static_cast<size_t>(n) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return out;
}

class OutputTransformGpu : public ::testing::TestWithParam<GlApi> {};

TEST_P(OutputTransformGpu, EveryToneMapperMatchesTheReferenceWithinOneLevel) {
  auto ctx = EglContext::create(GetParam());
  for (ToneMapper t : {ToneMapper::None, ToneMapper::Aces, ToneMapper::Agx, ToneMapper::Neutral})
    for (double ev : {-4.0, 0.0, 2.5}) {
      const ViewTransform view{t, ev};
      SCOPED_TRACE(std::string(toneMapperName(t)) + " at " + std::to_string(ev) + " EV");
      std::vector<uint8_t> got = runPass(view, GetParam());
      for (size_t i = 0; i < kValues.size(); ++i) {
        const Rgb want = outputTransform(view, {kValues[i], 0.3, 0.05});
        for (size_t c = 0; c < 3; ++c)
          EXPECT_NEAR(got[i * 4 + c], 255.0 * want[c], 1.0) << "value " << kValues[i] << " channel " << c;
        EXPECT_EQ(got[i * 4 + 3], 255);
      }
    }
}

TEST_P(OutputTransformGpu, LinearSegmentBelowTheKneeIsNotAPower) {
  // 0.002 linear is 12.92 x 0.002 = 0.0258 (6.6 of 255) by the piecewise curve; a 2.2 power
  // would give 0.059 (15.1): the pass must take the linear segment.
  auto ctx = EglContext::create(GetParam());
  std::vector<uint8_t> got = runPass({}, GetParam());
  EXPECT_EQ(got[2 * 4], std::lround(255 * linearToSrgb(0.002)));
  EXPECT_EQ(std::lround(255 * linearToSrgb(0.002)), 7);
}

INSTANTIATE_TEST_SUITE_P(Apis, OutputTransformGpu, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return info.param == GlApi::Es32 ? std::string("es32") : std::string("gl45"); });

}  // namespace
}  // namespace wg::rt
