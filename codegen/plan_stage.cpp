// The parts of a plan around the written bodies: a planned stage from a body, which
// uniforms, samplers and library items each stage declares, the scene resources, and the
// names every plan shares.
#include <algorithm>

#include "codegen/plan_body.h"
#include "nodes/glsl_library.h"

namespace wg {

std::vector<const GlslItem*> libraryFor(const std::vector<std::string>& called) {
  return GlslLibrary::builtin().itemsNamed(called);
}

// The library items are those the kept values call (StageBody::opCalls) and those the
// locals call: known from the values, not read from the text.
PlannedStage plannedStage(ShaderStage stage, StageBody&& w, StageLocals locals) {
  PlannedStage s;
  std::vector<std::string> called = std::move(locals.calls);
  std::vector<uint32_t> seen;
  for (const auto& [op, fn] : w.opCalls) {
    if (std::find(seen.begin(), seen.end(), fn) != seen.end()) continue;
    seen.push_back(fn);
    called.push_back(GlslExpr::callName(fn));
    s.opCalls.emplace_back(op, called.back());
  }
  s.stage = stage;
  s.locals = std::move(locals.lines);
  s.body = std::move(w.body);
  // Written by appending, the body may hold up to twice its size; the plan keeps it until
  // the manifest is built, alongside every target's shader text (the compile's peak heap).
  s.body.shrinkToFit();
  s.builtins = std::move(w.builtins);
  for (auto& f : w.fetches)
    if (f.kept) s.fetches.push_back(std::move(f.fetch));
  for (const auto& [sampler, times] : w.handedOn)
    if (times > 0) s.handedOn.insert(sampler);
  s.library = libraryFor(called);
  return s;
}

void addOwnGlsl(const Program& program, PlannedStage& s) {
  int last = -1;
  for (const PlannedStatement& statement : s.body.statements) {
    const int op = statement.op;
    if (op < 0 || op == last) continue;
    last = op;
    const auto& code = program.ops[static_cast<size_t>(op)].spec->ownGlsl;
    if (!code || std::find(s.ownGlsl.begin(), s.ownGlsl.end(), code) != s.ownGlsl.end()) continue;
    s.ownGlsl.push_back(code);
    s.ownGlslOp.push_back(op);
  }
}

std::vector<std::string> functionsOf(const std::vector<PlannedStage>& stages) {
  std::set<std::string> called;
  for (const auto& s : stages)
    for (const GlslItem* item : s.library) called.insert(item->name);
  std::vector<std::string> out;
  for (const auto& item : GlslLibrary::builtin().items())
    if (called.count(item.name) && std::find(out.begin(), out.end(), item.name) == out.end()) out.push_back(item.name);
  return out;
}

std::vector<size_t> uniformsWhere(const ShaderPlan& plan, const std::function<bool(const UniformInfo&)>& wanted) {
  std::vector<size_t> out;
  for (size_t i = 0; i < plan.uniforms.size(); ++i)
    if (wanted(plan.uniforms[i])) out.push_back(i);
  return out;
}

std::vector<size_t> texturesIn(const ShaderPlan& plan, unsigned bit) {
  std::vector<size_t> out;
  for (size_t i = 0; i < plan.textures.size(); ++i)
    if (plan.textures[i].stages & bit) out.push_back(i);
  return out;
}

void planResources(const Program& program, ShaderPlan& plan) {
  if (!plan.oceans.empty()) plan.passes.push_back(RenderPass::OceanSimulation);
  for (SceneResource r : program.sceneResources()) {
    plan.resources.push_back(r);
    plan.passes.push_back(sceneResourceRow(r).pass);
  }
  plan.passes.push_back(RenderPass::WaterSurface);
}

const PlannedStage* ShaderPlan::stage(ShaderStage s) const {
  for (const auto& st : stages)
    if (st.stage == s) return &st;
  return nullptr;
}

bool tessellates(Target target, bool allowed) { return allowed && target != Target::Es300; }

std::string sanitiseIdentifier(std::string_view id) {
  std::string out;
  for (char c : id) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    char ch = ok ? c : '_';
    if (ch == '_' && (out.empty() || out.back() == '_')) continue;
    out += ch;
    if (out.size() >= 24) break;
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "x" : out;
}

}  // namespace wg
