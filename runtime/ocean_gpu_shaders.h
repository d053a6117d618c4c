#pragma once
// The spectral ocean simulation's fragment shaders (runtime/ocean_gpu_cascade.h,
// runtime/ocean_gpu_foam.h): one text each, in variants by #define, drawn with the scene's
// full-screen vertex shader into N x N float targets. The runtime links them, and the scene
// description (`watergraph scene`) carries the es300 forms under these names for the web
// clients, which run the same passes in WebGL 2.
#include <string>

#include "runtime/scene.h"

namespace wg::rt {

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
};
inline constexpr int kOceanPassShaderCount = 9;

// "ocean_evolve", "ocean_evolve_displacement", ...: the scene description's name and the
// program's in error messages.
const char* oceanPassShaderName(OceanPassShader shader);
// The fragment shader's whole text for `api` (Gl330 or Es300): the runtime's header, the
// variant's #defines, the body.
std::string oceanPassFragment(SceneShaderApi api, OceanPassShader shader);

}  // namespace wg::rt
