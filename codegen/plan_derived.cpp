#include "codegen/plan_derived.h"

#include <stdexcept>

#include "codegen/derived_vocabulary.h"
#include "codegen/frequency_report.h"

namespace wg {

int DerivedPlan::valueOf(int op, int port) const {
  for (size_t k = 0; k < roots.size(); ++k)
    if (roots[k].index == op && roots[k].port == port) return static_cast<int>(k);
  return -1;
}

DerivedPlan planDerived(const Program& program, const PlannedStage* fragment) {
  const size_t n = program.ops.size();
  DerivedPlan out;
  out.skip.assign(n, 0);
  if (!fragment) return out;
  const FrequencyReport report = frequencyReportOf(program, fragment);
  std::vector<char> inCone(n, 0);
  for (const DerivedCandidate& c : report.candidates) {
    if (c.cost < kDerivedMinCost) continue;
    std::vector<DerivedValue> values;
    bool derivable = true;
    for (int port : c.ports) {
      DerivedValue d;
      try {
        d = extractDerived(program, c.op, port);
      } catch (const std::logic_error&) {
        derivable = false;  // a cone the analysis cannot take out whole stays in the shader
        break;
      }
      for (const Op& op : d.program.ops) derivable = derivable && isDerivedNodeType(op.spec->type);
      values.push_back(std::move(d));
    }
    if (!derivable) continue;
    for (size_t i = 0; i < c.ports.size(); ++i) {
      out.values.push_back(std::make_shared<const DerivedValue>(std::move(values[i])));
      out.roots.push_back(ValueRef::op(c.op, c.ports[i]));
    }
    for (int op : c.ops) inCone[static_cast<size_t>(op)] = 1;
  }
  // A cone op stays when a fragment op that stays (or a fragment output) reads it other
  // than through a taken root: candidates may share ops. Inputs come before their
  // readers, so one backward walk sees every reader first.
  std::vector<char> needed(n, 0);
  auto need = [&](const ValueRef& r) {
    if (r.kind == ValueRef::Kind::Op && out.valueOf(r.index, r.port) < 0) needed[static_cast<size_t>(r.index)] = 1;
  };
  for (const auto& o : program.outputs)
    if (outputSlotRow(o.slot).stage == kFragmentStage) need(o.value);
  for (size_t i = n; i-- > 0;) {
    const Op& op = program.ops[i];
    if (!(op.stage & kFragmentStage) || (inCone[i] && !needed[i])) continue;
    for (const auto& in : op.inputs) need(in);
  }
  for (size_t i = 0; i < n; ++i) out.skip[i] = inCone[i] && !needed[i];
  return out;
}

}  // namespace wg
