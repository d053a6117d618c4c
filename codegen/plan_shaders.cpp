// planShaders: the vertex (or tessellated geometry) and fragment stages of a drawn surface
// or of the deferred pass, and the interface between them; planTargets shares one plan
// among the targets that tessellate alike.
#include <stdexcept>

#include "codegen/plan_body.h"
#include "codegen/shader_interface.h"

namespace wg {
namespace {

std::string surfaceUniformName(BuiltinUniform u) { return std::string(builtinUniformRow(u).glslName); }

// The screen uv builtin in both stages (a local of main()).
const char* const kSurfaceScreenUv = "b_screen_uv";

// How a surface's (or the deferred pass's) stage bodies name the builtins: vertex stages
// compute them as locals from the attributes (or the patch), fragment stages from the
// varyings (or the G-buffer).
GlslExpr surfaceBuiltin(const ShaderPlan& plan, StageBody& w, Builtin b) {
  bool vertex = w.stage == kVertexStage;
  switch (b) {
    case Builtin::Uv: return GlslExpr::name(vertex ? (plan.tessellation ? "b_uv" : iface::kUvAttribute) : "v_uv");
    case Builtin::WorldPosition:
      if (vertex) w.use(BuiltinUniform::Model);
      return GlslExpr::name(vertex ? "b_world_position" : "v_world_position");
    case Builtin::Normal:
      if (vertex) w.use(BuiltinUniform::Model);
      return GlslExpr::name("b_normal");
    case Builtin::ViewDirection:
      w.use(BuiltinUniform::CameraPosition);
      if (vertex) w.use(BuiltinUniform::Model);
      return GlslExpr::name("b_view_direction");
    case Builtin::ScreenUv: w.use(BuiltinUniform::ViewportSize); return GlslExpr::name(kSurfaceScreenUv);
    case Builtin::FragDepth:
      return GlslExpr(plan.kind == ShaderPlan::Kind::Deferred && !vertex ? "b_water_surface.w" : "gl_FragCoord.z");
    case Builtin::CameraPosition:
    case Builtin::Time:
    case Builtin::CameraNearFar:
    case Builtin::View:
    case Builtin::Projection:
    case Builtin::SunDirection: return w.uniform(builtinRow(b).uniform);
    case Builtin::PixelAngle:
      // From the two uniforms every runtime and client sets; abs: a projection that flips y.
      return "(2.0 / abs(" + w.uniform(BuiltinUniform::Projection) + "[1][1] * " +
             w.uniform(BuiltinUniform::ViewportSize) + ".y))";
  }
  return GlslExpr();
}

// The untessellated vertex shader's builtin locals: the mesh in world space.
StageLocals vertexLocals(const StageBody& w) {
  const GlslExpr model = GlslExpr::name(surfaceUniformName(BuiltinUniform::Model));
  StageLocals locals;
  locals.add(Type::Vec3, "b_world_position", "(" + model + " * vec4(" + GlslExpr::name(iface::kPositionAttribute) + ", 1.0)).xyz");
  if (w.builtins.count(Builtin::Normal))
    locals.add(Type::Vec3, "b_normal",
               EmitContext::call("wg_safe_normalize_vec3", {"mat3(" + model + ") * " + GlslExpr::name(iface::kNormalAttribute)}));
  if (w.builtins.count(Builtin::ViewDirection))
    locals.add(Type::Vec3, "b_view_direction",
               EmitContext::call("wg_safe_normalize_vec3",
                                 {GlslExpr::name(surfaceUniformName(BuiltinUniform::CameraPosition)) + " - b_world_position"}));
  return locals;
}

// The fragment shader's builtin locals, from the varyings (deferred: from the G-buffer).
StageLocals fragmentLocals(const ShaderPlan& plan, const StageBody& w) {
  const bool deferred = plan.kind == ShaderPlan::Kind::Deferred;
  StageLocals locals = deferred ? deferredLocals(w) : StageLocals{};
  if (w.builtins.count(Builtin::Normal))
    locals.add(Type::Vec3, "b_normal", EmitContext::call("wg_safe_normalize_vec3", {GlslExpr::name("v_normal")}));
  if (w.builtins.count(Builtin::ViewDirection))
    locals.add(Type::Vec3, "b_view_direction",
               EmitContext::call("wg_safe_normalize_vec3",
                                 {GlslExpr::name(surfaceUniformName(BuiltinUniform::CameraPosition)) + " - v_world_position"}));
  if (w.builtins.count(Builtin::ScreenUv) && !deferred)
    locals.add(Type::Vec2, "b_screen_uv", "gl_FragCoord.xy / " + GlslExpr::name(surfaceUniformName(BuiltinUniform::ViewportSize)));
  return locals;
}

}  // namespace

ShaderPlan planShaders(const Program& program, std::string sourceName, bool tessellate) {
  ShaderPlan plan;
  plan.sourceName = std::move(sourceName);
  plan.graphName = program.graphName;
  plan.kind = program.reads(SceneResource::Underwater) ? ShaderPlan::Kind::Deferred : ShaderPlan::Kind::Surface;
  if (tessellate) plan.tessellation = requestedTessellation(program);
  const bool deferred = plan.kind == ShaderPlan::Kind::Deferred;
  BodyWriter writer(program, true, [&plan](StageBody& w, Builtin b) { return surfaceBuiltin(plan, w, b); });

  StageBody frag(kFragmentStage);
  writer.writeOps(frag);
  const GlslExpr color = writer.outputExpr(frag, OutputSlot::FragmentColor, "vec3(0.5)");
  const GlslExpr alpha = writer.outputExpr(frag, OutputSlot::FragmentAlpha, "1.0");
  const size_t colorStatement = frag.body.statements.size();
  frag.body.assign(-1, color.operations() + alpha.operations(), iface::kColorOutput, "vec4(", color.text(), ", ", alpha.text(), ")");
  if (deferred) planDeferredSamplers(writer, frag);

  StageBody vert(kVertexStage);
  writer.writeOps(vert);
  // What the fragment stage reads from the vertex stage.
  bool fragNeedsPosition = frag.builtins.count(Builtin::WorldPosition) || frag.builtins.count(Builtin::ViewDirection);
  bool fragNeedsNormal = frag.builtins.count(Builtin::Normal) > 0;
  bool fragNeedsUv = frag.builtins.count(Builtin::Uv) > 0;
  // Deferred: the vertex shader feeds the runtime's G-buffer pass, which stores all three.
  if (deferred) fragNeedsPosition = fragNeedsNormal = fragNeedsUv = true;
  const GlslExpr position = writer.outputExpr(vert, OutputSlot::VertexPosition, writer.builtinExpr(vert, Builtin::WorldPosition));
  const GlslExpr clip = GlslExpr::name(vert.use(BuiltinUniform::ViewProjection)) + " * vec4(" + position + ", 1.0)";
  vert.body.assign(-1, clip.operations(), "gl_Position", clip.text());
  if (fragNeedsPosition) vert.body.assign(-1, position.operations(), "v_world_position", position.text());
  if (fragNeedsNormal) {
    const GlslExpr normal = program.output(OutputSlot::VertexNormal) ? writer.outputExpr(vert, OutputSlot::VertexNormal, "")
                                                                     : writer.builtinExpr(vert, Builtin::Normal);
    vert.body.assign(-1, normal.operations(), "v_normal", normal.text());
  }
  if (fragNeedsUv) {
    vert.builtins.insert(Builtin::Uv);
    vert.body.assign(-1, 0, "v_uv", plan.tessellation ? "b_uv" : iface::kUvAttribute);  // a name
  }
  for (const auto& v : program.varyings) {
    const GlslExpr value = writer.opOutput(vert, v.index, v.port);
    vert.body.assign(-1, value.operations(), writer.varyingName(v.index, v.port), value.text());
  }
  if (plan.tessellation) {
    // The vertex shader places the mesh (model), the control stage measures distances.
    vert.use(BuiltinUniform::Model);
    vert.use(BuiltinUniform::CameraPosition);
  }

  // The interface.
  plan.attributes.push_back({iface::kPositionAttribute, Type::Vec3, iface::kPositionLocation});
  if (vert.builtins.count(Builtin::Normal)) plan.attributes.push_back({iface::kNormalAttribute, Type::Vec3, iface::kNormalLocation});
  if (vert.builtins.count(Builtin::Uv)) plan.attributes.push_back({iface::kUvAttribute, Type::Vec2, iface::kUvLocation});
  if (fragNeedsPosition) plan.varyings.push_back({"v_world_position", Type::Vec3, "world_position"});
  if (fragNeedsNormal) plan.varyings.push_back({"v_normal", Type::Vec3, "normal"});
  if (fragNeedsUv) plan.varyings.push_back({"v_uv", Type::Vec2, "uv"});
  for (const auto& v : program.varyings) {
    const Op& op = program.ops[static_cast<size_t>(v.index)];
    plan.varyings.push_back({writer.varyingName(v.index, v.port), op.outputTypes[static_cast<size_t>(v.port)],
                             "node '" + op.nodeId + "' output '" + op.spec->outputs[static_cast<size_t>(v.port)].name + "'"});
  }
  plan.uniforms = writer.uniforms(&vert, frag);
  plan.textures = writer.textures();
  plan.oceans = writer.oceans();
  planResources(program, plan);

  // The stages, each with what it declares.
  std::vector<StageVariable> varyings;
  for (const auto& v : plan.varyings) varyings.push_back({v.type, v.name});
  const std::string model = surfaceUniformName(BuiltinUniform::Model);
  if (plan.tessellation) {
    plan.stages.push_back(tessVertexStage(plan, vert));
    plan.stages.push_back(tessControlStage(plan, vert));
    std::vector<StageVariable> patch = patchVariables(vert, "te_");
    PlannedStage& eval = plan.stages.emplace_back(plannedStage(ShaderStage::TessEvaluation, std::move(vert), tessEvaluationLocals(vert)));
    addOwnGlsl(program, eval);
    eval.inputs = std::move(patch);
    eval.arrayedInputs = true;
    eval.outputs = varyings;
    // The model matrix served the earlier stages; the evaluation stage is in world space.
    eval.uniforms = uniformsWhere(plan, [&](const UniformInfo& u) { return (u.stages & kVertexStage) && u.name != model; });
    eval.textures = texturesIn(plan, kVertexStage);
  } else {
    PlannedStage& vs = plan.stages.emplace_back(plannedStage(ShaderStage::Vertex, std::move(vert), vertexLocals(vert)));
    addOwnGlsl(program, vs);
    vs.attributes = plan.attributes;
    vs.outputs = varyings;
    vs.uniforms = uniformsWhere(plan, [](const UniformInfo& u) { return (u.stages & kVertexStage) != 0; });
    vs.textures = texturesIn(plan, kVertexStage);
  }
  // Deferred: the look-ups of the G-buffer locals come first in main().
  std::vector<TextureFetch> localFetches = deferred ? deferredFetches(frag) : std::vector<TextureFetch>{};
  for (auto& f : frag.fetches) f.fetch.atScreenUv = f.coordIsScreenUv;
  PlannedStage& fs = plan.stages.emplace_back(plannedStage(ShaderStage::Fragment, std::move(frag), fragmentLocals(plan, frag)));
  addOwnGlsl(program, fs);
  fs.colorStatement = colorStatement;
  fs.fetches.insert(fs.fetches.begin(), localFetches.begin(), localFetches.end());
  // Deferred: the full-screen fragment shader reads the G-buffer instead of varyings.
  if (!deferred) fs.inputs = varyings;
  fs.uniforms = uniformsWhere(plan, [](const UniformInfo& u) { return (u.stages & kFragmentStage) != 0; });
  fs.textures = texturesIn(plan, kFragmentStage);
  plan.functions = functionsOf(plan.stages);
  return plan;
}

TargetPlans planTargets(const Program& program, const std::vector<Target>& targets, const std::string& sourceName,
                        bool allowTessellation) {
  TargetPlans out;
  out.targets = targets;
  // At most two plans: the geometry stage tessellated or not.
  std::optional<size_t> byChoice[2];
  const bool asked = requestedTessellation(program).has_value();
  for (Target t : targets) {
    bool tess = asked && tessellates(t, allowTessellation);
    std::optional<size_t>& at = byChoice[tess ? 1 : 0];
    if (!at) {
      at = out.plans.size();
      out.plans.push_back(planShaders(program, sourceName, tess));
    }
    out.planOf.push_back(*at);
  }
  return out;
}

}  // namespace wg
