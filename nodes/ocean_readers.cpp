// The ocean readers' shared parts (nodes/ocean_readers.h).
#include "core/emit_context.h"
#include "nodes/ocean_readers.h"

#include <cmath>
#include <stdexcept>

#include "core/ocean_settings.h"
#include "nodes/eval_math.h"
#include "nodes/port_builders.h"
#include "nodes/waves_common.h"

namespace wg::nodes::oceanread {

OptionSpec fadeOption() {
  return ports::number("fade_tiles", 12, 0, 1000,
                       "each cascade fades out between this many and twice as many of its tile "
                       "lengths from the camera "
                       "(a distant mesh or pixel cannot carry its short waves); 0: no fade");
}

double parseFade(const OptionReader& o) { return o.number("fade_tiles"); }

double distance(const Value& p, const Value& camera) {
  double dx = p[0] - camera[0], dy = p[1] - camera[1], dz = p[2] - camera[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

std::vector<GlslExpr> emitWeights(EmitContext& ctx, double fadeTiles, const GlslExpr& distance) {
  const auto& s = ctx.oceanSettings(ctx.inputIndex("ocean"));
  std::vector<GlslExpr> out;
  for (double l : s.cascades.tileLengths)
    out.push_back(fadeTiles > 0 ? ctx.temporary(Type::Float, EmitContext::call("wg_ocean_fade",
                                                                               {distance, ctx.literal(fadeTiles * l)}))
                                : "");
  return out;
}

GlslExpr emitSum(EmitContext& ctx, int oceanPort, int which, const GlslExpr& xz, const std::vector<GlslExpr>& weights) {
  const auto& s = ctx.oceanSettings(oceanPort);
  GlslExpr sum;
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c) {
    const int n = ocean::cascadeResolution(s.cascades, c);  // each cascade's texels per metre are its own
    GlslExpr map =
        EmitContext::call("wg_ocean_map", {ctx.oceanMap(oceanPort, static_cast<int>(c), which), xz,
                                           ctx.literal(n / s.cascades.tileLengths[c]), std::to_string(n)});
    GlslExpr term = weights[c].empty() ? map : weights[c] + " * " + map;
    sum += (sum.empty() ? "" : " + ") + term;
  }
  return ctx.temporary(Type::Vec4, sum);
}

std::vector<double> weights(const ocean::OceanSettings& s, double fadeTiles, double d) {
  std::vector<double> out;
  for (double l : s.cascades.tileLengths)
    if (fadeTiles > 0) {
      // The shader's literal, rounded to float.
      double start = static_cast<float>(fadeTiles * l);
      out.push_back(1.0 - glsl::safeSmoothstep(start, 2.0 * start, d));
    } else {
      out.push_back(1.0);
    }
  return out;
}

oceanref::MapSample sum(int oceanId, double t, double x, double z, const std::vector<double>& weights) {
  oceanref::MapSample total;
  for (size_t c = 0; c < weights.size(); ++c) {
    oceanref::MapSample m = oceanref::sampleCascade(oceanId, static_cast<int>(c), t, x, z);
    for (int k = 0; k < 4; ++k) {
      total.displacement[k] += weights[c] * m.displacement[k];
      total.slopes[k] += weights[c] * m.slopes[k];
    }
  }
  return total;
}

EvalPoint evalPoint(EvalContext& ctx) {
  EvalPoint at;
  at.id = oceanId(ctx.input("ocean"));
  at.position = ctx.input("position");
  at.time = ctx.environment().time[0];
  at.weights = weights(oceanref::settingsOf(at.id), ctx.options<double>(), distance(at.position, ctx.input("camera")));
  return at;
}

oceanref::MapSample sumAt(const EvalPoint& at) {
  return sum(at.id, at.time, at.position[0], at.position[2], at.weights);
}

Value normalOf(const oceanref::MapSample& m) {
  const auto& s = m.slopes;
  const double lDxz = m.displacement[3];
  const double jx = 1.0 + s[2], jz = 1.0 + s[3];
  waves::D3 n{s[1] * lDxz - jz * s[0], jx * jz - lDxz * lDxz, lDxz * s[0] - s[1] * jx};
  return waves::value(waves::unitOr(n, {0, 1, 0}));
}

double jacobianOf(const oceanref::MapSample& m) {
  return (1.0 + m.slopes[2]) * (1.0 + m.slopes[3]) - m.displacement[3] * m.displacement[3];
}

nlohmann::json smallSea(const nlohmann::json& extra) {
  nlohmann::json o = {{"fft_size", 64}, {"tile_lengths", {50, 8}}};
  for (auto it = extra.begin(); it != extra.end(); ++it) o[it.key()] = it.value();
  return o;
}

HardCase hardCase(std::string name, Value position, nlohmann::json seaOptions, std::string expectation, double lo,
                  double hi, std::string output) {
  HardCase c;
  c.name = std::move(name);
  c.inputs = {{"position", position}};
  c.expectation = std::move(expectation);
  c.lo = lo;
  c.hi = hi;
  c.output = std::move(output);
  c.oceanOptions = std::move(seaOptions);
  return c;
}

std::vector<HardCase> normalHardCases() {
  return {hardCase("a calm (wind 0): the normal of a flat sea", Value::vector({3, 0, -7}), smallSea({{"wind_speed", 0}}),
                   "straight up", 0, 1, "normal"),
          hardCase("a storm at 40 m/s with choppiness 4, where the surface folds", Value::vector({26, 0, 24.5}),
                   smallSea({{"wind_speed", 40}, {"choppiness", 4}, {"fetch", 1000}}),
                   "finite; the normal faces down where J < 0", -1, 1, "normal")};
}

int oceanId(const Value& v) {
  if (v.type != Type::Ocean) throw std::logic_error("an ocean reader's `ocean` input holds no ocean");
  return static_cast<int>(v[0]);
}

}  // namespace wg::nodes::oceanread
