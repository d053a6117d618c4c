#pragma once
// The runtime's own shaders in the form a WebGPU host takes them: GLSL 4.50 that naga's GLSL
// front end reads as it is, with a declaration table saying where everything is, so a host
// lays out its bind group and uniform buffer from data and never reads the shader text.
//
// Why GLSL 4.50 and not WGSL: the runtime's passes are written once in GLSL for GL, ES and
// Vulkan; naga (which the WebGPU client pins) translates this form to WGSL, and what naga
// needs differs from Vulkan's form only in its declarations: one std140 uniform block at
// group 0 binding 0 instead of push constants, and each texture a separate texture2D read
// through one nearest sampler (naga has no combined image samplers). Those declarations are
// written here from each shader's ShaderInterface, the same data the GL and Vulkan
// declarations come from, so a new pass shader gets its WebGPU form and table with nothing
// more than its interface.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg::rt {

// A constant (float, int, uint, vec2-4, mat4) or a texture ("sampler2D", "usampler2D").
struct ShaderMember {
  std::string type, name;
};

// A varying between the runtime's stages. `define`, when not empty, names the macro that
// sets its location: the host chooses it (the G-buffer reads the graph's varyings at the
// locations the graph's vertex stage writes them) and passes it to naga as a define; the
// text defaults it to `location`.
struct ShaderVarying {
  int location = 0;
  bool flat = false;
  std::string type, name;
  std::string define;
};

// What one shader declares besides its body: its constants (one block, in order), the
// textures it reads with texelFetch (binding order), and its varyings (a vertex stage's
// inputs are its attributes; a fragment stage's colour outputs stay in its body: output i
// is colour attachment i).
struct ShaderInterface {
  std::string block;  // the constants' block name (Vulkan's push-constant block)
  std::vector<ShaderMember> constants;
  std::vector<ShaderMember> textures;
  std::vector<ShaderVarying> inputs, outputs;
};

// The binding layout of the WebGPU form: the block at binding 0 (when there are constants),
// texture i at binding 1 + i, the one sampler after the textures.
inline constexpr int kWebgpuBlockBinding = 0;
inline constexpr const char* kWebgpuSamplerName = "wg_nearest";

// The GLSL 4.50 declarations of `i` for naga: the std140 block, the textures (each name a
// macro for `sampler2D(texture, wg_nearest)`, so a body's texelFetch(u_x, ...) reads it), the
// sampler and the varyings with their locations.
std::string webgpuDeclarations(const ShaderInterface& i);

// A vertex stage's wrapper for WebGPU's clip space, put around the body: the body's main()
// becomes wg_runtime_main() and a new main() converts gl_Position as the graph's vs_main does
// (the manifest's "webgpu".conventions: y negated, z' = (z + w) / 2).
std::string webgpuVertexBodyBefore();
std::string webgpuVertexBodyAfter();

// std140 byte offsets of the constants in order, and the block's size (a multiple of 16).
struct Std140Layout {
  std::vector<int> offsets;
  int size = 0;
};
Std140Layout std140Layout(const std::vector<ShaderMember>& constants);

// The declaration table of one WebGPU form (docs/webgpu.md, "The scene description's WebGPU
// forms"): {stage, entry_point, glsl, uniform_block, textures, samplers, inputs, outputs}.
nlohmann::json webgpuShaderTable(const std::string& stage, const std::string& glsl, const ShaderInterface& i);

}  // namespace wg::rt
