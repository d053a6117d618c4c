#include "core/emit_context.h"

#include <algorithm>
#include <stdexcept>

#include "core/number_format.h"
#include "core/ocean_settings.h"

namespace wg {
namespace {

template <class T>
void appendEachOnce(std::vector<T>& to, const std::vector<T>& from) {
  for (const T& x : from)
    if (std::find(to.begin(), to.end(), x) == to.end()) to.push_back(x);
}

}  // namespace

GlslExpr GlslExpr::symbol(std::string text, uint32_t symbol, bool isName) {
  GlslExpr e(std::move(text));
  e.name_ = isName;
  e.symbols_.push_back(symbol);
  return e;
}

GlslExpr GlslExpr::name(std::string text) {
  GlslExpr e(std::move(text));
  e.name_ = true;
  return e;
}

GlslExpr& GlslExpr::reading(uint32_t symbol) {
  if (std::find(symbols_.begin(), symbols_.end(), symbol) == symbols_.end()) symbols_.push_back(symbol);
  return *this;
}

// Text appended to nothing keeps what it was (a name stays a name); anything longer than
// one piece is no name.
GlslExpr& GlslExpr::operator+=(const GlslExpr& b) {
  if (text_.empty()) {
    name_ = b.name_;
  } else if (!b.text_.empty()) {
    name_ = false;
  }
  text_ += b.text_;
  appendEachOnce(symbols_, b.symbols_);
  appendEachOnce(calls_, b.calls_);
  return *this;
}

GlslExpr& GlslExpr::operator+=(std::string_view b) {
  if (!b.empty()) name_ = false;
  text_ += b;
  return *this;
}

int EmitContext::inputIndex(std::string_view port) const {
  int i = spec().inputIndex(port);
  if (i < 0) throw std::logic_error("node '" + spec().type + "' has no input '" + std::string(port) + "'");
  return i;
}

GlslExpr EmitContext::input(std::string_view port) { return input(inputIndex(port)); }

GlslExpr EmitContext::sceneTexture(std::string_view resource) {
  auto r = parseSceneResource(resource);
  if (!r) throw std::logic_error("node '" + spec().type + "' samples unknown scene resource '" + std::string(resource) + "'");
  return sceneTexture(*r);
}

GlslExpr EmitContext::sampleTexture(std::string_view option, const SamplerState& sampler, const GlslExpr& coord) {
  return "texture(" + texture(option, sampler) + ", " + coord + ")";
}

GlslExpr EmitContext::sampleScene(SceneResource resource, const GlslExpr& coord) {
  return "texture(" + sceneTexture(resource) + ", " + coord + ")";
}

GlslExpr EmitContext::sampleScene(std::string_view resource, const GlslExpr& coord) {
  auto r = parseSceneResource(resource);
  if (!r) throw std::logic_error("node '" + spec().type + "' samples unknown scene resource '" + std::string(resource) + "'");
  return sampleScene(*r, coord);
}

ValueFact EmitContext::inputFact(int) const { return {}; }
const ocean::OceanSettings& EmitContext::oceanSettings(int) const {
  static const ocean::OceanSettings defaults;
  return defaults;
}
GlslExpr EmitContext::oceanMap(int, int, int) {
  throw std::logic_error("node '" + spec().type + "' reads an ocean map where no planner gives one");
}
ValueFact EmitContext::knownBuiltin(Builtin) const { return {}; }
std::optional<Value> EmitContext::inputConstant(int) const { return std::nullopt; }
ValueFact EmitContext::inputFact(std::string_view port) const { return inputFact(inputIndex(port)); }

GlslExpr EmitContext::literal(double x) const { return formatGlslFloat(x); }

GlslExpr EmitContext::literal(const Value& v) const {
  if (v.size() == 1) return formatGlslFloat(v[0]);
  std::string s(typeName(v.type));
  s += '(';
  for (int i = 0; i < v.size(); ++i) {
    if (i) s += ", ";
    s += formatGlslFloat(v[i]);
  }
  return s + ')';
}

GlslExpr EmitContext::call(std::string_view fn, std::initializer_list<GlslExpr> args) {
  GlslExpr e(fn);
  e += '(';
  bool first = true;
  for (const auto& a : args) {
    if (!first) e += ", ";
    e += a;
    first = false;
  }
  e += ')';
  if (std::find(e.calls_.begin(), e.calls_.end(), fn) == e.calls_.end()) e.calls_.emplace_back(fn);
  return e;
}

}  // namespace wg
