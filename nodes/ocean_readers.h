#pragma once
// What the ocean readers (ocean_displacement, ocean_surface) share: the
// cascades' fade weights and the weighted sums of their maps, in GLSL and in
// double, written once so that the two readers and their references cannot
// drift apart.
#include <string>
#include <vector>

#include "core/emit_context.h"
#include "core/node_spec.h"
#include "nodes/ocean_reference.h"

namespace wg::nodes::oceanread {

// The option both readers take: the fade distance in tiles (0: no fade).
OptionSpec fadeOption();
double parseFade(const OptionReader& o);
// |p - camera|, as GLSL's distance().
double distance(const Value& p, const Value& camera);

// GLSL: per cascade its weight ("" for 1) at camera distance `distance` (an
// expression).
std::vector<GlslExpr> emitWeights(EmitContext& ctx, double fadeTiles, const GlslExpr& distance);
// GLSL: the weighted sum over the cascades of map `which` at `xz`, as a vec4
// expression.
GlslExpr emitSum(EmitContext& ctx, int oceanPort, int which, const GlslExpr& xz, const std::vector<GlslExpr>& weights);

// Double: what a reader's eval reads from its inputs: the ocean, the still point, the
// scene's time and each cascade's weight at the point's camera distance.
struct EvalPoint {
  int id = 0;
  Value position;
  double time = 0;
  std::vector<double> weights;
};
EvalPoint evalPoint(EvalContext& ctx);
// Double: the weighted sums of both maps at the point (as sum below).
oceanref::MapSample sumAt(const EvalPoint& at);

// Double: per cascade its weight at camera distance d.
std::vector<double> weights(const ocean::OceanSettings& s, double fadeTiles, double d);
// Double: the weighted sums of both maps at (x, z) and time t.
oceanref::MapSample sum(int oceanId, double t, double x, double z, const std::vector<double>& weights);

// The normal and J of the summed maps, as wg_ocean_normal and
// wg_ocean_jacobian.
Value normalOf(const oceanref::MapSample& m);
double jacobianOf(const oceanref::MapSample& m);

// The readers' hard cases run on small seas (64^2, tiles of 50 and 8 m: quick
// to simulate and to transform) with `extra` options; a case at `position`
// checks `output` in [lo, hi].
nlohmann::json smallSea(const nlohmann::json& extra = nlohmann::json::object());
HardCase hardCase(std::string name, Value position, nlohmann::json seaOptions, std::string expectation, double lo,
                  double hi, std::string output = "");

// The cases both readers' `normal` outputs share: a flat sea's (straight up) and a storm's
// at a point where the surface folds (J < 0 there at t = 0: the normal faces down).
std::vector<HardCase> normalHardCases();

// The id an `ocean` input carries (ocean_spectrum's eval puts it in component
// 0).
int oceanId(const Value& v);

}  // namespace wg::nodes::oceanread
