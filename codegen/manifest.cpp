#include "codegen/manifest.h"

#include <utility>

namespace wg {
namespace {

nlohmann::json valueJson(const Value& v) {
  if (v.size() == 1) return v[0];
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

nlohmann::json stagesJson(unsigned stages) {
  nlohmann::json a = nlohmann::json::array();
  if (stages & kVertexStage) a.push_back("vertex");
  if (stages & kFragmentStage) a.push_back("fragment");
  return a;
}

}  // namespace

nlohmann::json buildManifest(const Program& program, const std::vector<std::pair<Target, EmitResult>>& emitted,
                             const std::string& baseName) {
  nlohmann::json m;
  m["format"] = kManifestFormat;
  m["graph"] = program.graphName;
  if (!program.description.empty()) m["description"] = program.description;

  nlohmann::json targets = nlohmann::json::object();
  for (const auto& [target, er] : emitted) {
    nlohmann::json t;
    std::string prefix = baseName + "." + std::string(targetName(target)) + ".";
    for (const auto& sh : er.shaders) {
      std::string ext(stageExtension(sh.stage));
      t[ext] = prefix + ext;
      if (target == Target::Vk450) t[ext + ".spv"] = prefix + ext + ".spv";
    }
    targets[std::string(targetName(target))] = std::move(t);
  }
  m["targets"] = std::move(targets);

  // The interface is the same for every target (names, order); take it from the first.
  if (!emitted.empty()) {
    const EmitResult& er = emitted.front().second;
    nlohmann::json attributes = nlohmann::json::array();
    for (const auto& a : er.attributes)
      attributes.push_back({{"name", a.name}, {"type", std::string(typeName(a.type))}, {"location", a.location}});
    m["attributes"] = std::move(attributes);
    nlohmann::json uniforms = nlohmann::json::array();
    for (const auto& u : er.uniforms) {
      nlohmann::json j{{"name", u.name}, {"type", std::string(typeName(u.type))}, {"stages", stagesJson(u.stages)}};
      if (u.parameter >= 0) {
        const ProgramParameter& p = program.parameters[static_cast<size_t>(u.parameter)];
        j["parameter"] = p.name;
        j["default"] = valueJson(p.defaultValue);
        if (p.min) j["min"] = *p.min;
        if (p.max) j["max"] = *p.max;
        if (!p.hint.empty()) j["hint"] = p.hint;
        if (!p.description.empty()) j["description"] = p.description;
      } else {
        j["builtin"] = std::string(builtinUniformRow(u.builtin).meaning);
        if (u.builtin == BuiltinUniform::TimePhase) j["angular_frequency"] = u.omega;
      }
      uniforms.push_back(std::move(j));
    }
    m["uniforms"] = std::move(uniforms);
    nlohmann::json varyings = nlohmann::json::array();
    for (const auto& v : er.varyings)
      varyings.push_back({{"name", v.name}, {"type", std::string(typeName(v.type))}, {"carries", v.carries}});
    m["varyings"] = std::move(varyings);
    m["functions"] = er.functions;
    nlohmann::json textures = nlohmann::json::array();
    for (const auto& t : er.textures) {
      nlohmann::json j{{"name", t.name}, {"type", std::string(typeName(t.type))}, {"binding", t.binding},
                       {"stages", stagesJson(t.stages)}};
      if (!t.source.empty()) j["source"] = t.source;
      if (t.scene) j["resource"] = std::string(sceneResourceRow(sceneSamplerRow(*t.scene).resource).name);
      textures.push_back(std::move(j));
    }
    m["textures"] = std::move(textures);
  }
  // Tessellation, per target (GLSL ES 3.00 has none: es300 draws the mesh as it is).
  for (const auto& [target, er] : emitted)
    if (er.tessellation) {
      nlohmann::json& t = m["tessellation"];
      t["patch_vertices"] = 3;
      t["min_distance"] = er.tessellation->minDistance;
      t["max_distance"] = er.tessellation->maxDistance;
      t["factor"] = er.tessellation->factor;
      t["targets"].push_back(std::string(targetName(target)));
    }
  // Resources and the passes producing them in table order; the water surface last.
  nlohmann::json& resources = m["resources"] = nlohmann::json::array();
  nlohmann::json& passes = m["passes"] = nlohmann::json::array();
  for (SceneResource r : program.sceneResources()) {
    const SceneResourceRow& row = sceneResourceRow(r);
    resources.push_back(std::string(row.name));
    passes.push_back(std::string(renderPassRow(row.pass).name));
  }
  passes.push_back(std::string(renderPassRow(RenderPass::WaterSurface).name));

  nlohmann::json kept = nlohmann::json::array();
  for (const auto& op : program.ops) {
    nlohmann::json k{{"node", op.nodeId}, {"type", op.spec->type}, {"stages", stagesJson(op.stage)}};
    if (!op.mergedIds.empty()) k["merged"] = op.mergedIds;
    kept.push_back(std::move(k));
  }
  nlohmann::json removed = nlohmann::json::array();
  for (const auto& r : program.removed) removed.push_back({{"what", r.what}, {"reason", r.reason}});
  // Moved in, not copied: an initializer list would copy both arrays (one object per op).
  nlohmann::json& nodes = m["nodes"];
  nodes["total"] = program.totalNodes;
  nodes["kept"] = std::move(kept);
  nodes["removed"] = std::move(removed);
  return m;
}

}  // namespace wg
