// vertex_output: the surface the vertex stage hands on — a position plus a displacement,
// and a normal — with distance-based tessellation of the mesh as an option (the stylized water shader).
// Its outputs feed the graph's `outputs.vertex` slots; with tessellation, the vertex-stage
// nodes run per tessellated vertex (GLSL 330 through ARB_tessellation_shader, Vulkan
// 450); GLSL ES 3.00 has no tessellation stages, so es300 draws the mesh as it is.
#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

namespace {

// The tessellation the node asks for, or none.
std::optional<TessellationSettings> parseVertexOutputOptions(const OptionReader& o) {
  bool distance = o.is("tessellation", "distance");
  TessellationSettings t{o.number("min_distance"), o.number("max_distance"), o.number("factor")};
  return distance ? std::optional(t) : std::nullopt;
}

}  // namespace

NodeSpec vertexOutputNode() {
  NodeSpec s;
  s.type = "vertex_output";
  s.family = "output";
  s.summary = "The displaced surface for the vertex outputs, optionally tessellated by camera distance.";
  s.formula =
      "position = position + displacement; normal = safe_normalize(normal). Tessellation (distance): per vertex "
      "f = clamp(1 - (d - min_distance) / (max_distance - min_distance), 0.01, 1) * factor, floored at 1; an "
      "edge takes the mean of its two vertices, the inside the mean of all three.";
  s.source = "stylized water shader (tessellation: distance-based factor, triangle patches)";
  s.cost = "free without tessellation; with it, the vertex-stage nodes run once per generated vertex (up to "
           "factor^2 times as many), plus a control stage per patch";
  s.stages = kVertexStage;
  s.inputs = {
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition, "the surface point before displacement"),
      ports::fixed("displacement", Type::Vec3, Value::vector({0, 0, 0}), "offset added to the position"),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "the displaced surface's normal"),
  };
  s.outputs = {ports::fixed("position", Type::Vec3, "position + displacement, for outputs.vertex.position"),
               ports::fixed("normal", Type::Vec3, "the unit normal, for outputs.vertex.normal")};
  s.options = {
      ports::choice("tessellation", {"none", "distance"}, "none",
                    "subdivide the mesh near the camera (glsl330, vk450; es300 draws the mesh as it is)"),
      ports::number("min_distance", 5, 0, 1e6, "distance (m) within which the full factor applies"),
      ports::number("max_distance", 50, 0, 1e6, "distance (m) at which the factor has fallen to 1%"),
      // A quality knob: a lower factor generates fewer vertices (the vertex-stage nodes run
      // once per generated vertex) and follows the displacement more coarsely.
      ports::knob(ports::number("factor", 16, 1, 64,
                                "the largest tessellation level (lower: fewer vertices, the displacement followed "
                                "more coarsely; no effect without tessellation)"),
                  {1, 2, 4, 8, 16}),
  };
  s.parseOptions = optionParser(parseVertexOutputOptions);
  s.tessellation = [](const ParsedOptions& o) { return o.as<std::optional<TessellationSettings>>(); };
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{{}, ValueFact::unitVector()}; };
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, "(" + ctx.input("position") + " + " + ctx.input("displacement") + ")");
    // A normal proven unit (value facts: a wave node's output) is not normalised again.
    ctx.output(1, ctx.inputFact("normal").normalized ? ctx.input("normal")
                                                     : EmitContext::call("wg_safe_normalize_vec3", {ctx.input("normal")}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, glsl::map2(ctx.input("position"), ctx.input("displacement"), Type::Vec3,
                             [](double a, double b) { return a + b; }));
    ctx.output(1, glsl::safeNormalize(ctx.input("normal")));
  };
  s.tolerance = 1e-6;
  s.hardCases = {{"zero normal", {{"normal", Value::vector({0, 0, 0})}}, {}, "the zero vector, not NaN", -1e30, 1e30, "normal"},
                 {"huge coordinates", {{"position", Value::vector({1e5, 0, -1e5})}, {"displacement", Value::vector({0.5, 1, 0.5})}},
                  {}, "finite", -2e5, 2e5}};
  return s;
}

}  // namespace wg::nodes
