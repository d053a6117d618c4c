// Tessellation: a vertex-stage node (a displacement that wants finer geometry near the
// camera) asks for it; the vertex-stage nodes then run in the evaluation stage on the
// interpolated patch, after a vertex shader that only places the mesh in world space and a
// control stage that picks the levels from each corner's distance to the camera.
#include "codegen/plan_body.h"
#include "codegen/shader_interface.h"
#include "core/number_format.h"

namespace wg {
namespace {

std::string tessUniformName(BuiltinUniform u) { return std::string(builtinUniformRow(u).glslName); }

// A stage whose body is fixed text (no op wrote it), calling the library functions `calls`.
PlannedStage fixedStage(ShaderStage stage, PlannedLines body, const std::vector<std::string>& calls) {
  PlannedStage s;
  s.stage = stage;
  s.library = libraryFor(calls);
  s.body = std::move(body);
  return s;
}

}  // namespace

std::optional<TessellationSettings> requestedTessellation(const Program& p) {
  for (const auto& op : p.ops)
    if ((op.stage & kVertexStage) && op.spec->tessellation)
      if (auto settings = op.spec->tessellation(*op.parsedOptions)) return settings;
  return std::nullopt;
}

std::vector<StageVariable> patchVariables(const StageBody& geometry, const std::string& prefix) {
  std::vector<StageVariable> vars = {{Type::Vec3, prefix + "position"}};
  if (geometry.builtins.count(Builtin::Normal)) vars.push_back({Type::Vec3, prefix + "normal"});
  if (geometry.builtins.count(Builtin::Uv)) vars.push_back({Type::Vec2, prefix + "uv"});
  return vars;
}

// The patch's corners, interpolated at gl_TessCoord.
StageLocals tessEvaluationLocals(const StageBody& w) {
  auto lerp3 = [](const char* name) {
    const GlslExpr a = GlslExpr::name(name);
    return "gl_TessCoord.x * " + a + "[0] + gl_TessCoord.y * " + a + "[1] + gl_TessCoord.z * " + a + "[2]";
  };
  StageLocals locals;
  locals.add(Type::Vec3, "b_world_position", lerp3("te_position"));
  if (w.builtins.count(Builtin::Normal))
    locals.add(Type::Vec3, "b_normal", EmitContext::call("wg_safe_normalize_vec3", {lerp3("te_normal")}));
  if (w.builtins.count(Builtin::Uv)) locals.add(Type::Vec2, "b_uv", lerp3("te_uv"));
  if (w.builtins.count(Builtin::ViewDirection))
    locals.add(Type::Vec3, "b_view_direction",
               EmitContext::call("wg_safe_normalize_vec3",
                                 {GlslExpr::name(tessUniformName(BuiltinUniform::CameraPosition)) + " - b_world_position"}));
  return locals;
}

PlannedStage tessVertexStage(const ShaderPlan& plan, const StageBody& geometry) {
  const std::string model = tessUniformName(BuiltinUniform::Model);
  PlannedLines body;
  body.fixed("tc_position = (" + model + " * vec4(" + iface::kPositionAttribute + ", 1.0)).xyz;");
  std::vector<std::string> calls;
  if (geometry.builtins.count(Builtin::Normal)) {
    body.fixed("tc_normal = wg_safe_normalize_vec3(mat3(" + model + ") * " + iface::kNormalAttribute + ");");
    calls.emplace_back("wg_safe_normalize_vec3");
  }
  if (geometry.builtins.count(Builtin::Uv)) body.fixed("tc_uv = " + std::string(iface::kUvAttribute) + ";");
  body.fixed("gl_Position = vec4(tc_position, 1.0);");
  PlannedStage s = fixedStage(ShaderStage::Vertex, std::move(body), calls);
  s.attributes = plan.attributes;
  s.outputs = patchVariables(geometry, "tc_");
  s.uniforms = uniformsWhere(plan, [&](const UniformInfo& u) { return u.name == model; });
  return s;
}

// Levels from the camera distance of each corner; an edge takes the mean of its two ends,
// so neighbouring patches agree on it and no cracks open.
PlannedStage tessControlStage(const ShaderPlan& plan, const StageBody& geometry) {
  const TessellationSettings& t = *plan.tessellation;
  const std::string camera = tessUniformName(BuiltinUniform::CameraPosition);
  PlannedLines body;
  for (const auto& v : patchVariables(geometry, ""))
    body.fixed("te_" + v.name + "[gl_InvocationID] = tc_" + v.name + "[gl_InvocationID];");
  body.fixed("if (gl_InvocationID == 0) {");
  for (int i = 0; i < 3; ++i)
    body.fixed("  float f" + std::to_string(i) + " = wg_tess_distance_factor(tc_position[" + std::to_string(i) + "], " + camera +
               ", " + formatGlslFloat(t.minDistance) + ", " + formatGlslFloat(t.maxDistance) + ", " + formatGlslFloat(t.factor) + ");");
  body.fixed("  gl_TessLevelOuter[0] = 0.5 * (f1 + f2);");
  body.fixed("  gl_TessLevelOuter[1] = 0.5 * (f2 + f0);");
  body.fixed("  gl_TessLevelOuter[2] = 0.5 * (f0 + f1);");
  body.fixed("  gl_TessLevelInner[0] = (f0 + f1 + f2) / 3.0;");
  body.fixed("}");
  PlannedStage s = fixedStage(ShaderStage::TessControl, std::move(body), {"wg_tess_distance_factor"});
  s.inputs = patchVariables(geometry, "tc_");
  s.outputs = patchVariables(geometry, "te_");
  s.arrayedInputs = s.arrayedOutputs = true;
  s.uniforms = uniformsWhere(plan, [&](const UniformInfo& u) { return u.name == camera; });
  return s;
}

}  // namespace wg
