// Manifest::fromJson: a manifest file back into the value, refusing what the compiler
// would not have written (an unknown member, pass, resource, builtin or type; a member of
// the wrong kind) with a message that names the entry, so a hand-edited manifest fails
// when it is read, not in the middle of a frame.
#include <algorithm>
#include <initializer_list>
#include <iterator>

#include "codegen/manifest.h"

#include "core/ocean_settings.h"

namespace wg {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& message) { throw ManifestError(message); }

// `what` names the entry in messages: "uniform u_time", "the manifest's \"tessellation\"".
void onlyMembers(const json& object, std::initializer_list<std::string_view> known, const std::string& what) {
  for (const auto& [key, value] : object.items()) {
    bool listed = false;
    for (std::string_view k : known) listed |= key == k;
    if (!listed) fail(what + " has an unknown member \"" + key + "\"");
  }
}

const json* member(const json& object, const char* key) {
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

std::string text(const json& object, const char* key, const std::string& what) {
  const json* v = member(object, key);
  if (!v || !v->is_string()) fail(what + " lacks the string \"" + key + "\"");
  return v->get<std::string>();
}

std::string optionalText(const json& object, const char* key, const std::string& what) {
  return member(object, key) ? text(object, key, what) : std::string();
}

double number(const json& object, const char* key, const std::string& what) {
  const json* v = member(object, key);
  if (!v || !v->is_number()) fail(what + " lacks the number \"" + key + "\"");
  return v->get<double>();
}

int integer(const json& object, const char* key, const std::string& what) {
  const json* v = member(object, key);
  if (!v || !v->is_number_integer()) fail(what + " lacks the integer \"" + key + "\"");
  return v->get<int>();
}

Type typeOf(const json& object, const std::string& what) {
  const std::string name = text(object, "type", what);
  auto t = parseType(name);
  if (!t || *t == Type::Invalid) fail(what + " has an unknown type '" + name + "'");
  return *t;
}

unsigned stagesOf(const json& object, const std::string& what) {
  const json* v = member(object, "stages");
  if (!v || !v->is_array()) fail(what + " lacks the list \"stages\"");
  unsigned stages = 0;
  for (const auto& s : *v) {
    if (s == "vertex") stages |= kVertexStage;
    else if (s == "fragment") stages |= kFragmentStage;
    else fail(what + " lists an unknown stage " + s.dump());
  }
  return stages;
}

std::vector<std::string> texts(const json& list, const std::string& what) {
  if (!list.is_array()) fail(what + " is not a list");
  std::vector<std::string> out;
  for (const auto& s : list) {
    if (!s.is_string()) fail(what + " holds a non-string entry");
    out.push_back(s.get<std::string>());
  }
  return out;
}

// The objects of a top-level list ("uniforms", ...); an absent list has none.
const json& objects(const json& manifest, const char* key) {
  static const json kNone = json::array();
  const json* list = member(manifest, key);
  if (!list) return kNone;
  const std::string what = std::string("the manifest's \"") + key + "\"";
  if (!list->is_array()) fail(what + " is not a list");
  for (const auto& e : *list)
    if (!e.is_object()) fail(what + " holds an entry that is not an object");
  return *list;
}

std::vector<RenderPass> passesOf(const json& manifest) {
  const json* list = member(manifest, "passes");
  if (!list || !list->is_array()) fail("the manifest has no \"passes\" list");
  std::vector<RenderPass> passes;
  for (const auto& p : *list) {
    if (!p.is_string()) fail("the manifest's \"passes\" list holds a non-string entry");
    const std::string name = p.get<std::string>();
    auto pass = parseRenderPass(name);
    // The opaque scene and the output transform are the runtime's: a manifest never lists them.
    if (!pass || *pass == RenderPass::OpaqueScene || *pass == RenderPass::OutputTransform) fail("the manifest lists an unknown pass '" + name + "'");
    passes.push_back(*pass);
  }
  return passes;
}

// "pass_scales": {"depth_prepass": 0.5}: listed scene passes with a size in [0.25, 1) of
// the frame's (1 is what an absent entry means, so the compiler never writes it), in the
// order of "passes", as the compiler builds them.
std::vector<ManifestPassScale> passScalesOf(const json& j, const std::vector<RenderPass>& passes) {
  if (!j.is_object()) fail("the manifest's \"pass_scales\" is not an object");
  for (const auto& [name, value] : j.items()) {
    const std::string what = "the manifest's \"pass_scales\" entry '" + name + "'";
    auto pass = parseRenderPass(name);
    if (!pass) fail("the manifest's \"pass_scales\" names an unknown pass '" + name + "'");
    if (*pass == RenderPass::WaterSurface || *pass == RenderPass::OpaqueScene || *pass == RenderPass::EnvironmentCubemap ||
        *pass == RenderPass::OceanSimulation)
      fail(what + ": only a frame-sized scene pass can be scaled");
    if (std::find(passes.begin(), passes.end(), *pass) == passes.end()) fail(what + " names a pass \"passes\" does not list");
    if (!value.is_number() || !(value.get<double>() >= kMinResolution && value.get<double>() < 1))
      fail(what + " must be a number >= 0.25 and < 1 (1, the frame's size, is left out)");
  }
  std::vector<ManifestPassScale> out;
  for (RenderPass p : passes) {
    auto it = j.find(std::string(renderPassRow(p).name));
    if (it != j.end() && std::none_of(out.begin(), out.end(), [&](const ManifestPassScale& s) { return s.pass == p; }))
      out.push_back({p, it->get<double>()});
  }
  return out;
}

ManifestTarget targetOf(const std::string& name, const json& files) {
  const std::string what = "target " + name;
  if (!files.is_object()) fail(what + " is not an object");
  ManifestTarget t;
  t.name = name;
  const json* entryPoints = member(files, "entry_points");
  if (entryPoints && !entryPoints->is_object()) fail(what + "'s \"entry_points\" is not an object");
  if (!entryPoints != !member(files, "from")) fail(what + " has one of \"entry_points\" and \"from\" without the other");
  if (entryPoints) t.from = text(files, "from", what);
  size_t known = entryPoints ? 2 : 0;
  for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::TessControl, ShaderStage::TessEvaluation, ShaderStage::Fragment}) {
    const std::string ext(stageExtension(stage));
    if (!member(files, ext.c_str())) continue;
    ManifestStageFile f;
    f.stage = stage;
    f.file = text(files, ext.c_str(), what);
    f.spirv = optionalText(files, (ext + ".spv").c_str(), what);
    if (entryPoints) f.entryPoint = text(*entryPoints, ext.c_str(), what + "'s \"entry_points\"");
    known += f.spirv.empty() ? 1 : 2;
    t.files.push_back(std::move(f));
  }
  if (known != files.size()) fail(what + " has a member that is not a shader stage (vert, tesc, tese, frag, <stage>.spv)");
  if (entryPoints && entryPoints->size() != t.files.size()) fail(what + "'s \"entry_points\" names a stage it has no file for");
  return t;
}

// "three": the es300 stages' body files with the version they lack, one entry per stage
// of the es300 target (written by writeThreeSection).
void threeSectionOf(const json& three, Manifest& m) {
  const std::string what = "the manifest's \"three\"";
  if (!three.is_object()) fail(what + " is not an object");
  onlyMembers(three, {"vertex", "fragment"}, what);
  ManifestTarget* es300 = nullptr;
  for (auto& t : m.targets)
    if (t.name == "es300") es300 = &t;
  if (!es300) fail(what + " names body files of the es300 target, which \"targets\" does not list");
  for (auto& f : es300->files) {
    const char* stage = f.stage == ShaderStage::Vertex ? "vertex" : f.stage == ShaderStage::Fragment ? "fragment" : "";
    const json* entry = member(three, stage);
    if (!entry || !entry->is_object()) fail(what + " has no \"" + stage + "\" object for the es300 stage " + f.file);
    onlyMembers(*entry, {"body_file", "glsl_version"}, what + "'s \"" + stage + "\"");
    f.body = text(*entry, "body_file", what + "'s \"" + stage + "\"");
    const std::string version = text(*entry, "glsl_version", what + "'s \"" + stage + "\"");
    if (!es300->glslVersion.empty() && version != es300->glslVersion) fail(what + " gives its stages two versions");
    es300->glslVersion = version;
  }
  if (three.size() != es300->files.size()) fail(what + " names a stage the es300 target does not have");
}

AttributeInfo attributeOf(const json& a) {
  AttributeInfo out;
  out.name = text(a, "name", "a manifest attribute");
  const std::string what = "attribute " + out.name;
  onlyMembers(a, {"name", "type", "location"}, what);
  out.type = typeOf(a, what);
  out.location = integer(a, "location", what);
  return out;
}

std::vector<double> defaultOf(const json& u, const std::string& what) {
  const json* v = member(u, "default");
  std::vector<double> values;
  if (v && v->is_number()) values.push_back(v->get<double>());
  if (v && v->is_array())
    for (const auto& x : *v) {
      if (!x.is_number()) return {};
      values.push_back(x.get<double>());
    }
  if (values.empty()) fail(what + " has no numeric \"default\"");
  return values;
}

ManifestUniform uniformOf(const json& u) {
  ManifestUniform out;
  out.name = text(u, "name", "a manifest uniform");
  const std::string what = "uniform " + out.name;
  out.type = typeOf(u, what);
  out.stages = stagesOf(u, what);
  if (member(u, "parameter")) {
    onlyMembers(u, {"name", "type", "stages", "parameter", "default", "min", "max", "hint", "color_space", "description"}, what);
    ManifestParameter& p = out.parameter.emplace();
    p.name = text(u, "parameter", what);
    p.defaultValue = defaultOf(u, "parameter " + what);
    if (member(u, "min")) p.min = number(u, "min", what);
    if (member(u, "max")) p.max = number(u, "max", what);
    p.hint = optionalText(u, "hint", what);
    p.colorSpace = optionalText(u, "color_space", what);
    if (!p.colorSpace.empty() && p.colorSpace != "srgb") fail(what + ": unknown color_space '" + p.colorSpace + "' (srgb or absent)");
    p.description = optionalText(u, "description", what);
    return out;
  }
  const std::string meaning = text(u, "builtin", what);
  // A manifest written by the removed --derived-uniforms switch: its shaders read values
  // that no runtime computes any more (each shader now computes them itself).
  if (meaning == "derived")
    fail(what + " is a derived uniform (\"builtin\": \"derived\"), which watergraph no longer has: "
                "compile the graph again");
  auto builtin = parseBuiltinUniform(meaning);
  if (!builtin) fail(what + " asks for builtin '" + meaning + "', which is not a builtin uniform");
  out.builtin = *builtin;
  if (out.builtin == BuiltinUniform::TimePhase) {
    onlyMembers(u, {"name", "type", "stages", "builtin", "angular_frequency"}, what);
    out.angularFrequency = number(u, "angular_frequency", what);
  } else {
    onlyMembers(u, {"name", "type", "stages", "builtin"}, what);
  }
  return out;
}

VaryingInfo varyingOf(const json& v) {
  VaryingInfo out;
  out.name = text(v, "name", "a manifest varying");
  const std::string what = "varying " + out.name;
  onlyMembers(v, {"name", "type", "carries"}, what);
  out.type = typeOf(v, what);
  out.carries = text(v, "carries", what);
  return out;
}

// A node texture's "sampler": all three members, each one of its names.
SamplerState samplerOf(const json& s, const std::string& texture) {
  const std::string what = texture + "'s \"sampler\"";
  if (!s.is_object()) fail(what + " is not an object");
  onlyMembers(s, {"wrap", "filter", "color_space"}, what);
  auto named = [&](const char* key, auto parse, const char* choices) {
    const std::string name = text(s, key, what);
    auto v = parse(name);
    if (!v) fail(what + " has an unknown " + key + " '" + name + "' (" + choices + ")");
    return *v;
  };
  SamplerState out;
  out.wrap = named("wrap", parseWrap, "repeat, clamp or mirror");
  out.filter = named("filter", parseFilter, "nearest, linear or mipmapped");
  out.colorSpace = named("color_space", parseColorSpace, "linear or srgb");
  // The compiler leaves the default state out; reading it would not give the file back.
  if (out.isDefault()) fail(what + " is the default state (repeat, linear, linear), which a manifest leaves out");
  return out;
}

TextureInfo textureOf(const json& t) {
  TextureInfo out;
  out.name = text(t, "name", "a manifest texture");
  const std::string what = "texture " + out.name;
  onlyMembers(t, {"name", "type", "binding", "stages", "source", "file", "resource", "sampler", "ocean"}, what);
  out.type = typeOf(t, what);
  out.binding = integer(t, "binding", what);
  out.stages = stagesOf(t, what);
  if (member(t, "source") && member(t, "resource")) fail(what + " has both a \"source\" and a \"resource\"");
  if (member(t, "sampler") && !member(t, "source")) fail(what + " has a \"sampler\" but no \"source\"");
  if (member(t, "source")) {
    out.source = text(t, "source", what);
    // The PNG `compile --textures` writes: a plain file name beside the manifest.
    out.file = text(t, "file", what);
    if (out.file.empty() || out.file.find_first_of("/\\") != std::string::npos || out.file == "." || out.file == "..")
      fail(what + " has a \"file\" that is not a file name beside the manifest");
    if (const json* s = member(t, "sampler")) out.sampler = samplerOf(*s, what);
  } else if (const json* o = member(t, "ocean")) {
    if (member(t, "resource") || member(t, "file")) fail(what + " is an ocean map and has a \"resource\" or a \"file\"");
    const std::string whatMap = what + "'s \"ocean\"";
    if (!o->is_object()) fail(whatMap + " is not an object");
    onlyMembers(*o, {"ocean", "cascade", "map"}, whatMap);
    OceanMapRef ref;
    ref.ocean = integer(*o, "ocean", whatMap);
    ref.cascade = integer(*o, "cascade", whatMap);
    const std::string map = text(*o, "map", whatMap);
    auto known = std::find(std::begin(ocean::kOceanMapNames), std::end(ocean::kOceanMapNames), map);
    if (known == std::end(ocean::kOceanMapNames)) fail(whatMap + " names an unknown map '" + map + "'");
    ref.map = static_cast<int>(known - std::begin(ocean::kOceanMapNames));
    if (ref.ocean < 0 || ref.cascade < 0 || ref.cascade >= ocean::kMaxCascades)
      fail(whatMap + " names an ocean or cascade out of range");
    if (out.type != Type::Sampler2D) fail(what + " is an ocean map and must be a sampler2D");
    out.ocean = ref;
  } else if (member(t, "resource")) {
    // A scene texture is one of its resource's samplers, named as the shader declares it.
    const std::string resource = text(t, "resource", what);
    if (member(t, "file")) fail(what + " has a \"file\" but no \"source\"");
    if (!parseSceneResource(resource)) fail(what + " names an unknown scene resource '" + resource + "'");
    const SceneSamplerRow* sampler = findSceneSampler(out.name);
    if (!sampler || sceneResourceRow(sampler->resource).name != resource)
      fail(what + " is not a sampler of scene resource '" + resource + "'");
    out.scene = sampler->id;
  } else {
    fail(what + " has neither a \"source\" nor a \"resource\"");
  }
  return out;
}

ManifestTessellation tessellationOf(const json& t) {
  const std::string what = "the manifest's \"tessellation\"";
  if (!t.is_object()) fail(what + " is not an object");
  onlyMembers(t, {"patch_vertices", "min_distance", "max_distance", "factor", "targets"}, what);
  if (integer(t, "patch_vertices", what) != kPatchVertices)
    fail(what + " has patches of other than " + std::to_string(kPatchVertices) + " vertices");
  ManifestTessellation out;
  out.settings.minDistance = number(t, "min_distance", what);
  out.settings.maxDistance = number(t, "max_distance", what);
  out.settings.factor = number(t, "factor", what);
  const json* targets = member(t, "targets");
  if (!targets) fail(what + " lacks the list \"targets\"");
  out.targets = texts(*targets, what + "'s \"targets\"");
  return out;
}

void nodesOf(const json& nodes, Manifest& m) {
  const std::string what = "the manifest's \"nodes\"";
  if (!nodes.is_object()) fail(what + " is not an object");
  onlyMembers(nodes, {"total", "kept", "removed"}, what);
  m.nodesTotal = integer(nodes, "total", what);
  for (const char* list : {"kept", "removed"})
    if (const json* l = member(nodes, list); !l || !l->is_array()) fail(what + " lacks the list \"" + list + "\"");
  for (const auto& k : nodes["kept"]) {
    if (!k.is_object()) fail(what + "'s \"kept\" holds an entry that is not an object");
    ManifestKeptNode& n = m.kept.emplace_back();
    n.node = text(k, "node", "a kept node");
    const std::string nodeWhat = "kept node " + n.node;
    onlyMembers(k, {"node", "type", "stages", "merged"}, nodeWhat);
    n.type = text(k, "type", nodeWhat);
    n.stages = stagesOf(k, nodeWhat);
    if (const json* merged = member(k, "merged")) n.merged = texts(*merged, nodeWhat + "'s \"merged\"");
  }
  for (const auto& r : nodes["removed"]) {
    if (!r.is_object()) fail(what + "'s \"removed\" holds an entry that is not an object");
    onlyMembers(r, {"what", "reason"}, "a removed node");
    m.removed.push_back({text(r, "what", "a removed node"), text(r, "reason", "a removed node")});
  }
}

// "color": the contract this runtime implements (linear bt709 frame, sRGB output) and the
// graph's view. Absent in manifests written before it existed: the default view.
ViewTransform colorContractOf(const json& c) {
  const std::string what = "the manifest's \"color\"";
  if (!c.is_object()) fail(what + " is not an object");
  onlyMembers(c, {"frame", "primaries", "view"}, what);
  if (text(c, "frame", what) != "linear") fail(what + " has a \"frame\" other than \"linear\"");
  if (text(c, "primaries", what) != "bt709") fail(what + " has \"primaries\" other than \"bt709\"");
  const json* v = member(c, "view");
  if (!v || !v->is_object()) fail(what + " has no \"view\" object");
  onlyMembers(*v, {"exposure", "output", "tonemap"}, what + "'s view");
  if (text(*v, "output", what + "'s view") != "srgb") fail(what + "'s view has an \"output\" other than \"srgb\"");
  ViewTransform view;
  const std::string mapper = text(*v, "tonemap", what + "'s view");
  auto t = parseToneMapper(mapper);
  if (!t) fail(what + "'s view names an unknown tone mapper '" + mapper + "'");
  view.toneMapper = *t;
  const json* e = member(*v, "exposure");
  if (!e || !e->is_number() || !(e->get<double>() >= kMinExposureEv && e->get<double>() <= kMaxExposureEv))
    fail(what + "'s view has no \"exposure\" number in [-20, 20]");
  view.exposureEv = e->get<double>();
  return view;
}

}  // namespace

Manifest Manifest::fromJson(const json& j) {
  if (!j.is_object()) fail("the manifest is not a JSON object");
  Manifest m;
  m.passes = passesOf(j);
  if (const json* scales = member(j, "pass_scales")) m.passScales = passScalesOf(*scales, m.passes);
  onlyMembers(j,
              {"format", "graph", "description", "preset", "imports", "targets", "attributes", "uniforms", "varyings", "functions",
               "textures", "tessellation", "resources", "passes", "pass_scales", "nodes", "vulkan", "webgpu", "color",
               "oceans", "three"},
              "the manifest");
  if (member(j, "format") && integer(j, "format", "the manifest") != kManifestFormat)
    fail("the manifest has format " + j["format"].dump() + "; this runtime reads format " + std::to_string(kManifestFormat));
  m.graph = optionalText(j, "graph", "the manifest");
  m.description = optionalText(j, "description", "the manifest");
  if (const json* color = member(j, "color")) m.view = colorContractOf(*color);
  m.preset = optionalText(j, "preset", "the manifest");
  if (const json* imports = member(j, "imports")) m.imports = texts(*imports, "the manifest's \"imports\"");
  if (const json* targets = member(j, "targets")) {
    if (!targets->is_object()) fail("the manifest's \"targets\" is not an object");
    for (const auto& [name, files] : targets->items()) m.targets.push_back(targetOf(name, files));
  }
  if (const json* three = member(j, "three")) threeSectionOf(*three, m);
  for (const auto& a : objects(j, "attributes")) m.attributes.push_back(attributeOf(a));
  for (const auto& u : objects(j, "uniforms")) m.uniforms.push_back(uniformOf(u));
  for (const auto& v : objects(j, "varyings")) m.varyings.push_back(varyingOf(v));
  if (const json* functions = member(j, "functions")) m.functions = texts(*functions, "the manifest's \"functions\"");
  for (const auto& t : objects(j, "textures")) m.textures.push_back(textureOf(t));
  for (const auto& o : objects(j, "oceans")) {
    onlyMembers(o, {"filtered", "module", "node", "options"}, "an entry of the manifest's \"oceans\"");
    OceanInfo info;
    info.nodeId = text(o, "node", "an entry of the manifest's \"oceans\"");
    const json* filtered = member(o, "filtered");
    if (!filtered || !filtered->is_boolean())
      fail("ocean " + info.nodeId + " has no \"filtered\" true or false (a manifest written before it: compile the graph again)");
    info.filtered = filtered->get<bool>();
    // The web clients' module (codegen/ocean_module_js.h): one file for all the oceans.
    if (member(o, "module")) {
      std::string module = text(o, "module", "ocean " + info.nodeId + "'s \"module\"");
      if (!m.oceans.empty() && module != m.oceanModule) fail("ocean " + info.nodeId + " names another \"module\" than the first ocean");
      m.oceanModule = std::move(module);
    }
    const json* options = member(o, "options");
    if (!options || !options->is_object()) fail("ocean " + info.nodeId + " has no \"options\" object");
    info.options = *options;
    m.oceans.push_back(std::move(info));
  }
  if (m.oceans.empty() == m.lists(RenderPass::OceanSimulation))
    fail(m.oceans.empty() ? "the manifest lists the ocean_simulation pass but no \"oceans\""
                          : "the manifest has \"oceans\" but does not list the ocean_simulation pass");
  for (const auto& t : m.textures)
    if (t.ocean && (t.ocean->ocean >= static_cast<int>(m.oceans.size())))
      fail("texture " + t.name + " reads ocean " + std::to_string(t.ocean->ocean) + ", which \"oceans\" does not list");
  // "filtered" is what the compiler decided from these same maps: a manifest where the two
  // disagree was edited.
  for (size_t o = 0; o < m.oceans.size(); ++o) {
    const bool moments = std::any_of(m.textures.begin(), m.textures.end(), [o](const TextureInfo& t) {
      return t.ocean && t.ocean->ocean == static_cast<int>(o) && t.ocean->map == ocean::kMomentsMap;
    });
    if (moments != m.oceans[o].filtered)
      fail("ocean " + m.oceans[o].nodeId + " has \"filtered\": " + (m.oceans[o].filtered ? "true" : "false") + ", but " +
           (moments ? "a texture reads its moments map" : "no texture reads its moments map"));
  }
  if (const json* t = member(j, "tessellation")) m.tessellation = tessellationOf(*t);
  if (const json* resources = member(j, "resources"))
    for (const std::string& name : texts(*resources, "the manifest's \"resources\"")) {
      auto r = parseSceneResource(name);
      if (!r) fail("the manifest lists an unknown scene resource '" + name + "'");
      m.resources.push_back(*r);
    }
  if (const json* nodes = member(j, "nodes")) nodesOf(*nodes, m);
  // "vulkan" is derived from the rest (codegen/manifest_vulkan.h): it must be what the
  // compiler would write for it, so an engine and the runtime read the same bindings.
  const json* vulkan = member(j, "vulkan");
  const json written = json::parse(m.fileText());
  if (written.contains("vulkan") != (vulkan != nullptr))
    fail(vulkan ? "the manifest has a \"vulkan\" section but no vk450 target" : "the manifest has a vk450 target but no \"vulkan\" section");
  if (vulkan && *vulkan != written["vulkan"])
    fail("the manifest's \"vulkan\" section does not match its uniforms, textures, attributes and varyings");
  // "webgpu" likewise (codegen/manifest_webgpu.h), written with the wgsl target.
  const json* webgpu = member(j, "webgpu");
  if (written.contains("webgpu") != (webgpu != nullptr))
    fail(webgpu ? "the manifest has a \"webgpu\" section but no wgsl target" : "the manifest has a wgsl target but no \"webgpu\" section");
  if (webgpu && *webgpu != written["webgpu"])
    fail("the manifest's \"webgpu\" section does not match its uniforms, textures, attributes and varyings");
  return m;
}

}  // namespace wg
