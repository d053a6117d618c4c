#include "accuracy/error_bound.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "codegen/cpu_backend.h"

namespace wg::accuracy {
namespace {

constexpr double kUnitRoundoff = 0x1p-24;  // float32: half the spacing of [1, 2)

// The environment value a probe uniform carries; null for what carries no float32 rounding
// of its own here (time phases) or is not a plain value (matrices).
Value* builtinValue(EvalEnvironment& env, BuiltinUniform u) {
  const auto& carries = builtinUniformRow(u).carries;
  if (!carries) return nullptr;
  const BuiltinRow& row = builtinRow(*carries);
  if (row.type == Type::Mat3 || row.type == Type::Mat4) return nullptr;
  return &(env.*row.environment);
}

// Adds, per component, the larger move of the result when `x` moves by `delta` either way.
void addMoves(double& x, double delta, const std::array<double, 4>& base, int n, std::array<double, 4>& sum,
              const std::function<Value()>& evaluate) {
  if (!(delta > 0) || !std::isfinite(delta)) return;
  double saved = x;
  std::array<double, 4> move{};
  for (double sign : {1.0, -1.0}) {
    x = saved + sign * delta;
    Value v = evaluate();
    for (int k = 0; k < n; ++k) {
      double d = std::abs(v[k] - base[static_cast<size_t>(k)]);
      // A move into NaN/Inf bounds nothing: the finite checks report those.
      if (std::isfinite(d)) move[static_cast<size_t>(k)] = std::max(move[static_cast<size_t>(k)], d);
    }
  }
  x = saved;
  for (int k = 0; k < n; ++k) sum[static_cast<size_t>(k)] += move[static_cast<size_t>(k)];
}

}  // namespace

ErrorModel programErrorModel(const Program& program) {
  ErrorModel m;
  for (const auto& op : program.ops) {
    m.tolerance = std::max(m.tolerance, op.spec->tolerance);
    m.roundings = std::max(m.roundings, op.spec->conditionRoundings);
  }
  if (program.ops.empty()) m.tolerance = 1e-6;
  return m;
}

std::array<double, 4> conditioningTerm(const Program& program, const EvalEnvironment& env,
                                       const std::vector<Value>& parameters, const std::vector<BuiltinUniform>& builtins,
                                       double roundings) {
  std::array<double, 4> sum{};
  if (roundings <= 0) return sum;
  EvalEnvironment e = env;
  std::vector<Value> params = parameters;
  auto evaluate = [&] { return evaluateProgram(program, e, params).outputs.front(); };
  Value ref = evaluate();
  int n = std::min(ref.size(), 4);
  std::array<double, 4> base{};
  for (int k = 0; k < n; ++k) base[static_cast<size_t>(k)] = ref[k];
  auto perturb = [&](Value& v) {
    for (int i = 0; i < v.size(); ++i) addMoves(v[i], roundings * kUnitRoundoff * std::abs(v[i]), base, n, sum, evaluate);
  };
  for (auto& p : params) perturb(p);
  std::vector<BuiltinUniform> seen;
  for (BuiltinUniform u : builtins) {
    if (std::find(seen.begin(), seen.end(), u) != seen.end()) continue;
    seen.push_back(u);
    if (Value* v = builtinValue(e, u)) perturb(*v);
  }
  return sum;
}

}  // namespace wg::accuracy
