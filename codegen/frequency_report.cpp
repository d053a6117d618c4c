#include "codegen/frequency_report.h"

#include <set>

#include "codegen/shader_plan.h"

namespace wg {
namespace {

// Per op, the operations of the lines it writes in the fragment stage; `total`: those of
// the whole stage. The planner counted them from the values as it wrote each line
// (PlannedStatement::cost), so nothing here reads the shader's text.
std::vector<int> fragmentCosts(const Program& program, const PlannedStage* frag, int& total) {
  std::vector<int> cost(program.ops.size(), 0);
  total = 0;
  if (!frag) return cost;
  total = frag->locals.cost();
  for (const PlannedStatement& statement : frag->body.statements) {
    total += statement.cost;
    if (statement.op >= 0) cost[static_cast<size_t>(statement.op)] += statement.cost;
  }
  return cost;
}

bool perDrawInFragment(const Program& program, const std::vector<Frequency>& f, const ValueRef& r) {
  return r.kind == ValueRef::Kind::Op && f[static_cast<size_t>(r.index)] == Frequency::PerDraw &&
         (program.ops[static_cast<size_t>(r.index)].stage & kFragmentStage);
}

}  // namespace

FrequencyReport frequencyReport(const Program& program) {
  ShaderPlan plan = planShaders(program, program.file, false);
  FrequencyReport r;
  r.ops = analyseFrequency(program);
  r.fragmentCost = fragmentCosts(program, plan.stage(ShaderStage::Fragment), r.fragmentTotalCost);
  const size_t n = program.ops.size();
  for (size_t i = 0; i < n; ++i) {
    r.counts[static_cast<size_t>(r.ops[i])]++;
    if (perDrawInFragment(program, r.ops, ValueRef::op(static_cast<int>(i), 0))) {
      r.perDrawInFragment++;
      r.perDrawCost += r.fragmentCost[i];
    }
  }
  // Roots: per-draw values read per pixel (by an op that is not per-draw, or an output).
  std::vector<std::set<int>> rootPorts(n);
  for (size_t i = 0; i < n; ++i) {
    if (!(program.ops[i].stage & kFragmentStage) || r.ops[i] <= Frequency::PerDraw) continue;
    for (const auto& in : program.ops[i].inputs)
      if (perDrawInFragment(program, r.ops, in)) rootPorts[static_cast<size_t>(in.index)].insert(in.port);
  }
  for (const auto& out : program.outputs)
    if (outputSlotRow(out.slot).stage == kFragmentStage && perDrawInFragment(program, r.ops, out.value))
      rootPorts[static_cast<size_t>(out.value.index)].insert(out.value.port);
  for (size_t root = 0; root < n; ++root) {
    if (rootPorts[root].empty()) continue;
    PerDrawRoot c;
    c.op = static_cast<int>(root);
    c.ports.assign(rootPorts[root].begin(), rootPorts[root].end());
    // The per-draw ops below the root, walked back in reverse program order.
    std::vector<bool> in(n, false);
    in[root] = true;
    for (size_t i = root + 1; i-- > 0;) {
      if (!in[i]) continue;
      for (const auto& v : program.ops[i].inputs)
        if (perDrawInFragment(program, r.ops, v)) in[static_cast<size_t>(v.index)] = true;
    }
    for (size_t i = 0; i <= root; ++i)
      if (in[i]) {
        c.ops.push_back(static_cast<int>(i));
        c.cost += r.fragmentCost[i];
      }
    if (c.cost > 0) r.roots.push_back(std::move(c));
  }
  return r;
}

std::string formatFrequencyReport(const Program& program, const FrequencyReport& report) {
  auto plural = [](int k, const char* word) { return std::to_string(k) + " " + word + (k == 1 ? "" : "s"); };
  std::string s = program.graphName + ": " + plural(static_cast<int>(program.ops.size()), "op") + " after the passes: ";
  for (size_t f = 0; f < report.counts.size(); ++f)
    s += (f ? ", " : "") + std::to_string(report.counts[f]) + " " + std::string(frequencyName(static_cast<Frequency>(f)));
  s += "\n  per-draw ops computed per pixel: " + std::to_string(report.perDrawInFragment) + ", about " +
       std::to_string(report.perDrawCost) + " of the fragment stage's " +
       plural(report.fragmentTotalCost, "operation") + " per pixel\n";
  if (report.roots.empty()) return s + "  per-draw values computed per pixel: none\n";
  s += "  per-draw values computed per pixel (operations per pixel, estimated):\n";
  for (const auto& c : report.roots) {
    const Op& op = program.ops[static_cast<size_t>(c.op)];
    std::string ports;
    for (int p : c.ports) {
      std::string name = static_cast<size_t>(p) < op.spec->outputs.size() ? op.spec->outputs[static_cast<size_t>(p)].name
                                                                           : "#" + std::to_string(p);
      ports += (ports.empty() ? "" : ", ") + name + " (" + std::string(typeName(op.outputTypes[static_cast<size_t>(p)])) + ")";
    }
    // The graph nodes they came from, each once (an expression's ops share its id).
    std::string from;
    std::set<std::string> named;
    for (int i : c.ops)
      if (const std::string& id = program.ops[static_cast<size_t>(i)].nodeId; named.insert(id).second)
        from += (from.empty() ? "" : ", ") + id;
    s += "    node '" + op.nodeId + "' (" + op.spec->type + ") output " + ports + ": " + plural(c.cost, "operation") +
         " from " + plural(static_cast<int>(c.ops.size()), "op") + " of nodes [" + from + "]\n";
  }
  return s;
}

}  // namespace wg
