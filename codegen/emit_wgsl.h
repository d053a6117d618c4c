#pragma once
// ShaderPlan -> one WGSL module (GRAPH.wgsl) with a vertex entry point `vs_main` and a
// fragment entry point `fs_main`, for WebGPU. The same plan as the GLSL targets: each
// planned statement of main() (PlannedStatement: a declaration with its Type, or an
// assignment) is printed here, its expression and the library items the nodes wrote in
// WGSL's terms by codegen/wgsl_translate.h, and wrapped in WGSL's interface:
// - group 0, binding 0: every non-opaque uniform in one uniform buffer (struct WgUniforms),
//   laid out by WGSL's rules for the uniform address space (offsets in the manifest);
// - each texture as a texture binding and a sampler binding after it (1, 2; 3, 4; ...);
// - vertex attributes and varyings at @location numbers in the manifest's order.
// Clip space: the vertex stage computes GL's clip position and the module converts it to
// WebGPU's (y negated, z from [-w, w] to [0, w]), so a render target holds the same rows as
// the GL runtime's (row 0 at the bottom), @builtin(position) in the fragment stage equals
// gl_FragCoord, and a triangle's winding is mirrored: the pipeline's frontFace is "cw".
// WGSL has no tessellation stages: the plan must be made without tessellation (the mesh is
// drawn as it is, as es300 does).
// A probe plan (planProbe: a fragment stage alone) gets a vs_main drawing one triangle over
// the viewport, which `probe --target wgsl` restricts to a pixel per case.
#include <optional>
#include <string>
#include <vector>

#include "codegen/emit_glsl.h"
#include "codegen/shader_plan.h"

namespace wg {

struct WgslUniformMember {
  std::string name;
  Type type = Type::Float;
  size_t offset = 0, size = 0;
};

struct WgslBinding {
  std::string name;     // the WGSL variable
  std::string kind;     // "uniform_buffer", "texture_2d", "texture_cube", "sampler"
  std::string of;       // a texture or sampler: the GLSL sampler it stands for (the manifest's "textures" name)
  int group = 0, binding = 0;
};

struct WgslModule {
  std::string text;
  std::vector<int> lineOp;  // per line - 1: the op that wrote it, or -1
  std::vector<WgslUniformMember> uniforms;  // the uniform buffer's members, in order
  size_t uniformBufferSize = 0;             // bytes (0: no buffer)
  std::vector<WgslBinding> bindings;        // group 0, by binding number
};

// The plan's stages as WGSL. Throws WgslRefused when the plan holds what WGSL cannot carry
// (tessellation; a GLSL construct outside the translated subset, which is a bug in a node).
struct WgslRefused {
  std::string message;
  int op = -1;  // the op whose GLSL it is, when known
};
WgslModule emitWgsl(const ShaderPlan& plan);

// `probe --target wgsl`: the probe plan of `program` (planProbe, as the GLSL probe's) as one
// WGSL module, held as the one shader of an EmitResult (stage Fragment, both entry points in
// its text) with the plan's interface, so the probe's mutation and runner take it as they
// take a GLSL probe shader. The uniform buffer is laid out by wgslUniformLayout of
// `uniforms`, texture k is at wgslTextureBinding(k). Throws WgslRefused.
EmitResult emitWgslProbe(const Program& program, const std::string& sourceName);

// The bind group layout, shared by the emitter and the manifest's "webgpu" section.
inline constexpr const char* kWgslTargetName = "wgsl";      // the manifest's target name
inline constexpr const char* kWgslUniformVariable = "wg_u";  // the uniform buffer's variable
inline constexpr const char* kWgslSamplerSuffix = "_sampler";
inline constexpr int kWgslUniformBinding = 0;
// Texture k of the plan (node textures by first use, then scene textures) at binding 1 + 2k,
// its sampler at 2 + 2k; group 0.
inline int wgslTextureBinding(size_t k) { return 1 + 2 * static_cast<int>(k); }
// The buffer's size for members ending at `end` bytes: rounded up to 16.
inline size_t wgslUniformBufferSize(size_t end) { return (end + 15) / 16 * 16; }

// The uniform buffer's members for a plan's uniforms (samplers are bindings of their own),
// in order: what the module declares and what a host writes.
std::vector<WgslUniformMember> wgslUniformLayout(const std::vector<UniformInfo>& uniforms);

// WGSL's uniform address space layout of one member after `offsetSoFar` bytes (WGSL section
// 14.4: f32/i32/u32 align 4, vec2 8, vec3 and vec4 16, matCx3 and matCx4 columns 16).
WgslUniformMember wgslUniformMember(size_t offsetSoFar, Type type);

}  // namespace wg
