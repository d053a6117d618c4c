#include "runtime/output_transform.h"

#include <cmath>

namespace wg::rt {
namespace {

// The constants are those of core/view_transform.cpp (the reference); matrices are written
// as rows and applied as `v * mat3(row0, row1, row2)`, which is the row-matrix product.
constexpr const char* kBody = R"glsl(
layout(location = 0) out vec4 o_color;

// NaN and negatives -> 0, +Inf and above -> the largest half float: a finite output for
// every texel a frame can hold.
vec3 wg_view_sanitise(vec3 c) {
  c = mix(c, vec3(0.0), isnan(c));
  return clamp(c, 0.0, 65504.0);
}

vec3 wg_view_aces(vec3 c) {
  const mat3 inputRows = mat3(0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777);
  const mat3 outputRows = mat3(1.60475, -0.53108, -0.07367, -0.10208, 1.10813, -0.00605, -0.00327, -0.07276, 1.07602);
  vec3 v = c * inputRows;
  v = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
  return clamp(v * outputRows, 0.0, 1.0);
}

vec3 wg_view_agx(vec3 c) {
  const mat3 insetRows = mat3(0.842479062253094, 0.0784335999999992, 0.0792237451477643,
                              0.0423282422610123, 0.878468636469772, 0.0791661274605434,
                              0.0423756549057051, 0.0784336, 0.879142973793104);
  const mat3 outsetRows = mat3(1.19687900512017, -0.0980208811401368, -0.0990297440797205,
                               -0.0528968517574562, 1.15190312990417, -0.0989611768448433,
                               -0.0529716355144438, -0.0980434501171241, 1.15107367264116);
  const float minEv = -12.47393, maxEv = 4.026069;
  vec3 x = clamp(log2(max(c * insetRows, vec3(1e-10))), minEv, maxEv);
  x = (x - minEv) / (maxEv - minEv);
  vec3 x2 = x * x, x4 = x2 * x2;
  x = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
  return pow(clamp(x * outsetRows, 0.0, 1.0), vec3(2.2));
}

vec3 wg_view_neutral(vec3 c) {
  const float start = 0.8 - 0.04, desaturation = 0.15;
  float x = min(c.r, min(c.g, c.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  c -= offset;
  float peak = max(c.r, max(c.g, c.b));
  if (peak < start) return clamp(c, 0.0, 1.0);
  const float d = 1.0 - start;
  float newPeak = 1.0 - d * d / (peak + d - start);
  float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
  return clamp(mix(c * (newPeak / peak), vec3(newPeak), g), 0.0, 1.0);
}

// IEC 61966-2-1 (the piecewise curve); l is in [0, 1].
vec3 wg_view_srgb_encode(vec3 l) {
  vec3 curve = 1.055 * pow(l, vec3(1.0 / 2.4)) - 0.055;
  return mix(curve, 12.92 * l, lessThanEqual(l, vec3(0.0031308)));
}

void main() {
  vec3 c = wg_view_sanitise(texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb) * u_exposure_scale;
  // Branches on a uniform, not selects: a driver that flattens ?: would run all four.
  vec3 display;
  if (u_tone_mapper == 1) {
    display = wg_view_aces(c);
  } else if (u_tone_mapper == 2) {
    display = wg_view_agx(c);
  } else if (u_tone_mapper == 3) {
    display = wg_view_neutral(c);
  } else {
    display = clamp(c, 0.0, 1.0);
  }
  o_color = vec4(wg_view_srgb_encode(display), 1.0);
}
)glsl";

}  // namespace

std::string outputTransformFragment(SceneShaderApi api) { return glslVersionLine(api) + outputTransformFragmentBody(api); }

std::string outputTransformFragmentBody(SceneShaderApi api) {
  std::string inputs;
  switch (api) {
    case SceneShaderApi::Gl330:
      inputs = "uniform sampler2D u_frame;\nuniform float u_exposure_scale;\nuniform int u_tone_mapper;\n";
      break;
    case SceneShaderApi::Es300:
      // A sampler's precision is that of what it returns: lowp by default in ES.
      inputs = "uniform highp sampler2D u_frame;\nuniform float u_exposure_scale;\nuniform int u_tone_mapper;\n";
      break;
    case SceneShaderApi::Vulkan450:
      inputs =
          "layout(set = 0, binding = 0) uniform sampler2D u_frame;\n"
          "layout(push_constant) uniform ViewConstants {\n  float u_exposure_scale;\n  int u_tone_mapper;\n};\n";
      break;
    case SceneShaderApi::WebGpu450:
      inputs = webgpuDeclarations(outputTransformInterface());
      break;
  }
  return sceneShaderPreamble(api) + inputs + kBody;
}

ShaderInterface outputTransformInterface() {
  return {"ViewConstants", {{"float", "u_exposure_scale"}, {"int", "u_tone_mapper"}}, {{"sampler2D", "u_frame"}}, {}, {}};
}

OutputTransformUniforms outputTransformUniforms(const ViewTransform& view) {
  return {static_cast<float>(std::exp2(view.exposureEv)), static_cast<int>(view.toneMapper)};
}

}  // namespace wg::rt
