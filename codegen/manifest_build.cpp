#include "codegen/manifest_build.h"

namespace wg {
namespace {

ManifestUniform manifestUniform(const Program& program, const UniformInfo& u) {
  ManifestUniform m;
  m.name = u.name;
  m.type = u.type;
  m.stages = u.stages;
  if (u.parameter >= 0) {
    const ProgramParameter& p = program.parameters[static_cast<size_t>(u.parameter)];
    ManifestParameter& mp = m.parameter.emplace();
    mp.name = p.name;
    for (int i = 0; i < p.defaultValue.size(); ++i) mp.defaultValue.push_back(p.defaultValue[i]);
    mp.min = p.min;
    mp.max = p.max;
    mp.hint = p.hint;
    mp.description = p.description;
  } else {
    m.builtin = u.builtin;
    m.angularFrequency = u.omega;
  }
  return m;
}

}  // namespace

Manifest buildManifest(const Program& program, const std::vector<std::pair<Target, EmitResult>>& emitted,
                       const std::string& baseName) {
  Manifest m;
  m.graph = program.graphName;
  m.imports = program.importedFiles;
  m.description = program.description;

  for (const auto& [target, er] : emitted) {
    ManifestTarget& t = m.targets.emplace_back();
    t.name = targetName(target);
    const std::string prefix = baseName + "." + t.name + ".";
    for (const auto& sh : er.shaders) {
      ManifestStageFile& f = t.files.emplace_back();
      f.stage = sh.stage;
      f.file = prefix + std::string(stageExtension(sh.stage));
      if (target == Target::Vk450) f.spirv = f.file + ".spv";
    }
  }

  if (!emitted.empty()) {
    const EmitResult& er = emitted.front().second;
    m.attributes = er.attributes;
    for (const auto& u : er.uniforms) m.uniforms.push_back(manifestUniform(program, u));
    m.varyings = er.varyings;
    m.functions = er.functions;
    m.textures = er.textures;
  }
  // Tessellation, per target (GLSL ES 3.00 has none: es300 draws the mesh as it is).
  for (const auto& [target, er] : emitted)
    if (er.tessellation) {
      if (!m.tessellation) m.tessellation.emplace().settings = *er.tessellation;
      m.tessellation->targets.emplace_back(targetName(target));
    }

  // Resources and the passes producing them in table order; the water surface last.
  for (SceneResource r : program.sceneResources()) {
    m.resources.push_back(r);
    m.passes.push_back(sceneResourceRow(r).pass);
  }
  m.passes.push_back(RenderPass::WaterSurface);

  m.nodesTotal = program.totalNodes;
  m.kept.reserve(program.ops.size());
  for (const auto& op : program.ops) m.kept.push_back({op.nodeId, op.spec->type, op.stage, op.mergedIds});
  for (const auto& r : program.removed) m.removed.push_back({r.what, r.reason});
  return m;
}

}  // namespace wg
