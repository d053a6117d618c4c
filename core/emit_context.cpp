#include "core/emit_context.h"

#include <algorithm>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

#include "core/number_format.h"
#include "core/ocean_settings.h"

namespace wg {
namespace {

// The names of the functions called through EmitContext::call, one id each for the whole
// process (a few hundred names at most: the library's and GLSL's built-in functions).
struct CalledNames {
  std::mutex mutex;
  std::deque<std::string> names;  // by id; a deque keeps each name where it is
  std::deque<int> costs;          // by id: what one call costs (glslCallCost)
  std::unordered_map<std::string_view, uint32_t> ids;
};

CalledNames& calledNames() {
  static CalledNames names;
  return names;
}

struct CalledName {
  uint32_t id;
  int cost;
};

// The name's id, and what a call of it costs (computed once per name, outside the lock: a
// library function's cost comes from the library).
CalledName calledName(std::string_view fn) {
  CalledNames& c = calledNames();
  {
    std::lock_guard<std::mutex> lock(c.mutex);
    if (auto it = c.ids.find(fn); it != c.ids.end()) return {it->second, c.costs[it->second]};
  }
  const int cost = glslCallCost(fn);
  std::lock_guard<std::mutex> lock(c.mutex);
  if (auto it = c.ids.find(fn); it != c.ids.end()) return {it->second, c.costs[it->second]};
  const uint32_t id = static_cast<uint32_t>(c.names.size());
  c.ids.emplace(c.names.emplace_back(fn), id);
  c.costs.push_back(cost);
  return {id, cost};
}

// A call written inside a piece (no EmitContext::call: a GLSL built-in such as texture()).
int pieceCallCost(std::string_view name, const void*) { return glslCallCost(name); }

}  // namespace

bool GlslExprIds::contains(uint32_t id) const {
  for (uint32_t x : view())
    if (x == id) return true;
  return false;
}

void GlslExprIds::add(uint32_t id) {
  if (contains(id)) return;
  if (heap_.empty() && size_ < kInline) {
    inline_[size_++] = id;
    return;
  }
  if (heap_.empty()) heap_.assign(inline_, inline_ + size_);
  heap_.push_back(id);
  ++size_;
}

const std::string& GlslExpr::callName(uint32_t id) {
  CalledNames& c = calledNames();
  std::lock_guard<std::mutex> lock(c.mutex);
  return c.names.at(id);
}

std::vector<std::string> GlslExpr::calls() const {
  std::vector<std::string> out;
  for (uint32_t id : callIds()) out.push_back(callName(id));
  return out;
}

void GlslExpr::countPiece(std::string_view piece) { operations_ += countGlslOperations(piece, scan_, pieceCallCost, nullptr); }

// A name is an operand whose text is never read: renaming it changes no count.
GlslExpr GlslExpr::symbol(std::string text, uint32_t symbol, bool isName) {
  GlslExpr e;
  e.text_ = std::move(text);
  e.name_ = isName;
  e.scan_.started = e.scan_.afterOperand = true;
  e.symbols_.add(symbol);
  return e;
}

GlslExpr GlslExpr::name(std::string text) {
  GlslExpr e;
  e.text_ = std::move(text);
  e.name_ = true;
  e.scan_.started = e.scan_.afterOperand = true;
  return e;
}

GlslExpr& GlslExpr::reading(uint32_t symbol) {
  symbols_.add(symbol);
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
  operations_ += b.operations_ + joinGlslOperations(scan_, b.scan_);
  symbols_.addAll(b.symbols_);
  calls_.addAll(b.calls_);
  return *this;
}

GlslExpr& GlslExpr::operator+=(std::string_view b) {
  if (!b.empty()) name_ = false;
  text_ += b;
  countPiece(b);
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

// What the callee costs plus what its arguments cost: each argument follows "(" or ", ",
// so nothing at a seam is an operation.
GlslExpr EmitContext::call(std::string_view fn, std::initializer_list<GlslExpr> args) {
  size_t length = fn.size() + 2;
  for (const auto& a : args) length += a.text_.size() + 2;
  const CalledName callee = calledName(fn);
  GlslExpr e;
  e.text_.reserve(length);
  e.text_ = fn;
  e.text_ += '(';
  e.operations_ = callee.cost;
  bool first = true;
  for (const auto& a : args) {
    if (!first) e.text_ += ", ";
    e.text_ += a.text_;
    e.operations_ += a.operations_;
    e.symbols_.addAll(a.symbols_);
    e.calls_.addAll(a.calls_);
    first = false;
  }
  e.text_ += ')';
  e.scan_.started = e.scan_.afterOperand = true;
  e.calls_.add(callee.id);
  return e;
}

}  // namespace wg
