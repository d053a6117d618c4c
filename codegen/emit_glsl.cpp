#include "codegen/emit_glsl.h"

#include <algorithm>

#include "codegen/shader_interface.h"
#include "nodes/glsl_library.h"

namespace wg {
namespace {

// Per-target differences, as data.
struct TargetStyle {
  std::string_view version;  // what follows "#version " on the first line
  bool precision;         // ES: default precision statements
  bool uniformBlock;      // Vulkan: non-opaque uniforms in one std140 block
  bool varyingLocations;  // Vulkan: explicit locations on every in/out
};

TargetStyle styleOf(Target t) {
  switch (t) {
    case Target::Glsl330: return {targetGlslVersion(t), false, false, false};
    case Target::Es300: return {targetGlslVersion(t), true, false, false};
    case Target::Vk450: return {targetGlslVersion(t), false, true, true};
  }
  return {targetGlslVersion(Target::Glsl330), false, false, false};
}

// One shader's text being assembled: lines appended into one buffer, each with the op
// that wrote it (-1: none), so a glslang error maps back to its node.
struct ShaderText {
  EmittedShader shader;
  explicit ShaderText(ShaderStage stage) { shader.stage = stage; }
  void add(std::string_view line, int op = -1) {
    shader.text.append(line);
    shader.text += '\n';
    shader.lineOp.push_back(op);
  }
  // Whole lines, each ending in '\n' (lines from no op, or all from `ops`).
  void addLines(std::string_view lines, const std::vector<int>* ops = nullptr) {
    shader.text.append(lines);
    if (ops)
      shader.lineOp.insert(shader.lineOp.end(), ops->begin(), ops->end());
    else
      shader.lineOp.insert(shader.lineOp.end(), static_cast<size_t>(std::count(lines.begin(), lines.end(), '\n')), -1);
  }
  // Planned lines of main(), each with the op of its statement.
  void addLines(const PlannedLines& lines) {
    shader.text.append(lines.text);
    for (const PlannedStatement& s : lines.statements) shader.lineOp.push_back(s.op);
  }
};

// One planned stage in one target's dialect.
class StageAssembler {
 public:
  StageAssembler(const ShaderPlan& plan, Target target) : plan_(plan), target_(target), style_(styleOf(target)) {}

  EmittedShader assemble(const PlannedStage& s) const {
    ShaderText out(s.stage);
    addPreamble(s.stage, out);
    if (s.stage == ShaderStage::TessControl) out.add("layout(vertices = 3) out;");
    if (s.stage == ShaderStage::TessEvaluation) out.add("layout(triangles, fractional_odd_spacing, ccw) in;");
    for (const auto& a : s.attributes)
      out.add("layout(location = " + std::to_string(a.location) + ") in " + std::string(typeName(a.type)) + " " + a.name + ";");
    addInterface(out, "in", s.inputs, s.arrayedInputs);
    addInterface(out, "out", s.outputs, s.arrayedOutputs);
    if (s.stage == ShaderStage::Fragment)
      out.add("layout(location = " + std::to_string(iface::kColorLocation) + ") out vec4 " + iface::kColorOutput + ";");
    addUniforms(out, s);
    for (size_t i : s.textures) {
      const TextureInfo& t = plan_.textures[i];
      std::string qual = style_.uniformBlock ? "layout(set = 0, binding = " + std::to_string(t.binding) + ") " : "";
      // ES samplers default to lowp, which may return half floats: scene depth and the
      // float G-buffer need highp (node textures are 8-bit and keep the default).
      std::string precision = style_.precision && t.scene ? "highp " : "";
      out.add(qual + "uniform " + precision + std::string(typeName(t.type)) + " " + t.name + ";");
    }
    // Library functions this stage calls, dependencies first.
    for (const GlslItem* item : s.library) {
      out.add("");
      out.addLines(item->text);
      out.add("");  // ends the item's last line, or adds an empty one after a final '\n'
    }
    // The ops' own GLSL (function nodes' files, renamed into their namespaces).
    for (size_t k = 0; k < s.ownGlsl.size(); ++k) {
      const std::string& code = *s.ownGlsl[k];
      std::vector<int> ops(static_cast<size_t>(std::count(code.begin(), code.end(), '\n')), s.ownGlslOp[k]);
      out.add("");
      out.addLines(code, &ops);
    }
    out.add("");
    out.add("void main() {");
    out.addLines(s.locals);
    // The body is most of a big graph's shader: room for it and the closing "}\n" at once,
    // so the text is not doubled past its size while it grows (megabytes at 10,000 nodes).
    out.shader.text.reserve(out.shader.text.size() + s.body.text.size() + 2);
    out.shader.lineOp.reserve(out.shader.lineOp.size() + s.body.statements.size() + 1);
    out.addLines(s.body);
    out.add("}");
    return std::move(out.shader);
  }

 private:
  // The version line, the extension tessellation needs in GLSL 330, ES precision.
  void addPreamble(ShaderStage stage, ShaderText& out) const {
    out.add("#version " + std::string(style_.version));
    // The rest is the body a host that writes the version line itself takes (three.js).
    out.shader.bodyStart = out.shader.text.size();
    bool tessStage = stage == ShaderStage::TessControl || stage == ShaderStage::TessEvaluation;
    if (tessStage && target_ == Target::Glsl330) out.add("#extension GL_ARB_tessellation_shader : require");
    out.add("// Generated by watergraph from " + plan_.sourceName + " (graph '" + plan_.graphName + "'); do not edit.");
    if (style_.precision) {
      out.add("precision highp float;");
      out.add("precision highp int;");
      // Samplers default to lowp, and a sampler passed to a library function takes the
      // default: llvmpipe then returns half floats (0.6 reads 0.5996) and quantises 8-bit
      // texels to n/256. The hard-case probe found both.
      out.add("precision highp sampler2D;");
      out.add("precision highp samplerCube;");
    }
    out.add("");
  }

  // Declarations of a stage's ins or outs, with Vulkan locations from 0.
  void addInterface(ShaderText& out, const std::string& qualifier, const std::vector<StageVariable>& vars, bool arrayed) const {
    int location = 0;
    for (const auto& v : vars) {
      std::string loc = style_.varyingLocations ? "layout(location = " + std::to_string(location) + ") " : "";
      out.add(loc + qualifier + " " + std::string(typeName(v.type)) + " " + v.name + (arrayed ? "[]" : "") + ";");
      ++location;
    }
  }

  // Vulkan: one block with the same members in every stage; else the stage's own uniforms.
  void addUniforms(ShaderText& out, const PlannedStage& s) const {
    if (style_.uniformBlock) {
      bool any = false;
      for (const auto& u : plan_.uniforms) any |= !isSampler(u.type);
      if (!any) return;
      out.add("layout(std140, set = 0, binding = " + std::to_string(iface::kUniformBlockBinding) + ") uniform " +
              iface::kUniformBlock + " {");
      for (const auto& u : plan_.uniforms) out.add("  " + std::string(typeName(u.type)) + " " + u.name + ";");
      out.add("};");
      return;
    }
    for (size_t i : s.uniforms) {
      const UniformInfo& u = plan_.uniforms[i];
      out.add("uniform " + std::string(typeName(u.type)) + " " + u.name + ";");
    }
  }

  const ShaderPlan& plan_;
  Target target_;
  TargetStyle style_;
};

}  // namespace

EmitResult emitGlsl(const ShaderPlan& plan, Target target) {
  EmitResult result;
  StageAssembler assembler(plan, target);
  for (const auto& s : plan.stages) result.shaders.push_back(assembler.assemble(s));
  result.uniforms = plan.uniforms;
  result.attributes = plan.attributes;
  result.textures = plan.textures;
  result.oceans = plan.oceans;
  result.varyings = plan.varyings;
  result.functions = plan.functions;
  result.tessellation = plan.tessellation;
  return result;
}

EmittedShader emitStage(const ShaderPlan& plan, const PlannedStage& stage, Target target) {
  return StageAssembler(plan, target).assemble(stage);
}

EmitResult emitProgram(const Program& program, Target target, const std::string& sourceName, EmitMode mode,
                       bool allowTessellation) {
  if (mode == EmitMode::Probe) return emitGlsl(planProbe(program, sourceName), target);
  return emitGlsl(planShaders(program, sourceName, tessellates(target, allowTessellation)), target);
}

std::vector<EmitResult> emitPrograms(const Program& program, const std::vector<Target>& targets,
                                     const std::string& sourceName, bool allowTessellation) {
  TargetPlans plans = planTargets(program, targets, sourceName, allowTessellation);
  std::vector<EmitResult> out;
  out.reserve(targets.size());
  for (size_t i = 0; i < targets.size(); ++i) out.push_back(emitGlsl(plans.of(i), targets[i]));
  return out;
}

}  // namespace wg
