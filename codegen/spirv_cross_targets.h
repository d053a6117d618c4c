#pragma once
// Metal Shading Language and HLSL from the vk450 SPIR-V, through SPIRV-Cross
// (docs/ecosystem.md). Files: <graph>.msl.vert / .msl.frag and <graph>.hlsl.vert / .hlsl.frag,
// beside the GLSL ones. HLSL is checked by compiling it again with glslang's HLSL front end
// to SPIR-V and running spirv-val on that; MSL has no compiler on Linux, so it is checked
// only for a successful translation with the expected entry point.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "codegen/target.h"
#include "core/diagnostic.h"

namespace wg {

struct CrossShader {
  ShaderStage stage{};
  std::string text;
  std::string entryPoint;  // "main0" (MSL renames main), "main" (HLSL)
};

// SPIR-V words of one stage -> source. Throws nothing: on failure returns nullopt and sets `error`.
std::optional<CrossShader> crossCompileSpirv(const std::vector<uint32_t>& spirv, ShaderStage stage,
                                             CrossTarget target, std::string& error);

// Compiles HLSL with glslang's HLSL front end (entry `entryPoint`, shader model 5.0 rules),
// generates SPIR-V and validates it. "" when it passes, else glslang's or spirv-val's message.
std::string validateHlsl(const std::string& text, ShaderStage stage, const std::string& entryPoint,
                         const std::string& fileName);

// compileGraph for `targets` plus `cross` targets. vk450 is compiled whenever a cross target is
// asked for (its SPIR-V is the input) but its files are kept only when `targets` names it.
// The manifest's "targets" gains "msl" / "hlsl": the file per stage and the entry points.
std::optional<CompileResult> compileGraphWithCross(const Graph& graph, const Registry& registry,
                                                   CompileOptions options, const std::vector<CrossTarget>& cross,
                                                   Diagnostics& diags);

// Little-endian SPIR-V bytes (as in OutputFile::contents) -> words.
std::vector<uint32_t> spirvWords(const std::string& bytes);

}  // namespace wg
