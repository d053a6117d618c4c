// ocean_surface: the spectral ocean's surface detail for the fragment stage:
// the normal of the displaced surface, the slopes and the Jacobian J (where J <
// 0 the surface folds: whitecaps), read per pixel at the still point
// ocean_displacement passes on.
#include "core/emit_context.h"
#include "core/ocean_settings.h"
#include "nodes/node_library.h"
#include "nodes/ocean_readers.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

NodeSpec oceanSurfaceNode() {
  NodeSpec s;
  s.type = "ocean_surface";
  s.family = "waves";
  s.summary =
      "The spectral ocean's normal, slopes and Jacobian at a "
      "still-water point, per pixel: the surface "
      "detail a vertex grid cannot carry, and where the surface folds.";
  s.formula =
      "w_c as ocean_displacement; (lDx, h, lDz, lDxz) and (hx, hz, "
      "lDxx, lDzz) = sum over c of w_c map_c(p.xz); "
      "normal = cross(dP/dz, dP/dx) made unit (wg_ocean_normal); "
      "slopes = (hx, hz); "
      "jacobian = (1 + lDxx)(1 + lDzz) - lDxz^2.";
  s.source = "Tessendorf, Simulating Ocean Water (2001)";
  s.cost = "per cascade 8 texel fetches and ~20 ALU; the fade ~8 ALU";
  s.inputs = {ports::fixed("ocean", Type::Ocean, "the sea, from an ocean_spectrum node"),
              ports::fixed("position", Type::Vec3,
                           "the still water's point: ocean_displacement's "
                           "`undisplaced` output (the fragment's world "
                           "position is the displaced one)"),
              ports::fromBuiltin("camera", Type::Vec3, Builtin::CameraPosition, "where distances are measured from")};
  s.outputs = {ports::fixed("normal", Type::Vec3, "unit normal of the displaced surface (down where it folds)"),
               ports::fixed("slopes", Type::Vec2, "dh/dx and dh/dz of the height at the still point"),
               ports::fixed("jacobian", Type::Float,
                            "J of the horizontal displacement: 1 on still water, < 0 "
                            "where it folds")};
  s.options = {oceanread::fadeOption()};
  s.parseOptions = optionParser(oceanread::parseFade);
  s.isSource = true;
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{ValueFact::unitVector(), {}, {}};
  };
  s.emit = [](EmitContext& ctx) {
    const int ocean = ctx.inputIndex("ocean");
    GlslExpr p = ctx.temporary(Type::Vec3, ctx.input("position"));
    double fade = ctx.options<double>();
    std::vector<GlslExpr> w =
        oceanread::emitWeights(ctx, fade, fade > 0 ? "distance(" + p + ", " + ctx.input("camera") + ")" : "");
    GlslExpr xz = p + ".xz";
    GlslExpr d = oceanread::emitSum(ctx, ocean, ocean::kDisplacementMap, xz, w);
    GlslExpr slopes = oceanread::emitSum(ctx, ocean, ocean::kSlopeMap, xz, w);
    ctx.output(0, EmitContext::call("wg_ocean_normal", {slopes, d + ".w"}));
    ctx.output(1, slopes + ".xy");
    ctx.output(2, EmitContext::call("wg_ocean_jacobian", {slopes, d + ".w"}));
  };
  s.eval = [](EvalContext& ctx) {
    oceanref::MapSample m = oceanread::sumAt(oceanread::evalPoint(ctx));
    ctx.output(0, oceanread::normalOf(m));
    ctx.output(1, Value::vector({m.slopes[0], m.slopes[1]}));
    ctx.output(2, Value::scalar(oceanread::jacobianOf(m)));
  };
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy =
      "grows with the texel coordinate x N / L times the fields' "
      "gradients, and with the normal's turning "
      "where the surface folds";
  s.hardCases = {
      oceanread::hardCase("a calm (wind 0): the Jacobian of still water", Value::vector({3, 0, -7}),
                          oceanread::smallSea({{"wind_speed", 0}}), "J = 1 exactly", 1, 1, "jacobian"),
      oceanread::hardCase("a TMA sea in 1 cm of water", Value::vector({2, 0, 1}),
                          oceanread::smallSea({{"model", "tma"}, {"depth", 0.01}}),
                          "finite and nearly flat (every spectrum tends to 0 with the depth)", -1, 1),
      oceanread::hardCase("100 km from the origin", Value::vector({1e5, 0, -1e5}), oceanread::smallSea(),
                          "finite: the tiles repeat", -1, 1)};
  for (HardCase& c : oceanread::normalHardCases()) s.hardCases.push_back(std::move(c));
  return s;
}

}  // namespace wg::nodes
