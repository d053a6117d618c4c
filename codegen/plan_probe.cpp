// planProbe: the shader `watergraph probe` runs. Every op runs in one fragment stage and
// every builtin is a uniform the case sets, so the shader sees exactly the case's values.
#include <stdexcept>

#include "codegen/plan_body.h"
#include "codegen/shader_interface.h"

namespace wg {
namespace {

std::string probeUniformName(BuiltinUniform u) { return std::string(builtinUniformRow(u).glslName); }

GlslExpr probeBuiltin(StageBody& w, Builtin b) {
  if (b == Builtin::Uv) {
    // b_uv (probeLocals): the case's uv, varying across the quad by its gradient.
    w.use(BuiltinUniform::ProbeUvGradient);
    w.use(BuiltinUniform::ProbePixel);
    w.use(builtinRow(b).uniform);
    return GlslExpr::name("b_uv");
  }
  return w.uniform(builtinRow(b).uniform);
}

// uv also moves by the case's gradient per pixel away from the case's pixel, so dFdx(uv)
// and dFdy(uv) (the level of detail of a mipmapped texture()) are the gradient, while at
// the pixel itself the offset is exactly 0 and uv is the case's value bit for bit.
StageLocals probeLocals(const StageBody& w) {
  if (!w.builtins.count(Builtin::Uv)) return {};
  const GlslExpr gradient = GlslExpr::name(probeUniformName(BuiltinUniform::ProbeUvGradient));
  const GlslExpr pixel = GlslExpr::name(probeUniformName(BuiltinUniform::ProbePixel));
  StageLocals locals;
  locals.add(Type::Vec2, "b_uv",
             GlslExpr::name(probeUniformName(BuiltinUniform::ProbeUv)) + " + " + gradient + ".xy * (gl_FragCoord.x - " + pixel +
                 ".x) + " + gradient + ".zw * (gl_FragCoord.y - " + pixel + ".y)");
  return locals;
}

}  // namespace

ShaderPlan planProbe(const Program& program, std::string sourceName) {
  ShaderPlan plan;
  plan.kind = ShaderPlan::Kind::Probe;
  plan.sourceName = std::move(sourceName);
  plan.graphName = program.graphName;
  // Probe cases hand builtins and parameters any value: no facts about them.
  BodyWriter writer(program, false, probeBuiltin);
  StageBody frag(kFragmentStage);
  writer.writeOps(frag);
  if (program.outputs.empty()) throw std::logic_error("emit: a probe program needs an output");
  const ProgramOutput& out = program.outputs.front();
  const GlslExpr value = writer.valueExpr(frag, out.value, out.type);
  const char* pad[] = {"", ", 0.0, 0.0, 0.0", ", 0.0, 0.0", ", 0.0", ""};
  int n = componentCount(out.type);
  if (n < 1 || n > 4) throw std::logic_error("emit: a probe output must be a float or a vector");
  frag.body.assign(-1, value.operations(), iface::kColorOutput, "vec4(", value.text(), pad[n], ")");
  plan.uniforms = writer.uniforms(nullptr, frag);
  plan.textures = writer.textures();
  plan.oceans = writer.oceans();
  planResources(program, plan);
  PlannedStage& fs = plan.stages.emplace_back(plannedStage(ShaderStage::Fragment, std::move(frag), probeLocals(frag)));
  addOwnGlsl(program, fs);
  fs.uniforms = uniformsWhere(plan, [](const UniformInfo& u) { return (u.stages & kFragmentStage) != 0; });
  fs.textures = texturesIn(plan, kFragmentStage);
  plan.functions = functionsOf(plan.stages);
  return plan;
}

}  // namespace wg
