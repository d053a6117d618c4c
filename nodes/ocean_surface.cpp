// ocean_surface: the spectral ocean's surface detail for the fragment stage:
// the normal of the displaced surface, the slopes and the Jacobian J (where J <
// 0 the surface folds: whitecaps), read per pixel at the still point
// ocean_displacement passes on; filtered to the pixel's footprint on the water
// (the maps' mip pyramids), the slope variance the filter removes carried into
// the roughness it outputs.
#include <algorithm>

#include "core/emit_context.h"
#include "core/ocean_settings.h"
#include "nodes/node_library.h"
#include "nodes/ocean_readers.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

struct OceanSurfaceOptions {
  double fadeTiles = 12;
  bool filter = true;
};

OceanSurfaceOptions parseOceanSurfaceOptions(const OptionReader& o) { return {oceanread::parseFade(o), o.flag("filter")}; }

}  // namespace

NodeSpec oceanSurfaceNode() {
  NodeSpec s;
  s.type = "ocean_surface";
  s.family = "waves";
  s.summary =
      "The spectral ocean's normal, slopes and Jacobian at a still-water point, per pixel: the surface detail a "
      "vertex grid cannot carry, and where the surface folds. Filtered (the default) to the pixel's footprint "
      "on the water, with the slope variance the filter averages away as an output for the specular lobe "
      "(ggx_specular's slope_variance), so that waves far below a pixel shade as a spread of facets instead of a "
      "mask of sub-pixel glints.";
  s.formula =
      "w_c as ocean_displacement. Unfiltered: (lDx, h, lDz, lDxz) and (hx, hz, lDxx, lDzz) = sum over c of "
      "w_c map_c(p.xz), roughness_out = roughness. Filtered: footprint F = |p - camera| pixel_angle / "
      "max(cos theta, 1/1024) (theta the view's angle from the vertical); per cascade lod_c = clamp(log2(max(F "
      "N_c / L_c, 1)), 0, log2 N_c), S_c and M_c the slope and moments pyramids (2x2 box means; moments (hx^2, "
      "hz^2, hx hz, lDxz)) read trilinearly at lod_c; slopes = sum w_c S_c, lDxz = sum w_c M_c.w; variance V = "
      "sum (M_c.x + M_c.y - w_c^2 (S_c.x^2 + S_c.y^2)); variance = max(V, 0); roughness_out = (clamp(r, 0, 1)^4 + "
      "max(V, 0))^(1/4), at most 1. normal = cross(dP/dz, dP/dx) made unit (wg_ocean_normal); jacobian = (1 + lDxx)(1 + lDzz) - "
      "lDxz^2.";
  s.source =
      "Tessendorf, Simulating Ocean Water (2001); variance into roughness: Olano and Baker, LEAN Mapping (2010), a "
      "Beckmann lobe of alpha has slope variance alpha^2/2 per axis, as Tokuyoshi and Kaplanyan, Improved "
      "Geometric Specular Antialiasing (2019) apply to GGX";
  s.cost = "unfiltered: per cascade 8 texel fetches and ~20 ALU; filtered: per cascade 16 texel fetches per map "
           "(slopes and moments: 32) and ~60 ALU; the fade ~8 ALU";
  s.inputs = {ports::fixed("ocean", Type::Ocean, "the sea, from an ocean_spectrum node"),
              ports::fixed("position", Type::Vec3,
                           "the still water's point: ocean_displacement's `undisplaced` output (the fragment's world "
                           "position is the displaced one)"),
              ports::fromBuiltin("camera", Type::Vec3, Builtin::CameraPosition, "where distances are measured from"),
              ports::fromBuiltin("pixel_angle", Type::Float, Builtin::PixelAngle,
                                 "the angle one pixel subtends (radians): with the distance, the footprint the filter "
                                 "averages over"),
              ports::fixed("roughness", Type::Float, Value::scalar(0.05),
                           "the surface's own perceptual roughness (ggx_specular's), before the filter adds to it")};
  s.outputs = {ports::fixed("normal", Type::Vec3, "unit normal of the displaced surface (down where it folds)"),
               ports::fixed("slopes", Type::Vec2, "dh/dx and dh/dz of the height at the still point (filtered: their mean over the footprint)"),
               ports::fixed("jacobian", Type::Float,
                            "J of the horizontal displacement: 1 on still water, < 0 where it folds"),
               ports::fixed("roughness", Type::Float,
                            "the input roughness widened by the slope variance the filter removed, (r^4 + V)^(1/4) "
                            "(the input itself when unfiltered): for a node that takes a roughness alone. A single "
                            "widened GGX lobe does not keep the sun's energy (0.4 to 0.7 of it at distance): "
                            "ggx_specular takes `variance` instead"),
               ports::fixed("variance", Type::Float,
                            "the slope variance the filter removed, V (0 when unfiltered): feed it to ggx_specular's "
                            "slope_variance, with the surface's own roughness as its roughness")};
  s.options = {oceanread::fadeOption(),
               ports::flag("filter", true,
                           "read the maps averaged over the pixel's footprint (mip pyramids, trilinear) and add the "
                           "slope variance they lose to the roughness; false: point-sample level 0 as a probe would, "
                           "where waves below a pixel alias into glints")};
  s.parseOptions = optionParser(parseOceanSurfaceOptions);
  s.isSource = true;
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{ValueFact::unitVector(), {}, {}, {}, {}};
  };
  s.emit = [](EmitContext& ctx) {
    const int ocean = ctx.inputIndex("ocean");
    const auto o = ctx.options<OceanSurfaceOptions>();
    GlslExpr p = ctx.temporary(Type::Vec3, ctx.input("position"));
    std::vector<GlslExpr> w =
        oceanread::emitWeights(ctx, o.fadeTiles, o.fadeTiles > 0 ? "distance(" + p + ", " + ctx.input("camera") + ")" : "");
    GlslExpr xz = p + ".xz";
    if (!o.filter) {
      GlslExpr d = oceanread::emitSum(ctx, ocean, ocean::kDisplacementMap, xz, w, oceanread::MapRead::Bilinear);
      GlslExpr slopes = oceanread::emitSum(ctx, ocean, ocean::kSlopeMap, xz, w, oceanread::MapRead::Bilinear);
      ctx.output(0, EmitContext::call("wg_ocean_normal", {slopes, d + ".w"}));
      ctx.output(1, slopes + ".xy");
      ctx.output(2, EmitContext::call("wg_ocean_jacobian", {slopes, d + ".w"}));
      ctx.output(3, ctx.input("roughness"));
      ctx.output(4, "0.0");
      return;
    }
    GlslExpr footprint = ctx.temporary(
        Type::Float, EmitContext::call("wg_ocean_footprint", {p, ctx.input("camera"), ctx.input("pixel_angle")}));
    oceanread::FilteredExprs f = oceanread::emitFiltered(ctx, ocean, xz, footprint, w);
    ctx.output(0, EmitContext::call("wg_ocean_normal", {f.slopes, f.lDxz}));
    ctx.output(1, f.slopes + ".xy");
    ctx.output(2, EmitContext::call("wg_ocean_jacobian", {f.slopes, f.lDxz}));
    ctx.output(3, EmitContext::call("wg_ocean_roughness", {ctx.input("roughness"), f.variance}));
    ctx.output(4, EmitContext::call("max", {f.variance, "0.0"}));
  };
  s.eval = [](EvalContext& ctx) {
    const auto o = ctx.options<OceanSurfaceOptions>();
    const oceanread::EvalPoint at = oceanread::evalPoint(ctx, o.fadeTiles);
    oceanref::MapSample m;
    double roughness = ctx.scalar("roughness"), variance = 0;
    if (o.filter) {
      const double pixelAngle = ctx.scalar("pixel_angle");
      oceanread::FilteredSum f = oceanread::sumFiltered(at, oceanread::footprint(at.position, ctx.input("camera"), pixelAngle));
      m = f.sums;
      roughness = oceanread::filteredRoughness(roughness, f.variance);
      variance = std::max(f.variance, 0.0);
    } else {
      m = oceanread::sumAt(at, oceanread::MapRead::Bilinear);
    }
    ctx.output(0, oceanread::normalOf(m));
    ctx.output(1, Value::vector({m.slopes[0], m.slopes[1]}));
    ctx.output(2, Value::scalar(oceanread::jacobianOf(m)));
    ctx.output(3, Value::scalar(roughness));
    ctx.output(4, Value::scalar(variance));
  };
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy =
      "grows with the texel coordinate x N / L times the fields' gradients, and with the normal's turning where the "
      "surface folds";
  s.hardCases = {
      oceanread::hardCase("a calm (wind 0): the Jacobian of still water", Value::vector({3, 0, -7}),
                          oceanread::smallSea({{"wind_speed", 0}}), "J = 1 exactly", 1, 1, "jacobian"),
      oceanread::hardCase("a TMA sea in 1 cm of water", Value::vector({2, 0, 1}),
                          oceanread::smallSea({{"model", "tma"}, {"depth", 0.01}}),
                          "finite and nearly flat (every spectrum tends to 0 with the depth)", -1, 1),
      oceanread::hardCase("100 km from the origin", Value::vector({1e5, 0, -1e5}), oceanread::smallSea(),
                          "finite: the tiles repeat", -1, 1)};
  for (HardCase& c : oceanread::normalHardCases()) s.hardCases.push_back(std::move(c));
  for (HardCase& c : oceanread::filterHardCases()) s.hardCases.push_back(std::move(c));
  // The variance the filter hands to the sun's lobe, past the tiles: every cascade's whole
  // slope variance (the 1 x 1 means have slope ~0), finite.
  HardCase past = oceanread::hardCase("filtered, past the tiles: the variance is every cascade's slope variance",
                                      Value::vector({5000, 0, 30}), oceanread::smallSea(),
                                      "finite, in (0, 1): the sea's whole mean square slope", 1e-6, 1, "variance");
  past.inputs.push_back({"camera", Value::vector({0, 0, 0})});
  past.inputs.push_back({"pixel_angle", Value::scalar(1e-3)});
  s.hardCases.push_back(std::move(past));
  return s;
}

}  // namespace wg::nodes
