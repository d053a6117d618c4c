#include "codegen/manifest.h"

#include <algorithm>
#include <utility>

namespace wg {
namespace {

nlohmann::json stagesJson(unsigned stages) {
  nlohmann::json a = nlohmann::json::array();
  if (stages & kVertexStage) a.push_back("vertex");
  if (stages & kFragmentStage) a.push_back("fragment");
  return a;
}

// A scalar for one component, else an array.
nlohmann::json numbersJson(const std::vector<double>& v) {
  if (v.size() == 1) return v[0];
  return v;
}

nlohmann::json targetJson(const ManifestTarget& target) {
  nlohmann::json t = nlohmann::json::object();
  nlohmann::json entryPoints = nlohmann::json::object();
  for (const auto& f : target.files) {
    const std::string ext(stageExtension(f.stage));
    t[ext] = f.file;
    if (!f.spirv.empty()) t[ext + ".spv"] = f.spirv;
    if (!f.entryPoint.empty()) entryPoints[ext] = f.entryPoint;
  }
  if (!target.from.empty()) {
    t["entry_points"] = std::move(entryPoints);
    t["from"] = target.from;
  }
  return t;
}

nlohmann::json uniformJson(const ManifestUniform& u) {
  nlohmann::json j{{"name", u.name}, {"type", std::string(typeName(u.type))}, {"stages", stagesJson(u.stages)}};
  if (const auto& p = u.parameter) {
    j["parameter"] = p->name;
    j["default"] = numbersJson(p->defaultValue);
    if (p->min) j["min"] = *p->min;
    if (p->max) j["max"] = *p->max;
    if (!p->hint.empty()) j["hint"] = p->hint;
    if (!p->description.empty()) j["description"] = p->description;
  } else {
    j["builtin"] = std::string(builtinUniformRow(u.builtin).meaning);
    if (u.builtin == BuiltinUniform::TimePhase) j["angular_frequency"] = u.angularFrequency;
  }
  return j;
}

nlohmann::json textureJson(const TextureInfo& t) {
  nlohmann::json j{{"name", t.name}, {"type", std::string(typeName(t.type))}, {"binding", t.binding},
                   {"stages", stagesJson(t.stages)}};
  if (!t.source.empty()) j["source"] = t.source;
  // Only a state other than the default (repeat, linear, linear data) is written, so the
  // manifests of graphs that sample every texture the default way keep their bytes; the
  // entry then holds all three, so a client reads one complete state or none.
  if (!t.source.empty() && !t.sampler.isDefault())
    j["sampler"] = {{"wrap", std::string(wrapName(t.sampler.wrap))},
                    {"filter", std::string(filterName(t.sampler.filter))},
                    {"color_space", std::string(colorSpaceName(t.sampler.colorSpace))}};
  if (t.scene) j["resource"] = std::string(sceneResourceRow(sceneSamplerRow(*t.scene).resource).name);
  return j;
}

}  // namespace

const ManifestTarget* Manifest::target(std::string_view name) const {
  for (const auto& t : targets)
    if (t.name == name) return &t;
  return nullptr;
}

bool Manifest::lists(RenderPass pass) const { return std::find(passes.begin(), passes.end(), pass) != passes.end(); }

nlohmann::json Manifest::toJson() const {
  nlohmann::json m;
  m["format"] = format;
  m["graph"] = graph;
  if (!description.empty()) m["description"] = description;
  if (!preset.empty()) m["preset"] = preset;
  if (!imports.empty()) m["imports"] = imports;

  nlohmann::json& targetsJson = m["targets"] = nlohmann::json::object();
  for (const auto& t : targets) targetsJson[t.name] = targetJson(t);

  nlohmann::json& attributesJson = m["attributes"] = nlohmann::json::array();
  for (const auto& a : attributes)
    attributesJson.push_back({{"name", a.name}, {"type", std::string(typeName(a.type))}, {"location", a.location}});
  nlohmann::json& uniformsJson = m["uniforms"] = nlohmann::json::array();
  for (const auto& u : uniforms) uniformsJson.push_back(uniformJson(u));
  nlohmann::json& varyingsJson = m["varyings"] = nlohmann::json::array();
  for (const auto& v : varyings)
    varyingsJson.push_back({{"name", v.name}, {"type", std::string(typeName(v.type))}, {"carries", v.carries}});
  m["functions"] = functions;
  nlohmann::json& texturesJson = m["textures"] = nlohmann::json::array();
  for (const auto& t : textures) texturesJson.push_back(textureJson(t));

  if (tessellation) {
    nlohmann::json& t = m["tessellation"];
    t["patch_vertices"] = kPatchVertices;
    t["min_distance"] = tessellation->settings.minDistance;
    t["max_distance"] = tessellation->settings.maxDistance;
    t["factor"] = tessellation->settings.factor;
    t["targets"] = tessellation->targets;
  }

  nlohmann::json& resourcesJson = m["resources"] = nlohmann::json::array();
  for (SceneResource r : resources) resourcesJson.push_back(std::string(sceneResourceRow(r).name));
  nlohmann::json& passesJson = m["passes"] = nlohmann::json::array();
  for (RenderPass p : passes) passesJson.push_back(std::string(renderPassRow(p).name));

  nlohmann::json& nodes = m["nodes"];
  nodes["total"] = nodesTotal;
  nlohmann::json& keptJson = nodes["kept"] = nlohmann::json::array();
  for (const auto& k : kept) {
    nlohmann::json j{{"node", k.node}, {"type", k.type}, {"stages", stagesJson(k.stages)}};
    if (!k.merged.empty()) j["merged"] = k.merged;
    keptJson.push_back(std::move(j));
  }
  nlohmann::json& removedJson = nodes["removed"] = nlohmann::json::array();
  for (const auto& r : removed) removedJson.push_back({{"what", r.what}, {"reason", r.reason}});
  return m;
}

}  // namespace wg
