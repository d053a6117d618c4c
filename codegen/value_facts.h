#pragma once
// Value facts: what the compiler can prove about every value of a Program for every input
// the shader can receive, computed once before emission. Emitters query them through
// EmitContext::inputFact to choose cheaper library variants (native pow, no
// re-normalisation, no empty-range select) where a guard is provably dead.
//
// Sources, each a guarantee of the runtime contract (docs/architecture.md, "Value facts"):
// - constants: their exact range; a vector constant of length 1 or 0 is `normalized`;
// - parameters with min/max that stay uniforms: every client clamps the uniform into
//   [min, max] on upload (runtime Renderer::setParameter, clients/three setParameter;
//   the manifest's min/max say so), and defaults are checked against them at load;
// - builtins: normal and view_direction are safe-normalised by the emitted shader, the
//   runtime normalises sun_direction, screen_uv and frag_depth lie in [0, 1];
// - op outputs: NodeSpec::facts, given the facts of the op's inputs.
// Probe shaders (EmitMode::Probe) take builtins and parameters from arbitrary cases, so
// they are emitted without facts.
#include <vector>

#include "core/node_spec.h"
#include "core/program.h"

namespace wg {

// The fact of a constant: its component range; normalized when its length is 0 or 1.
ValueFact constantFact(const Value& v);

class ValueFacts {
 public:
  ValueFacts() = default;  // knows nothing
  explicit ValueFacts(const Program& program);
  // The fact of `ref` read as a `want`-typed value (a float splat to a vector keeps its
  // range but is not normalized).
  ValueFact of(const ValueRef& ref, Type want) const;
  ValueFact of(const ValueRef& ref) const;

 private:
  const Program* program_ = nullptr;
  std::vector<std::vector<ValueFact>> ops_;  // per op, per output
};

}  // namespace wg
