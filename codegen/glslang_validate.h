#pragma once
// Every emitted shader is compiled and linked by glslang before it is written; vk450 is
// also turned into SPIR-V and checked by the SPIR-V validator.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "codegen/target.h"

namespace wg {

struct ShaderSource {
  ShaderStage stage{};
  std::string fileName;  // "lake.glsl330.frag": glslang's messages name it
  std::string text;
};

struct ShaderMessage {
  std::string fileName;  // which shader ("" for link errors)
  int line = 0;          // 1-based line in that shader, 0 when glslang gives none
  std::string text;      // glslang's message without the "ERROR: file:line:" prefix
};

struct ValidationResult {
  bool ok = false;
  std::vector<ShaderMessage> errors;
  // vk450 only, when ok: one SPIR-V module per input shader, same order.
  std::vector<std::vector<uint32_t>> spirv;
};

// Compiles each shader for `target` (#version is inside the text), links them as one
// program, and for vk450 generates SPIR-V and runs spvtools validation on it.
// Thread-compatible; initialises glslang once per process.
ValidationResult validateShaders(Target target, const std::vector<ShaderSource>& shaders);

// SPIR-V (one module per shader, same order) of OpenGL GLSL shaders (glsl330), compiled
// and linked under glslang's relaxed Vulkan rules: loose uniforms gathered into one
// uniform block, bindings and locations assigned automatically. A driver-independent
// form in which any two glsl330 programs can be compared after spirv-opt (the
// hand-written bench). nullopt, with `errors` when given, if they do not compile and link.
std::optional<std::vector<std::vector<uint32_t>>> relaxedSpirv(const std::vector<ShaderSource>& shaders,
                                                               std::vector<ShaderMessage>* errors = nullptr);

// The uniforms (loose, uniform-block members and samplers) that glslang's reflection finds
// read by the linked program, sorted; empty when the shaders do not compile and link.
// The "declares only what it reads" tests compare these with the declarations.
std::optional<std::vector<std::string>> activeUniforms(Target target, const std::vector<ShaderSource>& shaders);

}  // namespace wg
