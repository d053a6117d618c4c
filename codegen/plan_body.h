#pragma once
// Inside the planner (codegen/plan_*.cpp): the writer of stage bodies that every kind of
// plan shares. It runs each op's emit() for one stage, names op outputs, parameters, time
// phases and samplers, and records what the body used; how a builtin is named is the one
// thing each kind of plan decides for itself (the BuiltinNamer it is given).
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "codegen/value_facts.h"
#include "core/emit_context.h"
#include "core/program.h"

namespace wg {

// The symbols the body writer hands out in GlslExprs (GlslExpr::symbols): a kind and an
// index within it. An op's emit reads its locals, declarations and look-ups through them,
// so the writer knows from the values, not from the text, what a kept line reads.
enum class PlanSymbol : uint32_t { Temporary, Parameter, Builtin, Uniform, Phase, NodeTexture, SceneTexture, OceanTexture, Ocean, Fetch };
inline uint32_t planSymbol(PlanSymbol kind, size_t index) {
  return static_cast<uint32_t>(kind) << 24 | static_cast<uint32_t>(index);
}
inline PlanSymbol planSymbolKind(uint32_t symbol) { return static_cast<PlanSymbol>(symbol >> 24); }
inline size_t planSymbolIndex(uint32_t symbol) { return symbol & 0xFFFFFFu; }

// The builtin locals a planner writes at the top of main(), built as values: each a
// declaration with its operations, and the library functions they call (the stage declares
// those items with the ones its ops call).
struct StageLocals {
  PlannedLines lines;
  std::vector<std::string> calls;
  void add(Type type, std::string_view name, const GlslExpr& value) {
    lines.declare(-1, value.operations(), type, name, value.text());
    for (uint32_t fn : value.callIds()) calls.push_back(GlslExpr::callName(fn));
  }
};

// One stage's body being written: its statements, each with the op that wrote it and the
// operations of the values written into it (PlannedLines), and what it used.
struct StageBody {
  unsigned stage = 0;  // kVertexStage or kFragmentStage
  PlannedLines body;
  std::set<Builtin> builtins;
  std::set<int> parameters;
  std::set<BuiltinUniform> builtinUniforms;
  // The functions the kept lines call (EmitContext::call, GlslExpr::callIds): which op
  // calls which, each pair once, in the order of the body (PlannedStage::opCalls).
  std::vector<std::pair<int, uint32_t>> opCalls;
  // Op outputs whose expression is already a name (a builtin, another temporary): used
  // directly instead of copying into a new local. By the writer's port index ("" none; a
  // flat vector: a map keyed by (op, port) was a tree walk per input on large graphs).
  // An alias reads what its name reads, but not the op's own temporaries (their symbols
  // mean something only inside that op): those symbols by port index, in the order the
  // aliases were made (ascending), only for the aliases that read any (a builtin, a
  // parameter, a sampler), so the flat vector stays one string per port.
  std::vector<std::string> aliases;
  std::vector<std::pair<size_t, std::vector<uint32_t>>> aliasSymbols;
  // The look-ups the ops make through EmitContext::sampleTexture and sampleScene (in the
  // order of the text; `kept` false once the text holding one was left out), and how often
  // each sampler is handed on by name (texture(), sceneTexture(), oceanMap()).
  struct Fetch {
    TextureFetch fetch;
    bool kept = true;
    bool coordIsScreenUv = false;  // the coordinate is the screen uv builtin itself
  };
  std::vector<Fetch> fetches;
  std::map<std::string, int> handedOn;

  // While an op is written: what its emit declared for the first time in this stage (a
  // parameter, a builtin uniform, a texture, ...), each with how to take it back, so a local
  // the writer leaves out does not leave a declaration nothing reads: the symbol the values
  // that read it carry (PlanSymbol).
  struct Registration {
    uint32_t symbol;
    std::function<void()> undo;
  };
  std::vector<Registration>* registered = nullptr;
  void noteRegistered(uint32_t symbol, std::function<void()> undo) {
    if (registered) registered->push_back({symbol, std::move(undo)});
  }

  explicit StageBody(unsigned s) : stage(s) {}
  // Records that the body reads uniform `u`; returns its GLSL name.
  std::string use(BuiltinUniform u);
  // The same, as a value that reads it.
  GlslExpr uniform(BuiltinUniform u) { return GlslExpr::symbol(use(u), planSymbol(PlanSymbol::Uniform, static_cast<size_t>(u))); }
};

class BodyWriter {
 public:
  // The expression for builtin `b` in `body` (which uniforms it needs go into body).
  using BuiltinNamer = std::function<GlslExpr(StageBody& body, Builtin b)>;
  // `knowFacts` false: the builtins and parameters may hold anything (probe cases), so
  // nodes are told nothing about their inputs.
  BodyWriter(const Program& program, bool knowFacts, BuiltinNamer namer);
  // Every op of body.stage, one local per used output that is not already a name.
  void writeOps(StageBody& body);
  GlslExpr valueExpr(StageBody& body, const ValueRef& r, Type want);
  GlslExpr outputExpr(StageBody& body, OutputSlot slot, GlslExpr fallback);
  GlslExpr builtinExpr(StageBody& body, Builtin b);
  GlslExpr opOutput(const StageBody& body, int op, int port) const;
  const std::string& varyingName(int op, int port) const;
  // Samplers read their own symbol first (handOn registers under it).
  GlslExpr phaseUniform(StageBody& body, double omega);
  GlslExpr nodeTexture(StageBody& body, const std::string& source, const SamplerState& sampler);
  GlslExpr sceneSampler(StageBody& body, SceneSampler sampler);
  // Records a look-up of `sampler` at `coord` in `body`; returns the call.
  GlslExpr fetch(StageBody& body, const GlslExpr& sampler, const GlslExpr& coord);
  // Records that an op hands `sampler` on by name (to a function); returns the name.
  GlslExpr handOn(StageBody& body, GlslExpr sampler);
  // Map `which` of cascade `cascade` of the ocean op `spectrumOp` computes.
  GlslExpr oceanMap(StageBody& body, int spectrumOp, int cascade, int which);
  // The oceans the maps read, by first use.
  std::vector<OceanInfo> oceans() const;

  // The interface the bodies made: builtin uniforms in table order, then the time phases,
  // then the parameters `vertex` (may be null) and `fragment` read.
  std::vector<UniformInfo> uniforms(const StageBody* vertex, const StageBody& fragment) const;
  // Node textures by first use, then scene textures in the manifest's resource order;
  // vk450 bindings follow the uniform block's.
  std::vector<TextureInfo> textures() const;

  const Program& program() const { return program_; }
  const ValueFacts& facts() const { return facts_; }
  bool knowsFacts() const { return knowFacts_; }
  const std::string& opName(int op) const { return opNames_[static_cast<size_t>(op)]; }

 private:
  std::string tempName(int op, int port) const;

  const Program& program_;
  bool knowFacts_;
  ValueFacts facts_;  // empty unless knowFacts_
  BuiltinNamer namer_;
  std::vector<std::string> opNames_;
  std::vector<size_t> portBase_;  // op i's outputs are port indices portBase_[i] ... portBase_[i + 1] - 1
  std::vector<std::string> paramNames_;
  std::vector<std::string> varyingNames_;   // by port index ("" for no varying)
  std::vector<UniformInfo> phases_;         // time phases, by first use
  std::vector<TextureInfo> nodeTextures_;   // by first use
  std::vector<TextureInfo> sceneTextures_;  // by first use (sorted by textures())
  std::vector<TextureInfo> oceanTextures_;  // by first use
  std::vector<int> oceanOps_;               // the ocean_spectrum ops the maps read, by first use
};

// Around the bodies (codegen/plan_stage.cpp).
// The planned stage for a written body: its locals, and the library items both call.
PlannedStage plannedStage(ShaderStage stage, StageBody&& body, StageLocals locals);
// Adds to `s` the own GLSL (NodeSpec::ownGlsl) of the ops that wrote its body.
void addOwnGlsl(const Program& program, PlannedStage& s);
// The library items among the functions `called`, with what they use, dependencies first.
std::vector<const GlslItem*> libraryFor(const std::vector<std::string>& called);
// The union of the stages' library items, in library order.
std::vector<std::string> functionsOf(const std::vector<PlannedStage>& stages);
// Loose uniforms of `plan` that `wanted` selects (indices).
std::vector<size_t> uniformsWhere(const ShaderPlan& plan, const std::function<bool(const UniformInfo&)>& wanted);
// Textures of `plan` sampled in stage bit `bit` (indices).
std::vector<size_t> texturesIn(const ShaderPlan& plan, unsigned bit);

// The pieces each kind of plan adds (codegen/plan_deferred.cpp, codegen/plan_tessellation.cpp).
// Deferred: declares the G-buffer samplers the fragment body's builtins need.
void planDeferredSamplers(BodyWriter& writer, StageBody& fragment);
// Deferred: the fragment's surface builtins read from the G-buffer, under the varyings' names.
StageLocals deferredLocals(const StageBody& fragment);
// Deferred: the look-ups those locals make, in their order.
std::vector<TextureFetch> deferredFetches(const StageBody& fragment);
// Tessellation asked for by a vertex-stage node, if any.
std::optional<TessellationSettings> requestedTessellation(const Program& program);
// Tessellated: the evaluation stage's builtin locals (the patch corners interpolated).
StageLocals tessEvaluationLocals(const StageBody& geometry);
// Tessellated: the vertex shader (mesh into world space) and the control stage (levels by
// camera distance), from what the geometry stage reads.
PlannedStage tessVertexStage(const ShaderPlan& plan, const StageBody& geometry);
PlannedStage tessControlStage(const ShaderPlan& plan, const StageBody& geometry);
// What travels from the vertex shader through the control stage to the evaluation stage.
std::vector<StageVariable> patchVariables(const StageBody& geometry, const std::string& prefix);

}  // namespace wg
