#include "codegen/manifest.h"

#include "core/ocean_settings.h"

#include <bit>

#include <algorithm>
#include <utility>

#include "codegen/manifest_vulkan.h"
#include "codegen/manifest_webgpu.h"
#include "core/json_text_writer.h"

namespace wg {
namespace {

// Every object below writes its members in byte order of their keys: the writer checks it,
// and it is the order the JSON had when it was built as an nlohmann DOM (a std::map).

void writeStages(JsonTextWriter& w, unsigned stages) {
  w.beginArray();
  if (stages & kVertexStage) w.string("vertex");
  if (stages & kFragmentStage) w.string("fragment");
  w.endArray();
}

// A scalar for one component, else an array.
void writeNumbers(JsonTextWriter& w, const std::vector<double>& v) {
  if (v.size() == 1) return w.number(v[0]);
  w.beginArray();
  for (double d : v) w.number(d);
  w.endArray();
}

void writeStrings(JsonTextWriter& w, const std::vector<std::string>& v) {
  w.beginArray();
  for (const auto& s : v) w.string(s);
  w.endArray();
}

// "three": for the target whose stages have body files (es300), each stage's body file and
// the version it lacks, as a host that writes the version line itself takes them (three.js's
// RawShaderMaterial): {"fragment": {"body_file", "glsl_version"}, "vertex": {...}}.
void writeThreeSection(JsonTextWriter& w, const ManifestTarget& target) {
  w.beginObject();
  for (ShaderStage stage : {ShaderStage::Fragment, ShaderStage::Vertex})  // keys in byte order
    for (const auto& f : target.files)
      if (f.stage == stage && !f.body.empty()) {
        w.key(stage == ShaderStage::Vertex ? "vertex" : "fragment");
        w.beginObject();
        w.member("body_file", f.body);
        w.member("glsl_version", target.glslVersion);
        w.endObject();
      }
  w.endObject();
}

void writeTarget(JsonTextWriter& w, const ManifestTarget& target) {
  // Members named by stage extensions ("frag", "vert", "vert.spv"): gathered, then sorted.
  // Every member is a file (the stages' bodies are named in "three", not here).
  std::vector<std::pair<std::string, const std::string*>> files;
  for (const auto& f : target.files) {
    const std::string ext(stageExtension(f.stage));
    files.emplace_back(ext, &f.file);
    if (!f.spirv.empty()) files.emplace_back(ext + ".spv", &f.spirv);
  }
  std::string entryKey = "entry_points", fromKey = "from";
  if (!target.from.empty()) {
    files.emplace_back(entryKey, nullptr);
    files.emplace_back(fromKey, &target.from);
  }
  std::sort(files.begin(), files.end());
  w.beginObject();
  for (const auto& [key, value] : files) {
    w.key(key);
    if (value) {
      w.string(*value);
      continue;
    }
    std::vector<std::pair<std::string, const std::string*>> entries;
    for (const auto& f : target.files)
      if (!f.entryPoint.empty()) entries.emplace_back(std::string(stageExtension(f.stage)), &f.entryPoint);
    std::sort(entries.begin(), entries.end());
    w.beginObject();
    for (const auto& [stage, entry] : entries) w.member(stage, *entry);
    w.endObject();
  }
  w.endObject();
}

void writeUniform(JsonTextWriter& w, const ManifestUniform& u) {
  w.beginObject();
  const auto& p = u.parameter;
  if (!p && u.builtin == BuiltinUniform::TimePhase) w.memberNumber("angular_frequency", u.angularFrequency);
  if (!p) w.member("builtin", builtinUniformRow(u.builtin).meaning);
  if (p) {
    if (!p->colorSpace.empty()) w.member("color_space", p->colorSpace);
    w.key("default");
    writeNumbers(w, p->defaultValue);
    if (!p->description.empty()) w.member("description", p->description);
    if (!p->hint.empty()) w.member("hint", p->hint);
    if (p->max) w.memberNumber("max", *p->max);
    if (p->min) w.memberNumber("min", *p->min);
  }
  w.member("name", u.name);
  if (p) w.member("parameter", p->name);
  w.key("stages");
  writeStages(w, u.stages);
  w.member("type", typeName(u.type));
  w.endObject();
}

void writeTexture(JsonTextWriter& w, const TextureInfo& t) {
  w.beginObject();
  w.memberInteger("binding", t.binding);
  if (!t.source.empty()) w.member("file", t.file);
  w.member("name", t.name);
  if (t.ocean) {
    w.key("ocean");
    w.beginObject();
    w.memberInteger("cascade", t.ocean->cascade);
    w.member("map", ocean::kOceanMapNames[t.ocean->map]);
    w.memberInteger("ocean", t.ocean->ocean);
    w.endObject();
  }
  if (t.scene) w.member("resource", sceneResourceRow(sceneSamplerRow(*t.scene).resource).name);
  // Only a state other than the default (repeat, linear, linear data) is written, so the
  // manifests of graphs that sample every texture the default way keep their bytes; the
  // entry then holds all three, so a client reads one complete state or none.
  if (!t.source.empty() && !t.sampler.isDefault()) {
    w.key("sampler");
    w.beginObject();
    w.member("color_space", colorSpaceName(t.sampler.colorSpace));
    w.member("filter", filterName(t.sampler.filter));
    w.member("wrap", wrapName(t.sampler.wrap));
    w.endObject();
  }
  if (!t.source.empty()) w.member("source", t.source);
  w.key("stages");
  writeStages(w, t.stages);
  w.member("type", typeName(t.type));
  w.endObject();
}

void writeNodes(JsonTextWriter& w, const Manifest& m) {
  w.beginObject();
  w.key("kept");
  w.beginArray();
  for (const auto& k : m.kept) {
    w.beginObject();
    if (!k.merged.empty()) {
      w.key("merged");
      writeStrings(w, k.merged);
    }
    w.member("node", k.node);
    w.key("stages");
    writeStages(w, k.stages);
    w.member("type", k.type);
    w.endObject();
  }
  w.endArray();
  w.key("removed");
  w.beginArray();
  for (const auto& r : m.removed) {
    w.beginObject();
    w.member("reason", r.reason);
    w.member("what", r.what);
    w.endObject();
  }
  w.endArray();
  w.memberInteger("total", m.nodesTotal);
  w.endObject();
}

// Room for the file with its node lists, which are nearly all of a big graph's manifest:
// each entry's text as dump(2) indents it (an id that needs escapes may go past) and 16 KiB
// for the rest. Reserved once, the text is not copied while it grows and does not hold up
// to twice its size (1.2 MB at 10,000 nodes, kept with the shaders for the compile's end).
size_t nodesTextBound(const Manifest& m) {
  size_t n = 16384;
  for (const auto& k : m.kept) {
    n += 96 + k.node.size() + k.type.size() + 24 * static_cast<size_t>(std::popcount(k.stages));
    if (!k.merged.empty()) n += 32;
    for (const auto& id : k.merged) n += 16 + id.size();
  }
  for (const auto& r : m.removed) n += 64 + r.what.size() + r.reason.size();
  return n;
}

}  // namespace

const ManifestTarget* Manifest::target(std::string_view name) const {
  for (const auto& t : targets)
    if (t.name == name) return &t;
  return nullptr;
}

bool Manifest::lists(RenderPass pass) const { return std::find(passes.begin(), passes.end(), pass) != passes.end(); }

double Manifest::scaleOf(RenderPass pass) const {
  for (const auto& s : passScales)
    if (s.pass == pass) return s.scale;
  return 1;
}

std::string Manifest::fileText() const {
  std::string text;
  text.reserve(nodesTextBound(*this));
  JsonTextWriter w(text);
  w.beginObject();
  w.key("attributes");
  w.beginArray();
  for (const auto& a : attributes) {
    w.beginObject();
    w.memberInteger("location", a.location);
    w.member("name", a.name);
    w.member("type", typeName(a.type));
    w.endObject();
  }
  w.endArray();
  w.key("color");
  w.beginObject();
  w.member("frame", "linear");
  w.member("primaries", "bt709");
  w.key("view");
  w.beginObject();
  w.memberNumber("exposure", view.exposureEv);
  w.member("output", "srgb");
  w.member("tonemap", toneMapperName(view.toneMapper));
  w.endObject();
  w.endObject();
  if (!description.empty()) w.member("description", description);
  w.memberInteger("format", format);
  w.key("functions");
  writeStrings(w, functions);
  w.member("graph", graph);
  if (!imports.empty()) {
    w.key("imports");
    writeStrings(w, imports);
  }
  w.key("nodes");
  writeNodes(w, *this);
  if (!oceans.empty()) {
    w.key("oceans");
    w.beginArray();
    for (const auto& o : oceans) {
      w.beginObject();
      w.key("filtered");
      w.boolean(o.filtered);
      if (!oceanModule.empty()) w.member("module", oceanModule);
      w.member("node", o.nodeId);
      w.key("options");
      w.value(o.options);
      w.endObject();
    }
    w.endArray();
  }
  if (!passScales.empty()) {  // "pass_scales" sorts before "passes"; its keys by name
    std::vector<const ManifestPassScale*> byName;
    for (const auto& p : passScales) byName.push_back(&p);
    std::stable_sort(byName.begin(), byName.end(), [](const ManifestPassScale* a, const ManifestPassScale* b) {
      return renderPassRow(a->pass).name < renderPassRow(b->pass).name;
    });
    w.key("pass_scales");
    w.beginObject();
    for (const ManifestPassScale* p : byName) w.memberNumber(renderPassRow(p->pass).name, p->scale);
    w.endObject();
  }
  w.key("passes");
  w.beginArray();
  for (RenderPass p : passes) w.string(renderPassRow(p).name);
  w.endArray();
  if (!preset.empty()) w.member("preset", preset);
  w.key("resources");
  w.beginArray();
  for (SceneResource r : resources) w.string(sceneResourceRow(r).name);
  w.endArray();
  // Target names are unique; nlohmann's object kept them in byte order.
  std::vector<const ManifestTarget*> byName;
  for (const auto& t : targets) byName.push_back(&t);
  std::stable_sort(byName.begin(), byName.end(), [](const ManifestTarget* a, const ManifestTarget* b) { return a->name < b->name; });
  w.key("targets");
  w.beginObject();
  for (const ManifestTarget* t : byName) {
    w.key(t->name);
    writeTarget(w, *t);
  }
  w.endObject();
  if (tessellation) {
    w.key("tessellation");
    w.beginObject();
    w.memberNumber("factor", tessellation->settings.factor);
    w.memberNumber("max_distance", tessellation->settings.maxDistance);
    w.memberNumber("min_distance", tessellation->settings.minDistance);
    w.memberInteger("patch_vertices", kPatchVertices);
    w.key("targets");
    writeStrings(w, tessellation->targets);
    w.endObject();
  }
  w.key("textures");
  w.beginArray();
  for (const auto& t : textures) writeTexture(w, t);
  w.endArray();
  for (const auto& t : targets)
    if (!t.glslVersion.empty()) {
      w.key("three");
      writeThreeSection(w, t);
    }
  w.key("uniforms");
  w.beginArray();
  for (const auto& u : uniforms) writeUniform(w, u);
  w.endArray();
  w.key("varyings");
  w.beginArray();
  for (const auto& v : varyings) {
    w.beginObject();
    w.member("carries", v.carries);
    w.member("name", v.name);
    w.member("type", typeName(v.type));
    w.endObject();
  }
  w.endArray();
  if (writesVulkanSection(*this)) {
    w.key("vulkan");
    writeVulkanSection(w, *this);
  }
  if (writesWebgpuSection(*this)) {
    w.key("webgpu");
    writeWebgpuSection(w, *this);
  }
  w.endObject();
  text += '\n';
  return text;
}

nlohmann::json Manifest::toJson() const { return nlohmann::json::parse(fileText()); }

}  // namespace wg
