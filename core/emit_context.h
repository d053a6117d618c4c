#pragma once
// The codegen side of a node (NodeSpec::emit): the context an emit() writes GLSL through,
// and the values it hands out. Every piece of text a node receives from the context is a
// GlslExpr that carries, next to its text, what it reads of the context: the symbols the
// planner handed out (a temporary, a parameter, a builtin, a uniform, a sampler, a texture
// look-up) and the library functions called through EmitContext::call. Concatenation
// merges them. The planner decides from these sets, never from the text, which locals a
// stage keeps, which declarations the kept text still reads and which library items a
// stage needs (codegen/plan_body.cpp). A GlslExpr also carries how many operations it asks
// for (core/glsl_operation_count.h), counted as it is built: the planner keeps per line what
// the ops wrote (PlannedStatement::cost), which --explain-frequency reports.
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/glsl_operation_count.h"
#include "core/node_spec.h"

namespace wg {

// A few ids, each once, in order of first insertion: inline up to four (what nearly every
// expression reads), on the heap beyond, so building an expression allocates for its text
// alone.
class GlslExprIds {
 public:
  std::span<const uint32_t> view() const {
    return heap_.empty() ? std::span<const uint32_t>(inline_, size_) : std::span<const uint32_t>(heap_);
  }
  bool contains(uint32_t id) const;
  void add(uint32_t id);
  void addAll(const GlslExprIds& other) {
    for (uint32_t id : other.view()) add(id);
  }

 private:
  static constexpr uint32_t kInline = 4;
  uint32_t inline_[kInline] = {};
  uint32_t size_ = 0;
  std::vector<uint32_t> heap_;  // all of them, once there are more than kInline
};

class GlslExpr {
 public:
  GlslExpr() = default;
  // Text that reads nothing of the context: an operator, a constant, a swizzle. It is a
  // piece the node (or the planner) writes: its operations are counted once, here.
  GlslExpr(const char* text) : GlslExpr(std::string_view(text)) {}
  GlslExpr(std::string text) : text_(std::move(text)) { countPiece(text_); }
  GlslExpr(std::string_view text) : text_(text) { countPiece(text_); }
  // A symbol a context hands out: `text` reads the context's symbol `symbol` (its meaning
  // is the context's); `isName` says the text is one identifier, which a planner may use
  // in place of a copy.
  static GlslExpr symbol(std::string text, uint32_t symbol, bool isName = true);
  // A value of the context that is neither a symbol of this op nor a library call (another
  // op's output, a varying): an identifier that reads nothing the op declared.
  static GlslExpr name(std::string text);
  // Adds `symbol` to what this text reads.
  GlslExpr& reading(uint32_t symbol);

  const std::string& text() const { return text_; }
  // The operations the text asks for (core/glsl_operation_count.h): those of the pieces
  // written into it, of the values appended and of the calls made through EmitContext::call.
  int operations() const { return operations_; }
  bool empty() const { return text_.empty(); }
  bool isName() const { return name_; }
  // The context's symbols the text reads, each once, in order of first use.
  std::span<const uint32_t> symbols() const { return symbols_.view(); }
  // The functions called through EmitContext::call, each once, in order of first call: as
  // ids (callName gives the name; one id per name for the whole process) and as names.
  std::span<const uint32_t> callIds() const { return calls_.view(); }
  std::vector<std::string> calls() const;
  static const std::string& callName(uint32_t id);

  GlslExpr& operator+=(const GlslExpr& b);
  GlslExpr& operator+=(std::string_view b);
  GlslExpr& operator+=(const char* b) { return *this += std::string_view(b); }
  GlslExpr& operator+=(const std::string& b) { return *this += std::string_view(b); }
  GlslExpr& operator+=(char c) { return *this += std::string_view(&c, 1); }

 private:
  friend class EmitContext;
  void countPiece(std::string_view piece);
  std::string text_;
  bool name_ = false;
  int operations_ = 0;
  GlslOperationScan scan_;  // where the count stands at the end of the text
  GlslExprIds symbols_;
  GlslExprIds calls_;
};

inline GlslExpr operator+(GlslExpr a, const GlslExpr& b) { return a += b; }
inline GlslExpr operator+(GlslExpr a, const char* b) { return a += b; }
inline GlslExpr operator+(GlslExpr a, const std::string& b) { return a += b; }
inline GlslExpr operator+(GlslExpr a, std::string_view b) { return a += b; }
inline GlslExpr operator+(GlslExpr a, char b) { return a += b; }
inline GlslExpr operator+(const char* a, const GlslExpr& b) { return GlslExpr(a) += b; }
inline GlslExpr operator+(const std::string& a, const GlslExpr& b) { return GlslExpr(a) += b; }
inline GlslExpr operator+(std::string_view a, const GlslExpr& b) { return GlslExpr(a) += b; }
inline GlslExpr operator+(char a, const GlslExpr& b) { return GlslExpr(std::string(1, a)) += b; }

// Inputs come in as GLSL expressions already converted to the port's type; the node hands
// back one expression per output. Names are generated by the emitter; a node never writes
// an identifier from the graph file.
class EmitContext {
 public:
  virtual ~EmitContext() = default;
  virtual GlslExpr input(int port) = 0;
  virtual Type inputType(int port) const = 0;
  virtual Type outputType(int port) const = 0;
  // The op's options, parsed once into the node's struct (core/node_options.h).
  virtual const ParsedOptions& parsedOptions() const = 0;
  template <class T>
  const T& options() const { return parsedOptions().as<T>(); }
  virtual void output(int port, GlslExpr expression) = 0;
  virtual GlslExpr builtin(Builtin b) = 0;
  // Declares a local `type name = expression;` and returns its generated name.
  virtual GlslExpr temporary(Type type, GlslExpr expression) = 0;
  virtual unsigned stage() const = 0;  // kVertexStage or kFragmentStage
  // A uniform holding mod(omega * time, 2*pi), computed by the runtime in double
  // precision each frame, so time-driven phases stay exact at t = 1e6 s where a float
  // u_time has 0.06 s steps. The CPU reference computes the same in double.
  virtual GlslExpr timePhase(double omega) = 0;
  // The sampler2D that holds the texture named by a Texture option, sampled with
  // `sampler` (declared once per distinct source and state, listed in the manifest; two
  // states of one source are two samplers, each with its own texture object).
  virtual GlslExpr texture(std::string_view option, const SamplerState& sampler) = 0;
  // With the default state: GL_REPEAT, GL_LINEAR, no mipmaps, linear data.
  GlslExpr texture(std::string_view option) { return texture(option, SamplerState{}); }
  // The sampler the runtime binds for a scene resource the node lists in `resources`
  // (SceneDepth -> u_scene_depth; see core/interface_tables.h).
  virtual GlslExpr sceneTexture(SceneResource resource) = 0;
  GlslExpr sceneTexture(std::string_view resource);  // by the resource's name
  // A look-up the node's own expressions make, "texture(S, coord)", of the texture of option
  // `option` or of scene resource `resource`. Through these the planner lists every look-up
  // main() makes (codegen/shader_plan.h TextureFetch: check reads them back); a sampler
  // named by texture(), sceneTexture() or oceanMap() is one handed on to a function (or to
  // textureLod), whose look-ups the planner does not see.
  virtual GlslExpr sampleTexture(std::string_view option, const SamplerState& sampler, const GlslExpr& coord);
  GlslExpr sampleTexture(std::string_view option, const GlslExpr& coord) {
    return sampleTexture(option, SamplerState{}, coord);
  }
  virtual GlslExpr sampleScene(SceneResource resource, const GlslExpr& coord);
  GlslExpr sampleScene(std::string_view resource, const GlslExpr& coord);
  // Declares the texture of option `option` now, for a node that samples it with
  // sampleTexture only after another texture (node textures are numbered by first use).
  virtual void reserveTexture(std::string_view option) { texture(option); }

  // The spectral ocean (ocean_* readers): the settings of the ocean_spectrum feeding input
  // `port` (an `ocean` port), and the sampler2D holding its cascade `cascade`'s map
  // `which` (OceanMap; declared once per ocean, cascade and map, listed in the manifest).
  // By default the spectrum's default settings and a logic error: only the planner
  // has maps to give.
  virtual const ocean::OceanSettings& oceanSettings(int port) const;
  virtual GlslExpr oceanMap(int port, int cascade, int which);

  // What is known about input `port` (see ValueFact); nothing by default.
  virtual ValueFact inputFact(int port) const;
  // What is known about a builtin read through builtin(): builtinFact(b) in a compiled
  // shader, nothing in a probe shader (its builtins come from arbitrary cases).
  virtual ValueFact knownBuiltin(Builtin b) const;
  // Input `port` as a constant of the port's type, when it is one (folded or literal).
  virtual std::optional<Value> inputConstant(int port) const;
  ValueFact inputFact(std::string_view port) const;

  GlslExpr input(std::string_view port);
  GlslExpr literal(double x) const;          // a GLSL float literal
  GlslExpr literal(const Value& v) const;    // float or vecN(...)
  // "fn(a, b, c)", recording `fn` among the calls the result makes (GlslExpr::calls): `fn`
  // is a function of the GLSL library (nodes/glsl/) or a GLSL built-in function. A library
  // function reaches a shader only through here: the planner declares the library items
  // the kept expressions call, and nothing else.
  static GlslExpr call(std::string_view fn, std::initializer_list<GlslExpr> args);
  int inputIndex(std::string_view port) const;
  virtual const NodeSpec& spec() const = 0;
};

}  // namespace wg
