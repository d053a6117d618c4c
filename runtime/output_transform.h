#pragma once
// The output transform pass's shader (core/view_transform.h says what it computes; the
// double functions there are its reference): a full-screen triangle (the scene shaders'
// fullscreen vertex shader) whose fragment shader reads the frame's linear radiance texel
// for texel and writes sRGB-encoded display values. One text for GL 3.3, ES 3.00 and
// Vulkan 450, exported to the three.js client by `watergraph scene`.
//
// Its inputs: the frame (sampler2D u_frame, read with texelFetch at the fragment's pixel),
// u_exposure_scale = 2^EV (float, computed in double on the CPU) and u_tone_mapper (int,
// the ToneMapper enumerator: 0 none, 1 aces, 2 agx, 3 neutral). On Vulkan the frame is
// set 0 binding 0 and the two numbers a push-constant block (float at 0, int at 4); on
// WebGPU, the form of runtime/webgpu_shader_form.h.
#include <string>

#include "core/view_transform.h"
#include "runtime/scene.h"

namespace wg::rt {

std::string outputTransformFragment(SceneShaderApi api);
// The same after its version line (runtime/scene.h, sceneShaderBodies).
std::string outputTransformFragmentBody(SceneShaderApi api);
// Its interface, from which the WebGPU form's declarations come (webgpu_shader_form.h).
ShaderInterface outputTransformInterface();

// The values of its two uniforms for a view: 2^EV and the tone mapper's number.
struct OutputTransformUniforms {
  float exposureScale = 1.0f;
  int toneMapper = 0;
};
OutputTransformUniforms outputTransformUniforms(const ViewTransform& view);

}  // namespace wg::rt
