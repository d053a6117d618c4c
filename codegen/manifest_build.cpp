#include "codegen/manifest_build.h"
#include "codegen/texture_files.h"

#include <algorithm>
#include <stdexcept>

#include "core/color_parameters.h"

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
    mp.colorSpace = std::string(parameterColorSpace(p.hint));
    mp.description = p.description;
  } else {
    m.builtin = u.builtin;
    m.angularFrequency = u.omega;
  }
  return m;
}

// The size of each listed scene pass (in the order of `passes`), from the `resolution`
// option of the ops that read its resources: the smallest wins, so lowering any one reader
// lowers the pass (one target serves every reader, and `tune` lowers one knob at a time).
// Only passes below 1 are listed, so a graph that sets no resolution has the manifest it
// always had.
std::vector<ManifestPassScale> passScales(const Program& program, const std::vector<RenderPass>& passes) {
  std::vector<ManifestPassScale> out;
  for (RenderPass pass : passes) {
    if (pass == RenderPass::WaterSurface || pass == RenderPass::EnvironmentCubemap || pass == RenderPass::OceanSimulation)
      continue;
    double scale = 1;
    for (const auto& op : program.ops)
      for (SceneResource r : op.spec->resources) {
        auto it = op.options().find(kResolutionOption);
        if (sceneResourceRow(r).pass == pass && it != op.options().end() && it->is_number())
          scale = std::min(scale, it->get<double>());
      }
    if (scale < 1) out.push_back({pass, scale});
  }
  return out;
}

}  // namespace

Manifest buildManifest(const Program& program, const TargetPlans& plans, const std::string& baseName) {
  Manifest m;
  m.graph = program.graphName;
  m.imports = program.importedFiles;
  m.description = program.description;
  m.view = program.view;

  for (size_t i = 0; i < plans.targets.size(); ++i) {
    const Target target = plans.targets[i];
    ManifestTarget& t = m.targets.emplace_back();
    t.name = targetName(target);
    if (writesStageBodies(target)) t.glslVersion = targetGlslVersion(target);
    const std::string prefix = baseName + "." + t.name + ".";
    for (const auto& stage : plans.of(i).stages) {
      ManifestStageFile& f = t.files.emplace_back();
      f.stage = stage.stage;
      f.file = prefix + std::string(stageExtension(stage.stage));
      if (target == Target::Vk450) f.spirv = f.file + ".spv";
      if (writesStageBodies(target)) f.body = f.file + std::string(kStageBodySuffix);
    }
  }

  ShaderPlan noTarget;  // resources and passes still listed when no target is compiled
  if (plans.targets.empty()) planResources(program, noTarget);
  const ShaderPlan& first = plans.targets.empty() ? noTarget : plans.of(0);
  m.attributes = first.attributes;
  for (const auto& u : first.uniforms) m.uniforms.push_back(manifestUniform(program, u));
  m.varyings = first.varyings;
  m.functions = first.functions;
  m.textures = first.textures;
  m.oceans = first.oceans;
  for (auto& t : m.textures)
    if (!t.source.empty()) t.file = textureFileName(baseName, t.name);
  // Tessellation, per target (GLSL ES 3.00 has none: es300 draws the mesh as it is).
  for (size_t i = 0; i < plans.targets.size(); ++i)
    if (const auto& tess = plans.of(i).tessellation) {
      if (!m.tessellation) m.tessellation.emplace().settings = *tess;
      m.tessellation->targets.emplace_back(targetName(plans.targets[i]));
    }
  // Resources and the passes producing them in table order; the water surface last.
  m.resources = first.resources;
  m.passes = first.passes;
  m.passScales = passScales(program, m.passes);

  m.nodesTotal = program.totalNodes;
  m.kept.reserve(program.ops.size());
  for (const auto& op : program.ops) m.kept.push_back({op.nodeId, op.spec->type, op.stage, op.mergedIds});
  for (const auto& r : program.removed) m.removed.push_back({r.what, r.reason});
  return m;
}

}  // namespace wg
