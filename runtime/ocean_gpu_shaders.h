#pragma once
// The spectral ocean's GPU passes as GLSL, one text per pass for both runtimes: the GL
// runtime (runtime/ocean_gpu_cascade.h, ocean_gpu_foam.h) links them with loose uniforms,
// the Vulkan runtime (runtime/vk_ocean_cascade.h, vk_ocean_foam.h) compiles them to SPIR-V
// with the same bodies. Each body uses ivec2(gl_FragCoord.xy) as its texel: in either API
// that is the texel the pass writes and the one texelFetch reads at the same coordinates
// (GL's window row 0 and Vulkan's framebuffer row 0 are both the image's first row).
//
// A pass's uniforms are its samplers and its scalar constants, declared per API: loose
// uniforms for GL; for Vulkan, sampler i at set 0, binding i, and the constants one
// push-constant block, constant i at byte offset 4 i (every constant is a 32-bit scalar); for
// WebGPU, the declarations of the pass's ShaderInterface (runtime/webgpu_shader_form.h).
#include <string>
#include <vector>

#include "runtime/scene.h"
#include "runtime/webgpu_shader_form.h"

namespace wg::rt::oceangpu {

enum class OceanPass { Evolve, Stockham, Pack, FoamStep, FoamBlend, Downsample };

// The defines that choose a cascade pass's variant (the foam passes take none).
struct OceanPassVariant {
  bool slopes = false;        // WG_OCEAN_SLOPES: the second texture (slopes, the Jacobian's fields) too
  bool jacobianOnly = false;  // WG_OCEAN_JACOBIAN_ONLY: the second texture's fields alone, in the first output
  bool moments = false;       // WG_OCEAN_MOMENTS (Pack with slopes): a third output, the slopes' moments map
};

// The sampler names of `pass` in binding order, for this variant (a sampler the variant
// does not read is not declared).
std::vector<std::string> oceanPassSamplers(OceanPass pass, const OceanPassVariant& variant);
// The scalar constant names of `pass` in push-constant order.
std::vector<std::string> oceanPassConstants(OceanPass pass);
// Its constants and textures (types "sampler2D", "usampler2D"), from which every API's
// declarations are written.
ShaderInterface oceanPassInterface(OceanPass pass, const OceanPassVariant& variant);
// The whole fragment shader: the API's version line and preamble (runtime/scene.h), the variant's defines,
// the declarations and the body.
std::string oceanPassFragment(OceanPass pass, SceneShaderApi api, const OceanPassVariant& variant = {});
// The same after its version line (runtime/scene.h, sceneShaderBodies).
std::string oceanPassFragmentBody(OceanPass pass, SceneShaderApi api, const OceanPassVariant& variant = {});

// The eleven programs the runtimes link, by name: the scene description (`watergraph scene`)
// carries their es300 forms under these names for the web clients, which run the same
// passes in WebGL 2 and (translated by naga) in WebGPU.
enum class OceanPassShader {
  Evolve,              // h~(k, t) from h0 into both spectra textures (A and B)
  EvolveDisplacement,  // into texture A alone (nothing reads the slope map)
  EvolveJacobian,      // texture B's fields alone, into the first output (the foam's J)
  Stockham,            // one radix-2 Stockham stage of both textures
  StockhamSingle,      // of one texture
  Pack,                // both transformed textures into the displacement and slope maps
  PackDisplacement,    // texture A into the displacement map alone
  FoamStep,            // one foam step from the Jacobian's fields
  FoamBlend,           // the foam at the frame's time between two steps
  PackFiltered,        // Pack, and the moments map (the filtered reader's second moments) at level 0
  Downsample,          // level l of the slope and moments maps, the 2x2 box mean of level l - 1
};
inline constexpr int kOceanPassShaderCount = 11;

// "ocean_evolve", "ocean_evolve_displacement", ...
const char* oceanPassShaderName(OceanPassShader shader);
// The named program's fragment shader for `api`, and its interface.
std::string oceanPassFragment(SceneShaderApi api, OceanPassShader shader);
std::string oceanPassFragmentBody(SceneShaderApi api, OceanPassShader shader);
ShaderInterface oceanPassInterface(OceanPassShader shader);

}  // namespace wg::rt::oceangpu
