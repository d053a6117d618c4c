// ocean_displacement: the spectral ocean's surface for the vertex stage. A
// point of the still water moves to x0 + (lambda Dx, h, lambda Dz), the
// cascades' maps summed (each faded with the camera distance), and the
// displaced surface's normal comes from the same maps. docs/ocean.md describes
// the model; ocean_spectrum makes the maps.
#include "core/emit_context.h"
#include "core/ocean_settings.h"
#include "nodes/node_library.h"
#include "nodes/ocean_readers.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

NodeSpec oceanDisplacementNode() {
  NodeSpec s;
  s.type = "ocean_displacement";
  s.family = "waves";
  s.summary =
      "Moves the still water's points as the spectral ocean does (height and "
      "horizontal displacement, cascades "
      "summed and faded with distance), with the displaced surface's normal.";
  s.formula =
      "w_c = 1 - smoothstep(F L_c, 2 F L_c, |p - camera|) (1 when F = "
      "0); (lDx, h, lDz, lDxz) = sum over c of w_c "
      "map_c(p.xz); position = p + (lDx, h, lDz); normal = "
      "cross(dP/dz, dP/dx) made unit, from the slope maps "
      "(wg_ocean_normal); each map_c read bicubic (Catmull-Rom) between "
      "its 4 x 4 texels around p.xz.";
  s.source = "Tessendorf, Simulating Ocean Water (2001)";
  s.cost =
      "per cascade 16 texel fetches for the position and 16 more for the "
      "normal, ~40 ALU each; the fade ~8 ALU";
  s.inputs = {
      ports::fixed("ocean", Type::Ocean, "the sea, from an ocean_spectrum node"),
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition, "the still water's point (world space, y up)"),
      ports::fromBuiltin("camera", Type::Vec3, Builtin::CameraPosition, "where distances are measured from")};
  s.outputs = {ports::fixed("position", Type::Vec3, "the displaced point"),
               ports::fixed("normal", Type::Vec3, "unit normal of the displaced surface (down where it folds)"),
               ports::fixed("undisplaced", Type::Vec3,
                            "the still point itself, for ocean_surface in the fragment "
                            "stage (it reaches it as a "
                            "varying, where the fragment's own world position is the "
                            "displaced one)")};
  s.options = {oceanread::fadeOption()};
  s.parseOptions = optionParser(oceanread::parseFade);
  s.isSource = true;  // reads the maps
  s.stages = kVertexStage | kFragmentStage;
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{{}, ValueFact::unitVector(), {}};
  };
  s.emit = [](EmitContext& ctx) {
    const int ocean = ctx.inputIndex("ocean");
    GlslExpr p = ctx.temporary(Type::Vec3, ctx.input("position"));
    GlslExpr xz = ctx.temporary(Type::Vec2, p + ".xz");
    double fade = ctx.options<double>();
    std::vector<GlslExpr> w =
        oceanread::emitWeights(ctx, fade, fade > 0 ? "distance(" + p + ", " + ctx.input("camera") + ")" : "");
    GlslExpr d = oceanread::emitSum(ctx, ocean, ocean::kDisplacementMap, xz, w, oceanread::MapRead::Bicubic);
    GlslExpr slopes = oceanread::emitSum(ctx, ocean, ocean::kSlopeMap, xz, w, oceanread::MapRead::Bicubic);
    ctx.output(0, "(" + p + " + " + d + ".xyz)");
    ctx.output(1, EmitContext::call("wg_ocean_normal", {slopes, d + ".w"}));
    ctx.output(2, p);
  };
  s.eval = [](EvalContext& ctx) {
    const oceanread::EvalPoint at = oceanread::evalPoint(ctx);
    const Value& p = at.position;
    oceanref::MapSample m = oceanread::sumAt(at, oceanread::MapRead::Bicubic);
    ctx.output(0, Value::vector({p[0] + m.displacement[0], p[1] + m.displacement[1], p[2] + m.displacement[2]}));
    ctx.output(1, oceanread::normalOf(m));
    ctx.output(2, p);
  };
  // The maps are float32 transforms of the double fields:
  // runtime/ocean_gpu_cascade.h bounds their error; a few metres of sea carry
  // ~1e-5 relative error.
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy =
      "grows with the texel coordinate x N / L (float32 spacing "
      "1/128 texel at 2^16 texels) times the "
      "fields' gradients, and with the normal's turning where the "
      "surface folds";
  s.hardCases = {
      oceanread::hardCase("a calm (wind 0): the empty spectrum leaves the point where it is", Value::vector({3, 0, -7}),
                          oceanread::smallSea({{"wind_speed", 0}}), "exactly the still point", -7, 3),
      oceanread::hardCase("a TMA sea in 1 cm of water", Value::vector({2, 0, 1}),
                          oceanread::smallSea({{"model", "tma"}, {"depth", 0.01}}),
                          "finite and nearly still (every spectrum tends to 0 with the depth)", -1, 3),
      oceanread::hardCase("100 km from the origin", Value::vector({1e5, 0, -1e5}), oceanread::smallSea(),
                          "finite: the tiles repeat", -1.1e5, 1.1e5),
      // 1/1000 of a texel inside the 50 m tile's far corner (64 texels: 0.78 m each): the
      // bicubic read's texels 63, 0, 1 and 2 past it come from the tile's near side.
      oceanread::hardCase("at a tile's corner: the bicubic read's 4 x 4 texels wrap to the far sides",
                          Value::vector({50 - 0.00078, 0, -0.00078}), oceanread::smallSea(),
                          "finite, within the sea's reach of the corner", -5, 55)};
  for (HardCase& c : oceanread::normalHardCases()) s.hardCases.push_back(std::move(c));
  return s;
}

}  // namespace wg::nodes
