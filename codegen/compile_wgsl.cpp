// The wgsl target within a compile (codegen/compile_wgsl.h).
#include "codegen/compile_wgsl.h"

namespace wg {
namespace {

// The interface the manifest lists (from the GLSL plans) against the WGSL plan's: the
// "webgpu" section is written from the former, the module from the latter.
std::string wgslInterfaceMismatch(const Manifest& m, const ShaderPlan& plan) {
  if (m.uniforms.size() != plan.uniforms.size()) return "uniforms";
  for (size_t i = 0; i < plan.uniforms.size(); ++i)
    if (m.uniforms[i].name != plan.uniforms[i].name || m.uniforms[i].type != plan.uniforms[i].type) return "uniform " + plan.uniforms[i].name;
  if (m.textures.size() != plan.textures.size()) return "textures";
  for (size_t i = 0; i < plan.textures.size(); ++i)
    if (m.textures[i].name != plan.textures[i].name) return "texture " + plan.textures[i].name;
  if (m.varyings.size() != plan.varyings.size()) return "varyings";
  for (size_t i = 0; i < plan.varyings.size(); ++i)
    if (m.varyings[i].name != plan.varyings[i].name) return "varying " + plan.varyings[i].name;
  return "";
}

}  // namespace

void reportWgslMessage(const Program& program, const std::vector<int>& lineOp, int line, const std::string& text,
                       DiagCode code, Diagnostics& diags) {
  int op = line > 0 && static_cast<size_t>(line) <= lineOp.size() ? lineOp[static_cast<size_t>(line - 1)] : -1;
  if (op >= 0) {
    const Op& o = program.ops[static_cast<size_t>(op)];
    withInstanceNotes(diags.error(code, o.where, text, o.nodeId), o);
  } else {
    diags.error(code, SourceRef{program.file, 0, 0}, text);
  }
}

bool addWgslTarget(const Program& program, const std::string& base, const std::string& sourceName,
                   CompileResult& result, Diagnostics& diags, std::vector<int>* lineOp) {
  ShaderPlan plan = planShaders(program, sourceName, /*tessellate=*/false);
  WgslModule module;
  try {
    module = emitWgsl(plan);
  } catch (const WgslRefused& r) {
    std::vector<int> at(1, r.op);
    reportWgslMessage(program, at, 1, "no WGSL form (--target wgsl): " + r.message, DiagCode::WgslRefused, diags);
    return false;
  }
  if (std::string what = wgslInterfaceMismatch(result.manifest, plan); !what.empty()) {
    diags.error(DiagCode::WgslRefused, SourceRef{program.file, 0, 0},
                "the WGSL plan's " + what + " differ from the GLSL targets' (a defect of the compiler)");
    return false;
  }
  const std::string file = base + "." + kWgslTargetName;
  ManifestTarget& t = result.manifest.targets.emplace_back();
  t.name = kWgslTargetName;
  t.from = "watergraph's WGSL emitter: one module, both entry points";
  t.files.push_back({.stage = ShaderStage::Vertex, .file = file, .entryPoint = "vs_main"});
  t.files.push_back({.stage = ShaderStage::Fragment, .file = file, .entryPoint = "fs_main"});
  result.files.push_back({file, std::move(module.text)});
  if (lineOp) *lineOp = std::move(module.lineOp);
  return true;
}

}  // namespace wg
