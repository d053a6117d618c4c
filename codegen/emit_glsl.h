#pragma once
// Program (after the stage pass) -> GLSL source per stage for one target, with a map
// from each output line back to the op that wrote it, and the shader interface the
// manifest describes. Identifiers are generated; no string from the graph file is pasted.
#include <optional>
#include <string>
#include <vector>

#include "codegen/target.h"
#include "core/program.h"

namespace wg {

struct UniformInfo {
  std::string name;  // GLSL name
  Type type = Type::Float;
  int parameter = -1;       // index into Program::parameters, or -1 for a builtin uniform
  BuiltinUniform builtin = BuiltinUniform::Time;  // what it holds, when parameter < 0
  unsigned stages = 0;      // where it is declared
  double omega = 0;         // time_phase: the value is mod(omega * time, 2 pi)
};

struct AttributeInfo {
  std::string name;
  Type type = Type::Float;
  int location = 0;
};

struct VaryingInfo {
  std::string name;
  Type type = Type::Float;
  std::string carries;  // "world_position", or "node 'wave' output 'normal'"
};

struct TextureInfo {
  std::string name;      // GLSL sampler name
  Type type = Type::Sampler2D;
  std::string source;    // node texture: "builtin:foam" or a path relative to the graph
  SamplerState sampler;  // node texture: how it is sampled (scene textures: the default, unused)
  std::optional<SceneSampler> scene;  // a scene texture (then source is "")
  int binding = 0;       // vk450 binding (set 0); the uniform block is binding 0
  unsigned stages = 0;
};

struct EmittedShader {
  ShaderStage stage{};
  std::string text;
  std::vector<int> lineOp;  // per 1-based line - 1: the op index that wrote it, or -1
};

struct EmitResult {
  std::vector<EmittedShader> shaders;  // vertex, fragment
  std::vector<UniformInfo> uniforms;   // declaration order
  std::vector<AttributeInfo> attributes;
  std::vector<TextureInfo> textures;   // node textures by first use, then scene textures
  std::vector<VaryingInfo> varyings;
  std::vector<std::string> functions;  // library items emitted, in order (union of stages)
  // Set when the geometry stage is tessellated: shaders are then vertex, tess control,
  // tess evaluation (where the vertex-stage nodes run) and fragment; patches of 3.
  std::optional<TessellationSettings> tessellation;
};

// Shader: the vertex and fragment shaders of a drawn surface (or the deferred pass).
// Probe: one fragment shader for `watergraph probe`, run on a full-screen triangle the
// runtime supplies. Every op runs in it; the surface builtins (uv, world position, normal,
// view direction, screen uv, fragment depth) are uniforms named "u_probe_<builtin>"
// (UniformInfo::builtin says which), taken verbatim from the case, so a case can hand a
// node any value, a zero-length normal included; the program's first output, padded with
// zeros to a vec4, is o_color.
enum class EmitMode { Shader, Probe };

// `allowTessellation` false draws the mesh as it is even where the target could
// tessellate (for HLSL through SPIRV-Cross, which has no HLSL tessellation stages).
EmitResult emitProgram(const Program& program, Target target, const std::string& sourceName,
                       EmitMode mode = EmitMode::Shader, bool allowTessellation = true);

// The same as emitProgram per target (EmitMode::Shader), each result byte-identical to
// it, with the stage bodies written once for all targets that tessellate alike (the
// bodies do not depend on the GLSL dialect; only the declarations around them do).
std::vector<EmitResult> emitPrograms(const Program& program, const std::vector<Target>& targets,
                                     const std::string& sourceName, bool allowTessellation = true);

// A graph identifier made safe as part of a GLSL name: [A-Za-z0-9_] only, no "__",
// at most 24 characters.
std::string sanitiseIdentifier(std::string_view id);

}  // namespace wg
