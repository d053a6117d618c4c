#pragma once
// The plan between the passes and the emitters: one plain value, built once from the final
// Program, holding everything about the shaders that does not depend on the GLSL dialect —
// the interface (attributes, varyings, uniforms, samplers with their vk450 bindings), the
// scene resources and passes, tessellation, and per stage its statements (each with the op
// that wrote it) and the library items it calls. Each target's emitter (codegen/emit_glsl.h) only wraps a
// plan in its dialect's declarations; the manifest (codegen/manifest_build.h) reads the
// plan too, so the two cannot disagree. Identifiers are generated; no string from the
// graph file is pasted.
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "codegen/target.h"
#include "core/interface_tables.h"
#include "core/program.h"

namespace wg {

struct GlslItem;

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

// An ocean map (core/ocean_settings.h): which of ShaderPlan::oceans, which cascade, which map.
struct OceanMapRef {
  int ocean = 0;
  int cascade = 0;
  int map = 0;  // kDisplacementMap, kSlopeMap, kFoamMap or kMomentsMap
  bool operator==(const OceanMapRef&) const = default;
};

// A spectral ocean the water reads: the ocean_spectrum op's node id and complete options
// (the runtime parses them with the node's own parser and simulates them).
struct OceanInfo {
  std::string nodeId;
  nlohmann::json options;
  // A shader reads its moments maps (ocean_surface's filtered reader): every cascade then
  // keeps its slope and moments maps with mip pyramids (ocean_pack_filtered and one
  // ocean_downsample per level) and computes its slopes whether read or not. Decided here
  // once, from the maps the plan samples; the runtimes and the web clients read the value.
  bool filtered = false;
};

struct TextureInfo {
  std::string name;      // GLSL sampler name
  Type type = Type::Sampler2D;
  std::string source;    // node texture: "builtin:foam" or a path relative to the graph
  std::string file;      // node texture, manifest only: the PNG `compile --textures` writes it as
  SamplerState sampler;  // node texture: how it is sampled (scene textures: the default, unused)
  std::optional<SceneSampler> scene;  // a scene texture (then source is "")
  std::optional<OceanMapRef> ocean;   // an ocean map (then source is "")
  int binding = 0;       // vk450 binding (set 0); the uniform block is binding 0
  unsigned stages = 0;
};

// One variable of a stage's `in` or `out` interface (vk450 numbers them from 0 per list).
struct StageVariable {
  Type type = Type::Float;
  std::string name;
};

// A texture() look-up main() makes: a node's (EmitContext::sampleTexture, sampleScene) or
// a deferred G-buffer local's. Its coordinate names only what main() declares before it,
// so the call is valid anywhere after, up to the end of main() (check's tap frames read it
// back there, accuracy/readback.h).
struct TextureFetch {
  std::string sampler;  // GLSL name, as in ShaderPlan::textures
  std::string coord;    // the coordinate expression
  bool atScreenUv = false;  // the coordinate is the stage's screen uv builtin itself
  std::string call() const { return "texture(" + sampler + ", " + coord + ")"; }
};

// One statement of main() as the planner wrote it: a declaration `TYPE NAME = EXPR;` (an
// op's temporary or output, a builtin local) or an assignment `NAME = EXPR;` (gl_Position, a
// varying, the colour output). A target that does not print GLSL (WGSL) prints it from these
// values: the declared type, the name and the expression the values were built into.
// A stage of fixed text (the tessellated pipeline's vertex and control stages) has Fixed
// lines, which only the GLSL targets print.
struct PlannedStatement {
  enum class Kind : unsigned char { Declare, Assign, Fixed };
  Kind kind = Kind::Fixed;
  Type type = Type::Invalid;  // Declare: the local's type
  int op = -1;                // the op that wrote it, or -1
  // The operations it asks for, counted from the values as they were built
  // (GlslExpr::operations, core/glsl_operation_count.h), never from the text; 0 when Fixed.
  int cost = 0;
  // Offsets into PlannedLines::text, where the statement's parts were written (not a copy
  // of them: the text is most of a big graph's plan): the target name, the expression, and
  // the end of the line (past ";\n").
  uint32_t name = 0, expression = 0, end = 0;
};

// Lines of main(), each "  " + statement + '\n' in one text (no string per line), and the
// statement each line holds, in order. The GLSL targets print the text; the WGSL target
// prints the statements.
struct PlannedLines {
  std::string text;
  std::vector<PlannedStatement> statements;

  std::string_view name(const PlannedStatement& s) const {
    return std::string_view(text).substr(s.name, s.expression - kAssignLength - s.name);
  }
  std::string_view expression(const PlannedStatement& s) const {
    return std::string_view(text).substr(s.expression, s.end - kEndLength - s.expression);
  }
  // `TYPE NAME = EXPR;` from its parts (the expression's pieces appended as they come).
  template <class... Parts>
  void declare(int op, int cost, Type type, std::string_view name, const Parts&... expression) {
    text += "  ";
    text += typeName(type);
    text += ' ';
    write(PlannedStatement::Kind::Declare, type, op, cost, name, expression...);
  }
  // `NAME = EXPR;` from its parts.
  template <class... Parts>
  void assign(int op, int cost, std::string_view name, const Parts&... expression) {
    text += "  ";
    write(PlannedStatement::Kind::Assign, Type::Invalid, op, cost, name, expression...);
  }
  // A line of fixed text (no op wrote it), without its indent and '\n'.
  void fixed(std::string_view line) {
    text += "  ";
    text += line;
    text += '\n';
    statements.push_back({PlannedStatement::Kind::Fixed, Type::Invalid, -1, 0, 0, 0, offset()});
  }
  // The first `count` statements and their text.
  void keepFirst(size_t count) {
    statements.resize(count);
    text.resize(count == 0 ? 0 : statements.back().end);
  }
  int cost() const {
    int total = 0;
    for (const auto& s : statements) total += s.cost;
    return total;
  }
  void shrinkToFit() {
    text.shrink_to_fit();
    statements.shrink_to_fit();
  }

 private:
  static constexpr uint32_t kAssignLength = 3, kEndLength = 2;  // " = ", ";\n"
  uint32_t offset() const { return static_cast<uint32_t>(text.size()); }
  template <class... Parts>
  void write(PlannedStatement::Kind kind, Type type, int op, int cost, std::string_view name, const Parts&... expression) {
    const uint32_t nameAt = offset();
    text += name;
    text += " = ";
    const uint32_t expressionAt = offset();
    (text.append(std::string_view(expression)), ...);
    text += ";\n";
    statements.push_back({kind, type, op, cost, nameAt, expressionAt, offset()});
  }
};

// One shader of the pipeline, before any target's declarations are wrapped around it.
struct PlannedStage {
  ShaderStage stage{};
  PlannedLines locals;  // the builtin locals at the top of main (no op wrote them)
  PlannedLines body;    // the ops' lines and the stage's outputs, after the locals
  std::set<Builtin> builtins;       // the builtins the body reads
  std::vector<AttributeInfo> attributes;  // vertex inputs it declares
  std::vector<StageVariable> inputs, outputs;
  bool arrayedInputs = false, arrayedOutputs = false;  // tessellation patches: "name[]"
  std::vector<size_t> uniforms;  // indices into ShaderPlan::uniforms declared loose here
  std::vector<size_t> textures;  // indices into ShaderPlan::textures sampled here
  std::vector<const GlslItem*> library;  // items of GlslLibrary::builtin() called, dependencies first
  // The functions the kept lines call (EmitContext::call), each once, with the first op
  // whose lines call it, in the order of the body. The WGSL target names the node behind an
  // error in a library item from it.
  std::vector<std::pair<int, std::string>> opCalls;
  // The ops' own GLSL (NodeSpec::ownGlsl: function nodes' files, renamed), each once, after
  // the library, with the first op that needs it (glslang's errors in it name that node).
  std::vector<std::shared_ptr<const std::string>> ownGlsl;
  std::vector<int> ownGlslOp;
  // What main() samples, as planned, not as read from the text: its look-ups in the order of
  // the text, and the samplers it hands to a function or to a call other than texture()
  // (look-ups inside those are not listed).
  std::vector<TextureFetch> fetches;
  std::set<std::string> handedOn;
  // A drawn fragment stage: the colour statement, the body's last: its index in
  // body.statements; npos where the stage writes none.
  size_t colorStatement = std::string::npos;
};

struct ShaderPlan {
  // Surface: a drawn mesh. Deferred: an op reads the underwater resource, so the fragment
  // stage runs as a full-screen pass taking the surface builtins from the water G-buffer.
  // Probe: one fragment shader for `watergraph probe` (see planProbe).
  enum class Kind { Surface, Deferred, Probe };
  Kind kind = Kind::Surface;
  // Set when the geometry stage is tessellated: the stages are then vertex, tess control,
  // tess evaluation (where the vertex-stage nodes run) and fragment; patches of 3.
  std::optional<TessellationSettings> tessellation;
  std::vector<PlannedStage> stages;  // pipeline order
  // The interface, the same in every target.
  std::vector<AttributeInfo> attributes;
  std::vector<VaryingInfo> varyings;
  std::vector<UniformInfo> uniforms;   // builtins in table order, time phases, parameters
  std::vector<TextureInfo> textures;   // node textures by first use, ocean maps, then scene textures
  std::vector<OceanInfo> oceans;       // by first use; each runs RenderPass::OceanSimulation's passes
  std::vector<std::string> functions;  // library items of all stages, in library order
  std::vector<SceneResource> resources;  // table order
  std::vector<RenderPass> passes;        // the passes producing them, then WaterSurface
  // For the header comment of every shader.
  std::string sourceName;
  std::string graphName;

  const PlannedStage* stage(ShaderStage s) const;  // null when the plan has none
};

// Whether `target` can run a tessellated geometry stage when `allowed` (GLSL ES 3.00 has
// no such stages; HLSL through SPIRV-Cross asks for none).
bool tessellates(Target target, bool allowed);

// The vertex and fragment stages of a drawn surface, or of the deferred pass.
// `tessellate`: tessellate the geometry stage where a vertex-stage node asks for it.
ShaderPlan planShaders(const Program& program, std::string sourceName, bool tessellate);

// Probe: one fragment shader for `watergraph probe`, run on a full-screen triangle the
// runtime supplies. Every op runs in it; the surface builtins (uv, world position, normal,
// view direction, screen uv, fragment depth) are uniforms named "u_probe_<builtin>"
// (UniformInfo::builtin says which), taken verbatim from the case, so a case can hand a
// node any value, a zero-length normal included; the program's first output, padded with
// zeros to a vec4, is o_color.
ShaderPlan planProbe(const Program& program, std::string sourceName);

// The plans for several targets: one per distinct tessellation choice, shared by every
// target that tessellates alike.
struct TargetPlans {
  std::vector<Target> targets;
  std::vector<ShaderPlan> plans;
  std::vector<size_t> planOf;  // per target: its index in plans
  const ShaderPlan& of(size_t targetIndex) const { return plans[planOf[targetIndex]]; }
};
TargetPlans planTargets(const Program& program, const std::vector<Target>& targets, const std::string& sourceName,
                        bool allowTessellation = true);

// Sets plan.resources and plan.passes: the ocean simulation when plan.oceans is not empty,
// the scene resources the program reads and the passes producing them (table order), then
// the water surface pass.
void planResources(const Program& program, ShaderPlan& plan);

// A graph identifier made safe as part of a GLSL name: [A-Za-z0-9_] only, no "__",
// at most 24 characters.
std::string sanitiseIdentifier(std::string_view id);

}  // namespace wg
