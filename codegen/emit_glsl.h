#pragma once
// ShaderPlan -> GLSL source per stage for one target: the plan's bodies wrapped in the
// target's declarations (version, precision, qualifiers, layouts, the vk450 uniform
// block), with a map from each output line back to the op that wrote it. Nothing here
// decides what a shader reads or computes; codegen/shader_plan.h does, once for all targets.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "codegen/target.h"
#include "core/program.h"

namespace wg {

struct EmittedShader {
  ShaderStage stage{};
  std::string text;
  std::vector<int> lineOp;  // per 1-based line - 1: the op index that wrote it, or -1
  // The text is "#version " + targetGlslVersion(target) + "\n" and the body from bodyStart
  // on: the form a host that writes the version line itself takes (three.js's
  // RawShaderMaterial, whose #defines follow that line), the `<graph>.es300.<stage>.body` files.
  size_t bodyStart = 0;
};

struct EmitResult {
  std::vector<EmittedShader> shaders;  // the plan's stages, in pipeline order
  // The plan's interface, copied for callers that hold only the result (the probe runner).
  std::vector<UniformInfo> uniforms;   // declaration order
  std::vector<AttributeInfo> attributes;
  std::vector<TextureInfo> textures;   // node textures by first use, ocean maps, then scene textures
  std::vector<OceanInfo> oceans;       // the oceans the ocean maps come from
  std::vector<VaryingInfo> varyings;
  std::vector<std::string> functions;  // library items emitted, in order (union of stages)
  // Set when the geometry stage is tessellated: shaders are then vertex, tess control,
  // tess evaluation (where the vertex-stage nodes run) and fragment; patches of 3.
  std::optional<TessellationSettings> tessellation;
};

// The plan's stages for `target`. A plan made with tessellation needs a target that has
// tessellation stages (not es300).
EmitResult emitGlsl(const ShaderPlan& plan, Target target);

// One stage of `plan` (or a variant of one of its stages: codegen/readback_taps.h) for `target`.
EmittedShader emitStage(const ShaderPlan& plan, const PlannedStage& stage, Target target);

// Shader: planShaders; Probe: planProbe (see codegen/shader_plan.h). The tap frames of
// `check` are a third mode, of the fragment stage alone: emitTapFragment (codegen/readback_taps.h).
enum class EmitMode { Shader, Probe };

// One target from a plan of its own. `allowTessellation` false draws the mesh as it is
// even where the target could tessellate (for HLSL through SPIRV-Cross, which has no HLSL
// tessellation stages).
EmitResult emitProgram(const Program& program, Target target, const std::string& sourceName,
                       EmitMode mode = EmitMode::Shader, bool allowTessellation = true);

// The same as emitProgram per target (EmitMode::Shader), each result byte-identical to
// it, from one plan per distinct tessellation choice (planTargets).
std::vector<EmitResult> emitPrograms(const Program& program, const std::vector<Target>& targets,
                                     const std::string& sourceName, bool allowTessellation = true);

}  // namespace wg
