#include "core/emit_context.h"
#include "nodes/glsl_call_check.h"

#include <set>
#include <stdexcept>

#include "core/port_typing.h"

namespace wg {
namespace {

// An EmitContext that hands out placeholder names and keeps every expression the node
// writes, so the functions they call (GlslExpr::calls) can be looked up.
class RecordingEmitContext final : public EmitContext {
 public:
  RecordingEmitContext(const NodeSpec& spec, const ParsedOptions& options, const PortTyping& types, bool withFacts)
      : spec_(spec), options_(options), types_(types), withFacts_(withFacts) {}

  GlslExpr input(int port) override { return GlslExpr::name("in" + std::to_string(port)); }
  Type inputType(int port) const override { return types_.inputTypes.at(static_cast<size_t>(port)); }
  Type outputType(int port) const override { return types_.outputTypes.at(static_cast<size_t>(port)); }
  const ParsedOptions& parsedOptions() const override { return options_; }
  void output(int, GlslExpr expression) override { written.push_back(std::move(expression)); }
  GlslExpr builtin(Builtin) override { return GlslExpr::name("builtin"); }
  GlslExpr temporary(Type, GlslExpr expression) override {
    written.push_back(std::move(expression));
    return GlslExpr::name("t" + std::to_string(written.size()));
  }
  unsigned stage() const override { return spec_.stages & kFragmentStage ? kFragmentStage : kVertexStage; }
  GlslExpr timePhase(double) override { return GlslExpr::name("phase"); }
  using EmitContext::texture;
  GlslExpr texture(std::string_view, const SamplerState&) override { return GlslExpr::name("sampler"); }
  GlslExpr sceneTexture(SceneResource) override { return GlslExpr::name("scene_sampler"); }
  GlslExpr oceanMap(int, int, int) override { return GlslExpr::name("ocean_sampler"); }
  const NodeSpec& spec() const override { return spec_; }

  // With facts: distinct constants per port (so two ranges never overlap), unit vectors,
  // the builtins' guarantees and the ports' defaults as constants.
  ValueFact inputFact(int port) const override {
    if (!withFacts_) return {};
    double x = port + 1;
    return {x, x, true};
  }
  ValueFact knownBuiltin(Builtin b) const override { return withFacts_ ? builtinFact(b) : ValueFact{}; }
  std::optional<Value> inputConstant(int port) const override {
    if (!withFacts_) return std::nullopt;
    return spec_.inputs.at(static_cast<size_t>(port)).defaultValue;
  }

  std::vector<GlslExpr> written;

 private:
  const NodeSpec& spec_;
  const ParsedOptions& options_;
  const PortTyping& types_;
  bool withFacts_;
};

// The option sets to emit with: defaults, one change at a time, and the hard cases'.
std::vector<nlohmann::json> optionSets(const NodeSpec& spec) {
  std::vector<nlohmann::json> sets{nlohmann::json::object()};
  for (const auto& o : spec.options) {
    if (o.kind == OptionSpec::Kind::Enum)
      for (const auto& c : o.choices) sets.push_back({{o.name, c}});
    if (o.kind == OptionSpec::Kind::Bool) sets.push_back({{o.name, !o.defaultValue.get<bool>()}});
  }
  for (const auto& hc : spec.hardCases) sets.push_back(hc.options);
  return sets;
}

}  // namespace

void checkGlslCalls(const NodeSpec& spec, const GlslLibrary& library) {
  if (spec.expand) return;  // no GLSL of its own: the nodes it expands into are checked
  bool generic = false;
  for (const auto& p : spec.inputs) generic |= p.kind != PortKind::Fixed;
  std::vector<Type> candidates = generic ? std::vector<Type>{Type::Float, Type::Vec2, Type::Vec3, Type::Vec4}
                                         : std::vector<Type>{Type::Float};
  std::set<std::string> seen;
  for (const auto& given : optionSets(spec)) {
    nlohmann::json complete = completeOptions(spec, given);
    auto options = parseOptions(spec, complete);
    for (Type t : candidates) {
      std::vector<Type> sources;
      for (const auto& p : spec.inputs) sources.push_back(p.kind == PortKind::Fixed ? p.type : t);
      PortTyping types = typePorts(spec, *options, sources, [](int) { return std::string("a probe type"); });
      if (!types.error.empty()) continue;  // the node does not take this type
      for (bool withFacts : {false, true}) {
        RecordingEmitContext ctx(spec, *options, types, withFacts);
        spec.emit(ctx);
        // A called name of the library's form (wg_*) that the library lacks; other names
        // are GLSL's built-in functions, which glslang judges.
        for (const auto& code : ctx.written)
          for (const auto& name : code.calls())
            if (name.rfind("wg_", 0) == 0 && seen.insert(name).second && !library.has(name))
              throw std::logic_error("node spec '" + spec.type + "': emit calls '" + name + "' (options " +
                                     complete.dump() + "), which the GLSL library (nodes/glsl/) does not define");
      }
    }
  }
}

}  // namespace wg
