#include "codegen/plan_body.h"

#include <algorithm>
#include <tuple>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "codegen/shader_interface.h"
#include "core/number_format.h"
#include "core/ocean_settings.h"
#include "core/texture_check.h"

namespace wg {
namespace {

std::string glslLiteral(const Value& v) {
  if (v.size() == 1) return formatGlslFloat(v[0]);
  std::string s(typeName(v.type));
  s += '(';
  bool same = true;
  for (int i = 1; i < v.size(); ++i) same &= v[i] == v[0] && std::signbit(v[i]) == std::signbit(v[0]);  // -0.0 is not 0.0
  if (same) return s + formatGlslFloat(v[0]) + ')';
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatGlslFloat(v[i]);
  return s + ')';
}

// Scene samplers are declared in the order of their resources' table rows.
int sceneSamplerRank(const TextureInfo& t) { return static_cast<int>(sceneSamplerRow(*t.scene).resource); }

// What an op's emit() sees: its inputs as expressions, and the writer to name the rest.
class PlanOpContext final : public EmitContext {
 public:
  PlanOpContext(BodyWriter& w, StageBody& b, int opIndex) : w_(w), b_(b), opIndex_(opIndex) {}
  GlslExpr input(int port) override {
    return w_.valueExpr(b_, op().inputs.at(static_cast<size_t>(port)), op().inputTypes.at(static_cast<size_t>(port)));
  }
  Type inputType(int port) const override { return op().inputTypes.at(static_cast<size_t>(port)); }
  Type outputType(int port) const override { return op().outputTypes.at(static_cast<size_t>(port)); }
  const ParsedOptions& parsedOptions() const override {
    if (!op().parsedOptions) throw std::logic_error("op '" + op().nodeId + "' has no parsed options");
    return *op().parsedOptions;
  }
  void output(int port, GlslExpr expression) override { outputs.at(static_cast<size_t>(port)) = std::move(expression); }
  GlslExpr builtin(Builtin b) override { return w_.builtinExpr(b_, b); }
  // Held until the op's outputs are known: writeOps leaves out a local no read output needs.
  GlslExpr temporary(Type type, GlslExpr expression) override {
    std::string name = w_.opName(opIndex_) + "_t" + std::to_string(temps.size());
    temps.push_back({type, name, std::move(expression)});
    return GlslExpr::symbol(std::move(name), planSymbol(PlanSymbol::Temporary, temps.size() - 1));
  }
  unsigned stage() const override { return b_.stage; }
  GlslExpr timePhase(double omega) override { return w_.phaseUniform(b_, omega); }
  using EmitContext::texture;
  GlslExpr texture(std::string_view option, const SamplerState& sampler) override {
    return w_.handOn(b_, nodeTexture(option, sampler));
  }
  GlslExpr sceneTexture(SceneResource resource) override { return w_.handOn(b_, sceneTextureName(resource)); }
  using EmitContext::sampleTexture;
  GlslExpr sampleTexture(std::string_view option, const SamplerState& sampler, const GlslExpr& coord) override {
    return w_.fetch(b_, nodeTexture(option, sampler), coord);
  }
  using EmitContext::sampleScene;
  GlslExpr sampleScene(SceneResource resource, const GlslExpr& coord) override {
    return w_.fetch(b_, sceneTextureName(resource), coord);
  }
  void reserveTexture(std::string_view option) override { nodeTexture(option, SamplerState{}); }
  const ocean::OceanSettings& oceanSettings(int port) const override {
    return spectrumOp(port).parsedOptions->as<ocean::OceanSettings>();
  }
  GlslExpr oceanMap(int port, int cascade, int which) override {
    spectrumOp(port);
    return w_.handOn(b_, w_.oceanMap(b_, op().inputs.at(static_cast<size_t>(port)).index, cascade, which));
  }
  const NodeSpec& spec() const override { return *op().spec; }
  ValueFact inputFact(int port) const override {
    const ValueRef& in = op().inputs.at(static_cast<size_t>(port));
    ValueFact f = w_.facts().of(in, op().inputTypes.at(static_cast<size_t>(port)));
    // Read through a varying: interpolation keeps a range (a convex combination) but not
    // unit length.
    if (in.kind == ValueRef::Kind::Op && b_.stage == kFragmentStage &&
        !(w_.program().ops[static_cast<size_t>(in.index)].stage & kFragmentStage))
      f.normalized = false;
    return f;
  }
  ValueFact knownBuiltin(Builtin b) const override { return w_.knowsFacts() ? builtinFact(b) : ValueFact{}; }
  std::optional<Value> inputConstant(int port) const override {
    const ValueRef& in = op().inputs.at(static_cast<size_t>(port));
    if (in.kind != ValueRef::Kind::Const) return std::nullopt;
    return in.constant().convertedTo(op().inputTypes.at(static_cast<size_t>(port)));
  }

  struct Temporary {
    Type type;
    std::string name;
    GlslExpr expression;
  };
  std::vector<GlslExpr> outputs;
  std::vector<Temporary> temps;

 private:
  const Op& op() const { return w_.program().ops[static_cast<size_t>(opIndex_)]; }
  GlslExpr nodeTexture(std::string_view option, const SamplerState& sampler) {
    const nlohmann::json& v = op().options().at(option);
    if (!v.is_string()) throw std::logic_error("texture(): option '" + std::string(option) + "' is not a texture");
    return w_.nodeTexture(b_, v.get<std::string>(), sampler);
  }
  GlslExpr sceneTextureName(SceneResource resource) {
    const auto& resources = spec().resources;
    const SceneResourceRow& row = sceneResourceRow(resource);
    if (std::find(resources.begin(), resources.end(), resource) == resources.end())
      throw std::logic_error("node '" + spec().type + "' samples scene resource '" + std::string(row.name) +
                             "' without listing it in its resources");
    return w_.sceneSampler(b_, row.sampler);
  }
  // The ocean_spectrum op feeding an `ocean` input (resolve admits nothing else there).
  const Op& spectrumOp(int port) const {
    const ValueRef& in = op().inputs.at(static_cast<size_t>(port));
    if (in.kind != ValueRef::Kind::Op || op().inputTypes.at(static_cast<size_t>(port)) != Type::Ocean)
      throw std::logic_error("node '" + spec().type + "' reads an ocean from an input that is not an ocean");
    const Op& source = w_.program().ops[static_cast<size_t>(in.index)];
    if (!source.parsedOptions) throw std::logic_error("ocean op '" + source.nodeId + "' has no parsed options");
    return source;
  }
  BodyWriter& w_;
  StageBody& b_;
  int opIndex_;
};

// Takes back the entry a registration appended when it is still the last (`size` is the
// size it made): its name holds its index, so an earlier one stays, declared, when a later
// one of the same op is read.
template <class T>
void popIfLast(std::vector<T>& entries, size_t size) {
  if (entries.size() == size) entries.pop_back();
}

// Which of an op's locals the stage needs: those its read outputs read, and those the
// needed ones read (a local reads only earlier ones).
std::vector<char> neededTemporaries(const PlanOpContext& ctx, const std::vector<char>& outputRead) {
  const size_t n = ctx.temps.size();
  std::vector<char> needed(n, 0);
  auto markRead = [&](const GlslExpr& e) {
    for (uint32_t symbol : e.symbols())
      if (planSymbolKind(symbol) == PlanSymbol::Temporary) needed[planSymbolIndex(symbol)] = 1;
  };
  for (size_t p = 0; p < ctx.outputs.size(); ++p)
    if (outputRead[p]) markRead(ctx.outputs[p]);
  for (size_t t = n; t-- > 0;)
    if (needed[t]) markRead(ctx.temps[t].expression);
  return needed;
}

// Calls `each` with every value of the op the stage keeps: its read outputs and needed locals.
template <class F>
void forKeptValues(const PlanOpContext& ctx, const std::vector<char>& outputRead, const std::vector<char>& needed, F each) {
  for (size_t p = 0; p < ctx.outputs.size(); ++p)
    if (outputRead[p]) each(ctx.outputs[p]);
  for (size_t t = 0; t < ctx.temps.size(); ++t)
    if (needed[t]) each(ctx.temps[t].expression);
}

// Takes back what only left-out locals read: a uniform, texture or builtin the op declared
// first that none of the values the stage keeps from it reads (newest first, so a texture
// appended last is popped first).
void forgetUnread(std::vector<StageBody::Registration>& registered, const PlanOpContext& ctx,
                  const std::vector<char>& outputRead, const std::vector<char>& needed) {
  std::vector<uint32_t> kept;
  forKeptValues(ctx, outputRead, needed, [&](const GlslExpr& e) { kept.insert(kept.end(), e.symbols().begin(), e.symbols().end()); });
  for (size_t k = registered.size(); k-- > 0;)
    if (std::find(kept.begin(), kept.end(), registered[k].symbol) == kept.end()) registered[k].undo();
}

}  // namespace

std::string StageBody::use(BuiltinUniform u) {
  std::string name(builtinUniformRow(u).glslName);
  if (builtinUniforms.insert(u).second)
    noteRegistered(planSymbol(PlanSymbol::Uniform, static_cast<size_t>(u)), [this, u] { builtinUniforms.erase(u); });
  return name;
}

BodyWriter::BodyWriter(const Program& p, bool knowFacts, BuiltinNamer namer)
    : program_(p), knowFacts_(knowFacts), namer_(std::move(namer)) {
  if (knowFacts_) facts_ = ValueFacts(p);
  opNames_.reserve(p.ops.size());
  portBase_.reserve(p.ops.size() + 1);
  portBase_.push_back(0);
  for (size_t i = 0; i < p.ops.size(); ++i) {
    opNames_.push_back("n" + std::to_string(i) + "_" + sanitiseIdentifier(p.ops[i].nodeId));
    portBase_.push_back(portBase_.back() + p.ops[i].outputTypes.size());
  }
  std::set<std::string> taken;
  for (const auto& param : p.parameters) {
    std::string name = "p_" + sanitiseIdentifier(param.name);
    if (!taken.insert(name).second) name = "p" + std::to_string(paramNames_.size()) + "_" + sanitiseIdentifier(param.name);
    taken.insert(name);
    paramNames_.push_back(name);
  }
  varyingNames_.resize(portBase_.back());
  for (size_t k = 0; k < p.varyings.size(); ++k) {
    const ValueRef& v = p.varyings[k];
    const Op& op = p.ops[static_cast<size_t>(v.index)];
    varyingNames_[portBase_[static_cast<size_t>(v.index)] + static_cast<size_t>(v.port)] =
        "v" + std::to_string(k) + "_" + sanitiseIdentifier(op.nodeId) +
        (op.outputTypes.size() > 1 ? "_" + op.spec->outputs[static_cast<size_t>(v.port)].name : "");
  }
}

void BodyWriter::writeOps(StageBody& w) {
  // Which outputs of which ops this stage reads.
  std::vector<char> used(portBase_.back(), 0);  // by port index
  auto use = [&](const ValueRef& r) {
    if (r.kind != ValueRef::Kind::Op) return;
    used[portBase_[static_cast<size_t>(r.index)] + static_cast<size_t>(r.port)] = 1;
  };
  for (size_t i = 0; i < program_.ops.size(); ++i)
    if (program_.ops[i].stage & w.stage)
      for (const auto& in : program_.ops[i].inputs) use(in);
  for (const auto& out : program_.outputs)
    if (outputSlotRow(out.slot).stage == w.stage) use(out.value);
  if (w.stage == kVertexStage)
    for (const auto& v : program_.varyings) use(v);
  std::vector<StageBody::Registration> registered;
  std::vector<char> outputRead;

  for (size_t i = 0; i < program_.ops.size(); ++i) {
    const Op& op = program_.ops[i];
    if (!(op.stage & w.stage)) continue;
    PlanOpContext ctx(*this, w, static_cast<int>(i));
    ctx.outputs.resize(op.outputTypes.size());
    registered.clear();
    w.registered = &registered;
    op.spec->emit(ctx);
    w.registered = nullptr;
    outputRead.assign(op.outputTypes.size(), 0);
    for (size_t p = 0; p < op.outputTypes.size(); ++p) outputRead[p] = used[portBase_[i] + p];
    std::vector<char> needed = neededTemporaries(ctx, outputRead);
    // An output no one reads, or a local left out, may have been the only reader of
    // something the op declared.
    if (!registered.empty() && (std::find(needed.begin(), needed.end(), 0) != needed.end() ||
                                std::find(outputRead.begin(), outputRead.end(), 0) != outputRead.end()))
      forgetUnread(registered, ctx, outputRead, needed);
    const size_t opCallsBefore = w.opCalls.size();
    forKeptValues(ctx, outputRead, needed, [&](const GlslExpr& e) {
      for (uint32_t fn : e.callIds()) {
        const std::pair<int, uint32_t> call{static_cast<int>(i), fn};
        if (std::find(w.opCalls.begin() + static_cast<std::ptrdiff_t>(opCallsBefore), w.opCalls.end(), call) == w.opCalls.end())
          w.opCalls.push_back(call);
      }
    });
    for (size_t t = 0; t < ctx.temps.size(); ++t)
      if (needed[t])
        w.body.declare(static_cast<int>(i), ctx.temps[t].expression.operations(), ctx.temps[t].type, ctx.temps[t].name,
                       ctx.temps[t].expression.text());
    for (size_t p = 0; p < op.outputTypes.size(); ++p) {
      if (!used[portBase_[i] + p]) continue;
      if (ctx.outputs[p].empty())
        throw std::logic_error("node '" + op.spec->type + "' emitted no expression for output '" +
                               op.spec->outputs[p].name + "'");
      if (ctx.outputs[p].isName()) {
        if (w.aliases.empty()) w.aliases.resize(portBase_.back());
        const size_t at = portBase_[i] + p;
        w.aliases[at] = ctx.outputs[p].text();
        std::vector<uint32_t> symbols;
        for (uint32_t symbol : ctx.outputs[p].symbols())
          if (planSymbolKind(symbol) != PlanSymbol::Temporary) symbols.push_back(symbol);
        if (!symbols.empty()) w.aliasSymbols.emplace_back(at, std::move(symbols));
        continue;
      }
      const int at = static_cast<int>(i), cost = ctx.outputs[p].operations();
      if (op.outputTypes.size() > 1)
        w.body.declare(at, cost, op.outputTypes[p], opNames_[i] + "_" + op.spec->outputs[p].name, ctx.outputs[p].text());
      else
        w.body.declare(at, cost, op.outputTypes[p], opNames_[i], ctx.outputs[p].text());
    }
  }
}

GlslExpr BodyWriter::valueExpr(StageBody& w, const ValueRef& r, Type want) {
  GlslExpr e;
  Type have = program_.typeOf(r);
  switch (r.kind) {
    case ValueRef::Kind::Const: return glslLiteral(r.constant().convertedTo(want));
    case ValueRef::Kind::Param: {
      const uint32_t symbol = planSymbol(PlanSymbol::Parameter, static_cast<size_t>(r.index));
      e = GlslExpr::symbol(paramNames_[static_cast<size_t>(r.index)], symbol);
      if (w.parameters.insert(r.index).second) w.noteRegistered(symbol, [&w, i = r.index] { w.parameters.erase(i); });
      break;
    }
    case ValueRef::Kind::Builtin: e = builtinExpr(w, static_cast<Builtin>(r.index)); break;
    case ValueRef::Kind::Op: {
      // Another op's value: what it reads was declared for that op, which keeps it.
      const Op& op = program_.ops[static_cast<size_t>(r.index)];
      e = w.stage == kFragmentStage && !(op.stage & kFragmentStage) ? GlslExpr::name(varyingName(r.index, r.port))
                                                                    : opOutput(w, r.index, r.port);
      break;
    }
    case ValueRef::Kind::None: throw std::logic_error("emit: unset value");
  }
  if (have != want && have == Type::Float) return GlslExpr(typeName(want)) + "(" + e + ")";
  return e;
}

GlslExpr BodyWriter::outputExpr(StageBody& w, OutputSlot slot, GlslExpr fallback) {
  const ProgramOutput* out = program_.output(slot);
  if (!out) return fallback;
  return valueExpr(w, out->value, out->type);
}

GlslExpr BodyWriter::builtinExpr(StageBody& w, Builtin b) {
  bool added = w.builtins.insert(b).second;
  // What the builtin's own expression declares (u_camera_position for the view direction)
  // is read by the builtin's line, not by the op: it goes and stays with the builtin.
  std::vector<StageBody::Registration> inner, *outer = w.registered;
  w.registered = &inner;
  GlslExpr e = namer_(w, b);
  w.registered = outer;
  const uint32_t symbol = planSymbol(PlanSymbol::Builtin, static_cast<size_t>(b));
  e.reading(symbol);
  if (added)
    w.noteRegistered(symbol, [&w, b, inner = std::move(inner)] {
      w.builtins.erase(b);
      for (size_t k = inner.size(); k-- > 0;) inner[k].undo();
    });
  else
    for (auto& r : inner) {
      e.reading(r.symbol);
      w.noteRegistered(r.symbol, std::move(r.undo));
    }
  return e;
}

GlslExpr BodyWriter::opOutput(const StageBody& w, int op, int port) const {
  size_t at = portBase_[static_cast<size_t>(op)] + static_cast<size_t>(port);
  if (at < w.aliases.size() && !w.aliases[at].empty()) {
    GlslExpr e = GlslExpr::name(w.aliases[at]);
    auto read = std::lower_bound(w.aliasSymbols.begin(), w.aliasSymbols.end(), at,
                                 [](const auto& entry, size_t port) { return entry.first < port; });
    if (read != w.aliasSymbols.end() && read->first == at)
      for (uint32_t symbol : read->second) e.reading(symbol);
    return e;
  }
  return GlslExpr::name(tempName(op, port));
}

std::string BodyWriter::tempName(int op, int port) const {
  const Op& o = program_.ops[static_cast<size_t>(op)];
  return o.outputTypes.size() > 1 ? opNames_[static_cast<size_t>(op)] + "_" + o.spec->outputs[static_cast<size_t>(port)].name
                                   : opNames_[static_cast<size_t>(op)];
}

const std::string& BodyWriter::varyingName(int op, int port) const {
  const std::string& name = varyingNames_.at(portBase_[static_cast<size_t>(op)] + static_cast<size_t>(port));
  if (name.empty()) throw std::logic_error("emit: the fragment stage reads a vertex-stage value that is no varying");
  return name;
}

GlslExpr BodyWriter::phaseUniform(StageBody& w, double omega) {
  for (auto& p : phases_)
    if (p.omega == omega) {
      const size_t at = static_cast<size_t>(&p - phases_.data());
      const uint32_t symbol = planSymbol(PlanSymbol::Phase, at);
      if (!(p.stages & w.stage))
        w.noteRegistered(symbol, [this, at, s = w.stage] { phases_[at].stages &= ~s; });
      p.stages |= w.stage;
      return GlslExpr::symbol(p.name, symbol);
    }
  UniformInfo u{std::string(builtinUniformRow(BuiltinUniform::TimePhase).glslName) + std::to_string(phases_.size()),
                Type::Float, -1, BuiltinUniform::TimePhase, w.stage, omega};
  const uint32_t symbol = planSymbol(PlanSymbol::Phase, phases_.size());
  phases_.push_back(u);
  w.noteRegistered(symbol, [this, n = phases_.size()] { popIfLast(phases_, n); });
  return GlslExpr::symbol(u.name, symbol);
}

// One sampler per distinct (source, sampler state): GL 3.3 keeps wrap and filter in the
// texture object (the runtime uses no sampler objects) and sRGB is its internal format,
// so a PNG read two ways is two textures, each with its own unit.
GlslExpr BodyWriter::nodeTexture(StageBody& w, const std::string& source, const SamplerState& sampler) {
  for (auto& t : nodeTextures_)
    if (t.source == source && t.sampler == sampler) {
      const size_t at = static_cast<size_t>(&t - nodeTextures_.data());
      const uint32_t symbol = planSymbol(PlanSymbol::NodeTexture, at);
      if (!(t.stages & w.stage)) w.noteRegistered(symbol, [this, at, s = w.stage] { nodeTextures_[at].stages &= ~s; });
      t.stages |= w.stage;
      return GlslExpr::symbol(t.name, symbol);
    }
  std::string stem = source.rfind(kBuiltinTexturePrefix, 0) == 0 ? source.substr(kBuiltinTexturePrefix.size())
                                                                   : std::filesystem::path(source).stem().string();
  TextureInfo t;
  t.name = "t" + std::to_string(nodeTextures_.size()) + "_" + sanitiseIdentifier(stem);
  t.source = source;
  t.sampler = sampler;
  t.stages = w.stage;
  const uint32_t symbol = planSymbol(PlanSymbol::NodeTexture, nodeTextures_.size());
  nodeTextures_.push_back(t);
  w.noteRegistered(symbol, [this, n = nodeTextures_.size()] { popIfLast(nodeTextures_, n); });
  return GlslExpr::symbol(t.name, symbol);
}

GlslExpr BodyWriter::sceneSampler(StageBody& w, SceneSampler sampler) {
  const uint32_t symbol = planSymbol(PlanSymbol::SceneTexture, static_cast<size_t>(sampler));
  for (auto& t : sceneTextures_)
    if (t.scene == sampler) {
      if (!(t.stages & w.stage))
        w.noteRegistered(symbol, [this, at = &t - sceneTextures_.data(), s = w.stage] {
          sceneTextures_[static_cast<size_t>(at)].stages &= ~s;
        });
      t.stages |= w.stage;
      return GlslExpr::symbol(t.name, symbol);
    }
  const SceneSamplerRow& row = sceneSamplerRow(sampler);
  TextureInfo t;
  t.name = row.glslName;
  t.type = row.type;
  t.scene = sampler;
  t.stages = w.stage;
  sceneTextures_.push_back(t);
  w.noteRegistered(symbol, [this, n = sceneTextures_.size()] { popIfLast(sceneTextures_, n); });
  return GlslExpr::symbol(t.name, symbol);
}

// Taken back, like a declaration, when the op's value holding it is left out.
GlslExpr BodyWriter::fetch(StageBody& w, const GlslExpr& sampler, const GlslExpr& coord) {
  GlslExpr call = "texture(" + sampler + ", " + coord + ")";
  const uint32_t symbol = planSymbol(PlanSymbol::Fetch, w.fetches.size());
  const std::span<const uint32_t> reads = coord.symbols();
  const bool atScreenUv = coord.isName() && std::find(reads.begin(), reads.end(),
                                                      planSymbol(PlanSymbol::Builtin, static_cast<size_t>(Builtin::ScreenUv))) != reads.end();
  w.fetches.push_back({TextureFetch{sampler.text(), coord.text()}, true, atScreenUv});
  w.noteRegistered(symbol, [&w, at = w.fetches.size() - 1] { w.fetches[at].kept = false; });
  return call.reading(symbol);
}

// Counted under the sampler's own symbol (the first it reads): kept while a kept value of
// the op names the sampler.
GlslExpr BodyWriter::handOn(StageBody& w, GlslExpr sampler) {
  ++w.handedOn[sampler.text()];
  w.noteRegistered(sampler.symbols().front(), [&w, name = sampler.text()] { --w.handedOn[name]; });
  return sampler;
}

// One sampler per ocean, cascade and map, named after them ("u_ocean0_slopes2").
GlslExpr BodyWriter::oceanMap(StageBody& w, int spectrumOp, int cascade, int which) {
  auto known = std::find(oceanOps_.begin(), oceanOps_.end(), spectrumOp);
  const int ocean = static_cast<int>(known - oceanOps_.begin());
  const OceanMapRef ref{ocean, cascade, which};
  // Every map reads its ocean: kept while any kept value samples one of its maps.
  const uint32_t oceanSymbol = planSymbol(PlanSymbol::Ocean, static_cast<size_t>(ocean));
  if (known == oceanOps_.end()) {
    // Taken back with the op's maps when no read output needs them (then no ocean is simulated).
    oceanOps_.push_back(spectrumOp);
    w.noteRegistered(oceanSymbol, [this, n = oceanOps_.size()] { popIfLast(oceanOps_, n); });
  }
  for (auto& t : oceanTextures_)
    if (t.ocean == ref) {
      const size_t at = static_cast<size_t>(&t - oceanTextures_.data());
      const uint32_t symbol = planSymbol(PlanSymbol::OceanTexture, at);
      if (!(t.stages & w.stage)) w.noteRegistered(symbol, [this, at, s = w.stage] { oceanTextures_[at].stages &= ~s; });
      t.stages |= w.stage;
      return GlslExpr::symbol(t.name, symbol).reading(oceanSymbol);
    }
  TextureInfo t;
  t.name = "u_ocean" + std::to_string(ocean) + "_" + ocean::kOceanMapNames[which] + std::to_string(cascade);
  t.ocean = ref;
  t.stages = w.stage;
  const uint32_t symbol = planSymbol(PlanSymbol::OceanTexture, oceanTextures_.size());
  oceanTextures_.push_back(t);
  w.noteRegistered(symbol, [this, n = oceanTextures_.size()] { popIfLast(oceanTextures_, n); });
  return GlslExpr::symbol(t.name, symbol).reading(oceanSymbol);
}

std::vector<OceanInfo> BodyWriter::oceans() const {
  std::vector<OceanInfo> out;
  for (int i : oceanOps_) out.push_back({program_.ops[static_cast<size_t>(i)].nodeId, program_.ops[static_cast<size_t>(i)].options()});
  for (const TextureInfo& t : oceanTextures_)
    if (t.ocean->map == ocean::kMomentsMap) out.at(static_cast<size_t>(t.ocean->ocean)).filtered = true;
  return out;
}

std::vector<UniformInfo> BodyWriter::uniforms(const StageBody* vert, const StageBody& frag) const {
  std::vector<UniformInfo> out;
  for (const auto& row : builtinUniformTable()) {
    unsigned stages = (vert && vert->builtinUniforms.count(row.id) ? kVertexStage : 0u) |
                      (frag.builtinUniforms.count(row.id) ? kFragmentStage : 0u);
    if (stages) out.push_back({std::string(row.glslName), row.type, -1, row.id, stages});
  }
  out.insert(out.end(), phases_.begin(), phases_.end());
  for (size_t i = 0; i < program_.parameters.size(); ++i) {
    unsigned stages = (vert && vert->parameters.count(static_cast<int>(i)) ? kVertexStage : 0u) |
                      (frag.parameters.count(static_cast<int>(i)) ? kFragmentStage : 0u);
    if (stages) out.push_back({paramNames_[i], program_.parameters[i].type, static_cast<int>(i), {}, stages});
  }
  return out;
}

std::vector<TextureInfo> BodyWriter::textures() const {
  std::vector<TextureInfo> scene = sceneTextures_;
  std::stable_sort(scene.begin(), scene.end(),
                   [](const TextureInfo& a, const TextureInfo& b) { return sceneSamplerRank(a) < sceneSamplerRank(b); });
  std::vector<TextureInfo> out = nodeTextures_;
  std::vector<TextureInfo> ocean = oceanTextures_;
  std::stable_sort(ocean.begin(), ocean.end(), [](const TextureInfo& a, const TextureInfo& b) {
    return std::tie(a.ocean->ocean, a.ocean->cascade, a.ocean->map) < std::tie(b.ocean->ocean, b.ocean->cascade, b.ocean->map);
  });
  out.insert(out.end(), ocean.begin(), ocean.end());
  out.insert(out.end(), scene.begin(), scene.end());
  for (size_t i = 0; i < out.size(); ++i) out[i].binding = iface::kUniformBlockBinding + 1 + static_cast<int>(i);
  return out;
}

}  // namespace wg
