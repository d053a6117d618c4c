// The ocean readers' shared parts (nodes/ocean_readers.h).
#include "core/emit_context.h"
#include "nodes/ocean_readers.h"

#include <algorithm>
#include <bit>
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

GlslExpr emitSum(EmitContext& ctx, int oceanPort, int which, const GlslExpr& xz, const std::vector<GlslExpr>& weights,
                 MapRead read) {
  const auto& s = ctx.oceanSettings(oceanPort);
  GlslExpr sum;
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c) {
    const int n = ocean::cascadeResolution(s.cascades, c);  // each cascade's texels per metre are its own
    GlslExpr map =
        EmitContext::call(read == MapRead::Bicubic ? "wg_ocean_map_cubic" : "wg_ocean_map",
                          {ctx.oceanMap(oceanPort, static_cast<int>(c), which), xz,
                                           ctx.literal(n / s.cascades.tileLengths[c]), std::to_string(n)});
    GlslExpr term = weights[c].empty() ? map : weights[c] + " * " + map;
    sum += (sum.empty() ? "" : " + ") + term;
  }
  return ctx.temporary(Type::Vec4, sum);
}

FilteredExprs emitFiltered(EmitContext& ctx, int oceanPort, const GlslExpr& xz, const GlslExpr& footprint,
                           const std::vector<GlslExpr>& weights) {
  const auto& s = ctx.oceanSettings(oceanPort);
  const size_t count = s.cascades.tileLengths.size();
  std::vector<GlslExpr> k(count), size(count), levels(count), lod(count), slopes(count);
  FilteredExprs out;
  auto read = [&](size_t c, int which) {
    GlslExpr value = EmitContext::call("wg_ocean_map_lod", {ctx.oceanMap(oceanPort, static_cast<int>(c), which), xz, k[c],
                                                           size[c], levels[c], lod[c]});
    // The slopes' levels exist only in a filtered cascade, which the runtimes recognise by a
    // shader's moments map: reading the filtered slopes keeps the moments sampler too (a use
    // that reads the slopes alone declares it unread in the text, and the pyramids are made).
    if (which == ocean::kSlopeMap) {
      // A named value: symbols() is a view into it (a temporary would end before the loop).
      const GlslExpr moments = ctx.oceanMap(oceanPort, static_cast<int>(c), ocean::kMomentsMap);
      for (uint32_t symbol : moments.symbols()) value.reading(symbol);
    }
    return ctx.temporary(Type::Vec4, value);
  };
  auto weighted = [&](size_t c, const GlslExpr& term) {
    return GlslExpr(c == 0 ? "" : " + ") + (weights[c].empty() ? term : weights[c] + " * " + term);
  };
  // The slopes first and the moments after: a use that reads the slopes alone (the `slopes`
  // output) leaves every moments read unread, at the end, where the planner takes it back.
  for (size_t c = 0; c < count; ++c) {
    const int n = ocean::cascadeResolution(s.cascades, c);
    k[c] = ctx.literal(n / s.cascades.tileLengths[c]);
    size[c] = std::to_string(n);
    levels[c] = std::to_string(std::countr_zero(static_cast<unsigned>(n)));
    lod[c] = ctx.temporary(Type::Float, EmitContext::call("wg_ocean_lod", {footprint, k[c], levels[c]}));
    slopes[c] = read(c, ocean::kSlopeMap);
    out.slopes += weighted(c, slopes[c]);
  }
  out.slopes = ctx.temporary(Type::Vec4, out.slopes);
  for (size_t c = 0; c < count; ++c) {
    GlslExpr moments = read(c, ocean::kMomentsMap);
    out.lDxz += weighted(c, moments + ".w");
    out.variance += GlslExpr(c == 0 ? "" : " + ") +
                    EmitContext::call("wg_ocean_lost_variance", {slopes[c], moments, weights[c].empty() ? GlslExpr("1.0") : weights[c]});
  }
  out.lDxz = ctx.temporary(Type::Float, out.lDxz);
  out.variance = ctx.temporary(Type::Float, out.variance);
  return out;
}

double footprint(const Value& p, const Value& camera, double pixelAngle) {
  const double d = distance(p, camera);
  const double cosTheta = d > 0 ? std::abs(p[1] - camera[1]) / d : 0.0;
  return d * pixelAngle / std::max(cosTheta, 1.0 / 1024);
}

double lodOf(double footprint, double texelsPerMetre, int levels) {
  return std::clamp(std::log2(std::max(footprint * texelsPerMetre, 1.0)), 0.0, static_cast<double>(levels));
}

FilteredSum sumFiltered(const EvalPoint& at, double footprintMetres) {
  const ocean::OceanSettings& s = oceanref::settingsOf(at.id);
  FilteredSum out;
  for (size_t c = 0; c < at.weights.size(); ++c) {
    const int n = ocean::cascadeResolution(s.cascades, c);
    const double k = static_cast<float>(n / s.cascades.tileLengths[c]);  // the shader's literal
    const double lod = lodOf(footprintMetres, k, std::countr_zero(static_cast<unsigned>(n)));
    const oceanref::FilteredSample m =
        oceanref::sampleCascadeFiltered(at.id, static_cast<int>(c), at.time, at.position[0], at.position[2], lod);
    const double w = at.weights[c];
    for (int i = 0; i < 4; ++i) out.sums.slopes[i] += w * m.slopes[i];
    out.sums.displacement[3] += w * m.moments[3];
    out.variance += m.moments[0] + m.moments[1] - w * w * (m.slopes[0] * m.slopes[0] + m.slopes[1] * m.slopes[1]);
  }
  return out;
}

double filteredRoughness(double r, double variance) {
  const double rc = std::clamp(r, 0.0, 1.0);
  return std::min(std::sqrt(std::sqrt(rc * rc * rc * rc + std::max(variance, 0.0))), 1.0);
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

oceanref::MapSample sum(int oceanId, double t, double x, double z, const std::vector<double>& weights, MapRead read) {
  oceanref::MapSample total;
  for (size_t c = 0; c < weights.size(); ++c) {
    oceanref::MapSample m = oceanref::sampleCascade(oceanId, static_cast<int>(c), t, x, z, read == MapRead::Bicubic);
    for (int k = 0; k < 4; ++k) {
      total.displacement[k] += weights[c] * m.displacement[k];
      total.slopes[k] += weights[c] * m.slopes[k];
    }
  }
  return total;
}

EvalPoint evalPoint(EvalContext& ctx) { return evalPoint(ctx, ctx.options<double>()); }

EvalPoint evalPoint(EvalContext& ctx, double fadeTiles) {
  EvalPoint at;
  at.id = oceanId(ctx.input("ocean"));
  at.position = ctx.input("position");
  at.time = ctx.environment().time[0];
  at.weights = weights(oceanref::settingsOf(at.id), fadeTiles, distance(at.position, ctx.input("camera")));
  return at;
}

oceanref::MapSample sumAt(const EvalPoint& at, MapRead read) {
  return sum(at.id, at.time, at.position[0], at.position[2], at.weights, read);
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

std::vector<HardCase> filterHardCases() {
  auto withView = [](HardCase c, Value camera, double pixelAngle) {
    c.inputs.push_back({"camera", std::move(camera)});
    c.inputs.push_back({"pixel_angle", Value::scalar(pixelAngle)});
    return c;
  };
  return {withView(hardCase("filtered, a grazing view: the camera at the water's level 5 km away",
                            Value::vector({5000, 0, 30}), smallSea(),
                            "finite; the footprint spans the tiles (the 1 x 1 means): roughness in [0.05, 1]", 0.05, 1,
                            "roughness"),
                   Value::vector({0, 0, 0}), 1e-3),
          withView(hardCase("filtered, the camera touching the water: footprint 0, level 0", Value::vector({3, 0, -7}),
                            smallSea(), "finite: the maps at level 0, the roughness its input or more", 0.05, 1,
                            "roughness"),
                   Value::vector({3, 0, -7}), 1e-3),
          withView(hardCase("filtered, a calm (wind 0): no slope variance", Value::vector({3, 0, -7}),
                            smallSea({{"wind_speed", 0}}), "the roughness unchanged, 0.05", 0.05, 0.05, "roughness"),
                   Value::vector({0, 40, 0}), 1e-3),
          // 64 texels over 8 m: 8 per metre; 8 m away straight down with pixel angle 1/64 the
          // footprint is 1/8 m, one texel: lod exactly 0 for the short cascade, between levels
          // for the long one (64 texels over 50 m).
          withView(hardCase("filtered, a footprint of exactly one texel (a level boundary)", Value::vector({3, 0, -7}),
                            smallSea({{"wind_speed", 20}}), "finite; the roughness above its input", 0.05, 1, "roughness"),
                   Value::vector({3, 8, -7}), 1.0 / 64)};
}

int oceanId(const Value& v) {
  if (v.type != Type::Ocean) throw std::logic_error("an ocean reader's `ocean` input holds no ocean");
  return static_cast<int>(v[0]);
}

}  // namespace wg::nodes::oceanread
