#include "codegen/value_facts.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wg {
namespace {

// A bound as the shader sees it: the GLSL literal or the runtime's clamp is the float
// nearest the double (clamping and rounding are both monotonic, so a value clamped in
// double and then uploaded as float still lies within the float-rounded bounds). Float
// denormals may be flushed to zero on the GPU, so a bound inside (-FLT_MIN, FLT_MIN) is
// widened to the nearest value that survives a flush: 0 or -/+FLT_MIN.
double lowerBound(double x) {
  if (!std::isfinite(x)) return x;
  double f = static_cast<double>(static_cast<float>(x));
  double tiny = static_cast<double>(std::numeric_limits<float>::min());
  if (std::abs(f) < tiny) return f > 0 || (f == 0 && x >= 0) ? 0.0 : -tiny;
  return f;
}
double upperBound(double x) {
  if (!std::isfinite(x)) return x;
  double f = static_cast<double>(static_cast<float>(x));
  double tiny = static_cast<double>(std::numeric_limits<float>::min());
  if (std::abs(f) < tiny) return f < 0 || (f == 0 && x <= 0) ? 0.0 : tiny;
  return f;
}

}  // namespace

ValueFact constantFact(const Value& v) {
  ValueFact f;
  if (v.size() < 1) return f;
  f.lo = f.hi = v[0];
  double len2 = 0;
  for (int i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return {};
    f.lo = std::min(f.lo, v[i]);
    f.hi = std::max(f.hi, v[i]);
    len2 += v[i] * v[i];
  }
  f.lo = lowerBound(f.lo);
  f.hi = upperBound(f.hi);
  // Within float rounding of unit length, or exactly zero: re-normalising changes nothing
  // beyond the nodes' 1e-5 tolerances.
  f.normalized = v.size() > 1 && (len2 == 0 || std::abs(std::sqrt(len2) - 1) < 1e-6);
  return f;
}

ValueFacts::ValueFacts(const Program& program) : program_(&program) {
  ops_.resize(program.ops.size());
  for (size_t i = 0; i < program.ops.size(); ++i) {
    const Op& op = program.ops[i];
    ops_[i].assign(op.outputTypes.size(), ValueFact{});
    if (!op.spec->facts) continue;
    std::vector<ValueFact> in;
    for (size_t p = 0; p < op.inputs.size(); ++p)
      in.push_back(op.inputs[p].kind == ValueRef::Kind::None ? ValueFact{} : of(op.inputs[p], op.inputTypes[p]));
    std::vector<ValueFact> out = op.spec->facts(in, *op.parsedOptions);
    for (size_t p = 0; p < out.size() && p < ops_[i].size(); ++p) ops_[i][p] = out[p];
  }
}

ValueFact ValueFacts::of(const ValueRef& ref) const {
  if (!program_) return {};
  switch (ref.kind) {
    case ValueRef::Kind::Const: return constantFact(ref.constant());
    case ValueRef::Kind::Param: {
      const ProgramParameter& p = program_->parameters[static_cast<size_t>(ref.index)];
      ValueFact f;
      if (p.min) f.lo = lowerBound(*p.min);
      if (p.max) f.hi = upperBound(*p.max);
      return f;
    }
    case ValueRef::Kind::Builtin: return builtinFact(static_cast<Builtin>(ref.index));
    case ValueRef::Kind::Op:
      if (ref.index >= 0 && static_cast<size_t>(ref.index) < ops_.size() &&
          static_cast<size_t>(ref.port) < ops_[static_cast<size_t>(ref.index)].size())
        return ops_[static_cast<size_t>(ref.index)][static_cast<size_t>(ref.port)];
      return {};
    case ValueRef::Kind::None: return {};
  }
  return {};
}

ValueFact ValueFacts::of(const ValueRef& ref, Type want) const {
  if (!program_) return {};
  ValueFact f = of(ref);
  if (program_->typeOf(ref) != want) f.normalized = false;  // a float splat
  return f;
}

}  // namespace wg
