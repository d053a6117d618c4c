#include "accuracy/error_bound.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>

#include "codegen/cpu_backend.h"
#include "nodes/rounded_intermediates.h"

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

// Where in [x - delta, x + delta] the result is sampled: both ends.
constexpr double kSamples[] = {1.0, -1.0};

// Adds, per component, the larger move of the result over the samples of `set`, which
// puts the evaluation at a fraction of its interval (0: where it was).
void addMoves(const std::function<void(double fraction)>& set, const std::array<double, 4>& base, int n,
              std::array<double, 4>& sum, const std::function<Value()>& evaluate) {
  std::array<double, 4> move{};
  for (double fraction : kSamples) {
    set(fraction);
    Value v = evaluate();
    for (int k = 0; k < n; ++k) {
      double d = std::abs(v[k] - base[static_cast<size_t>(k)]);
      // A move into NaN/Inf bounds nothing: the finite checks report those.
      if (std::isfinite(d)) move[static_cast<size_t>(k)] = std::max(move[static_cast<size_t>(k)], d);
    }
  }
  set(0.0);
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
                                       double roundings, const std::map<std::string, std::vector<Value>>* fetches,
                                       bool filterPrecision) {
  std::array<double, 4> sum{};
  if (roundings <= 0) return sum;
  EvalEnvironment e = env;
  std::vector<Value> params = parameters;
  Program varied = program;  // ops' options replaced one intermediate at a time
  std::optional<TextureFetches> texels;
  if (fetches) texels = *fetches;
  FilterNudge nudge;
  auto evaluate = [&] { return evaluateProgram(varied, e, params, texels ? &*texels : nullptr, &nudge).outputs.front(); };
  Value ref = evaluate();
  const int lookups = nudge.count;
  int n = std::min(ref.size(), 4);
  std::array<double, 4> base{};
  for (int k = 0; k < n; ++k) base[static_cast<size_t>(k)] = ref[k];
  auto perturb = [&](Value& v) {
    for (int i = 0; i < v.size(); ++i) {
      double saved = v[i], delta = roundings * kUnitRoundoff * std::abs(saved);
      if (!(delta > 0) || !std::isfinite(delta)) continue;
      addMoves([&](double fraction) { v[i] = saved + fraction * delta; }, base, n, sum, evaluate);
      v[i] = saved;
    }
  };
  for (auto& p : params) perturb(p);
  // Read-back texels are float32 inputs of the shader's arithmetic like the uniforms.
  if (texels)
    for (auto& [source, values] : *texels)
      for (auto& v : values) perturb(v);
  std::vector<BuiltinUniform> seen;
  for (BuiltinUniform u : builtins) {
    if (std::find(seen.begin(), seen.end(), u) != seen.end()) continue;
    seen.push_back(u);
    if (Value* v = builtinValue(e, u)) perturb(*v);
  }
  // The look-ups the reference filters itself, one at a time (the unperturbed
  // evaluation counted them: a nudge changes no look-up before its own).
  for (int k = 0; filterPrecision && k < lookups; ++k)
    addMoves(
        [&](double fraction) {
          nudge.nudged = fraction == 0.0 ? -1 : k;
          nudge.fraction = fraction;
        },
        base, n, sum, evaluate);
  // Intermediates that round on their own (nodes/rounded_intermediates.h), one at a time.
  for (size_t i = 0; i < program.ops.size(); ++i) {
    const Op& op = program.ops[i];
    const nodes::RoundedIntermediates* intermediates = nodes::roundedIntermediates(op.spec->type);
    if (!intermediates || !op.parsedOptions) continue;
    double relative = roundings * kUnitRoundoff;
    std::array<std::vector<std::shared_ptr<const ParsedOptions>>, std::size(kSamples)> variants;
    for (size_t s = 0; s < std::size(kSamples); ++s) variants[s] = (*intermediates)(*op.parsedOptions, kSamples[s] * relative);
    for (size_t j = 0; j < variants[0].size(); ++j)
      addMoves(
          [&](double fraction) {
            const auto* at = std::find(std::begin(kSamples), std::end(kSamples), fraction);
            varied.ops[i].parsedOptions =
                at == std::end(kSamples) ? op.parsedOptions : variants[at - std::begin(kSamples)][j];
          },
          base, n, sum, evaluate);
  }
  return sum;
}

}  // namespace wg::accuracy
