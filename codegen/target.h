#pragma once
// The GLSL dialects watergraph emits. Per-target differences live in small tables
// (codegen/target.cpp), not in `if (target)` inside nodes.
#include <optional>
#include <string_view>
#include <vector>

namespace wg {

enum class Target { Glsl330, Es300, Vk450 };

std::string_view targetName(Target t);  // "glsl330", "es300", "vk450"
// What follows "#version " on the first line of every shader of `t`: "330 core", "300 es", "450".
std::string_view targetGlslVersion(Target t);
std::optional<Target> parseTarget(std::string_view name);
const std::vector<Target>& allTargets();

// Targets made from vk450's SPIR-V by SPIRV-Cross (codegen/spirv_cross_targets.h): Metal
// Shading Language and HLSL. Not GLSL dialects, so not in allTargets(); compiling for one
// compiles vk450 too (its SPIR-V is the input).
enum class CrossTarget { Msl, Hlsl };

std::string_view crossTargetName(CrossTarget t);  // "msl", "hlsl"
std::optional<CrossTarget> parseCrossTarget(std::string_view name);
const std::vector<CrossTarget>& allCrossTargets();

enum class ShaderStage { Vertex, TessControl, TessEvaluation, Fragment };
std::string_view stageExtension(ShaderStage s);  // "vert", "tesc", "tese", "frag"

// Whether `compile` writes each stage of `t` a second time without its version line, as
// "<stage file>.body" (EmittedShader::bodyStart; the manifest's "three" section names them
// with the "glsl_version" they lack): es300, for hosts that write the version line
// themselves (three.js's RawShaderMaterial).
inline bool writesStageBodies(Target t) { return t == Target::Es300; }
inline constexpr std::string_view kStageBodySuffix = ".body";

}  // namespace wg
