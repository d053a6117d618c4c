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
// How a reader reads level 0 of the maps: the vertex stage bicubic (ocean_displacement:
// wg_ocean_map_cubic, where the mesh is finer than a long cascade's texels), the fragment
// stage bilinear (wg_ocean_map).
enum class MapRead { Bilinear, Bicubic };

// GLSL: the weighted sum over the cascades of map `which` at `xz`, as a vec4
// expression.
GlslExpr emitSum(EmitContext& ctx, int oceanPort, int which, const GlslExpr& xz, const std::vector<GlslExpr>& weights,
                 MapRead read);

// Double: what a reader's eval reads from its inputs: the ocean, the still point, the
// scene's time and each cascade's weight at the point's camera distance.
struct EvalPoint {
  int id = 0;
  Value position;
  double time = 0;
  std::vector<double> weights;
};
EvalPoint evalPoint(EvalContext& ctx);  // the fade from the node's options (a double)
EvalPoint evalPoint(EvalContext& ctx, double fadeTiles);
// Double: the weighted sums of both maps at the point (as sum below).
oceanref::MapSample sumAt(const EvalPoint& at, MapRead read);

// Double: per cascade its weight at camera distance d.
std::vector<double> weights(const ocean::OceanSettings& s, double fadeTiles, double d);
// Double: the weighted sums of both maps at (x, z) and time t.
oceanref::MapSample sum(int oceanId, double t, double x, double z, const std::vector<double>& weights, MapRead read);

// --- The filtered reader (ocean_surface's `filter`, nodes/glsl/ocean_displacement.glsl).
// GLSL: the weighted sums over the cascades of the slope map and of the moments map's
// lambda dDx/dz, each cascade read at the level of detail of `footprint` (metres), and the
// slope variance the footprint's mean removes (wg_ocean_lost_variance summed).
struct FilteredExprs {
  GlslExpr slopes;    // vec4
  GlslExpr lDxz;      // float
  GlslExpr variance;  // float
};
FilteredExprs emitFiltered(EmitContext& ctx, int oceanPort, const GlslExpr& xz, const GlslExpr& footprint,
                           const std::vector<GlslExpr>& weights);
// Double: wg_ocean_footprint and wg_ocean_lod.
double footprint(const Value& p, const Value& camera, double pixelAngle);
double lodOf(double footprint, double texelsPerMetre, int levels);
// Double: as emitFiltered; the sums in a MapSample (slopes, and lambda dDx/dz in
// displacement[3], what normalOf and jacobianOf read).
struct FilteredSum {
  oceanref::MapSample sums;
  double variance = 0;
};
FilteredSum sumFiltered(const EvalPoint& at, double footprint);
// Double: wg_ocean_roughness.
double filteredRoughness(double r, double variance);

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

// ocean_surface's filtered reader's cases: a grazing view (the footprint spans the tiles:
// the top level), the camera touching the water (footprint 0: level 0), a calm (no
// variance: the roughness unchanged), a footprint on a level boundary.
std::vector<HardCase> filterHardCases();

// The id an `ocean` input carries (ocean_spectrum's eval puts it in component
// 0).
int oceanId(const Value& v);

}  // namespace wg::nodes::oceanread
