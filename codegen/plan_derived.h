#pragma once
// Inside the planner: which per-draw values of the fragment stage become derived uniforms
// (issue #19). The frequency report's candidates (codegen/frequency_report.h) whose
// estimated cost per pixel is at least kDerivedMinCost and whose ops are all of derivable
// node types (codegen/derived_program.h) are taken: the fragment stage reads
// "u_derived<k>" for each output of the root it read, and no longer computes the ops
// below it that nothing else in the stage reads. The vertex stage is unchanged.
#include <memory>
#include <vector>

#include "codegen/derived_program.h"
#include "codegen/shader_plan.h"

namespace wg {

// A uniform read costs 0 operations (codegen/glsl_cost.h); a single product (1) stays in
// the shader, where it costs what the upload and the read would.
inline constexpr int kDerivedMinCost = 2;

struct DerivedPlan {
  std::vector<std::shared_ptr<const DerivedValue>> values;  // "u_derived<k>" is values[k]
  std::vector<ValueRef> roots;  // per value: the op output of the program it stands for
  std::vector<char> skip;       // per op: the fragment stage no longer computes it
  // The index of the value standing for op output (`op`, `port`), or -1.
  int valueOf(int op, int port) const;
};

// `fragment`: the fragment stage of a plan made from `program` without derived uniforms
// (its lines give the costs). Deterministic: candidates in program order, ports ascending.
DerivedPlan planDerived(const Program& program, const PlannedStage* fragment);

}  // namespace wg
