// The WebGPU form of the runtime's shaders and its declaration table (runtime/webgpu_shader_form.h).
#include "runtime/webgpu_shader_form.h"

#include <stdexcept>

namespace wg::rt {
namespace {

using nlohmann::json;

// std140 base alignment and size of the constant types the runtime's shaders use.
struct Std140Type {
  const char* name;
  int align, size;
};
constexpr Std140Type kStd140Types[] = {{"float", 4, 4}, {"int", 4, 4},   {"uint", 4, 4},   {"vec2", 8, 8},
                                       {"vec3", 16, 12}, {"vec4", 16, 16}, {"mat4", 16, 64}};

Std140Type std140Type(const std::string& type) {
  for (const Std140Type& t : kStd140Types)
    if (type == t.name) return t;
  throw std::logic_error("a runtime shader constant of type " + type + ", which has no std140 layout here");
}

bool isUintTexture(const ShaderMember& t) {
  if (t.type == "usampler2D") return true;
  if (t.type == "sampler2D") return false;
  throw std::logic_error("a runtime shader texture " + t.name + " of type " + t.type +
                         ", which has no WebGPU form here");
}

std::string textureName(const ShaderMember& t) { return "wg_texture_" + t.name; }
int textureBinding(size_t i) { return kWebgpuBlockBinding + 1 + static_cast<int>(i); }

std::string varying(const ShaderVarying& v, const char* direction) {
  std::string s;
  std::string location = std::to_string(v.location);
  if (!v.define.empty()) {
    s = "#ifndef " + v.define + "\n#define " + v.define + " " + location + "\n#endif\n";
    location = v.define;
  }
  return s + "layout(location = " + location + ") " + (v.flat ? "flat " : "") + direction + " " + v.type + " " +
         v.name + ";\n";
}

// `attributes`: a vertex stage's inputs, which are not interpolated.
json varyingsTable(const std::vector<ShaderVarying>& varyings, bool attributes = false) {
  json out = json::array();
  for (const ShaderVarying& v : varyings) {
    json row = {{"name", v.name}, {"type", v.type}, {"location", v.location}};
    if (!attributes) row["interpolation"] = v.flat ? "flat" : "perspective";
    if (!v.define.empty()) row["define"] = v.define;
    out.push_back(row);
  }
  return out;
}

}  // namespace

Std140Layout std140Layout(const std::vector<ShaderMember>& constants) {
  Std140Layout l;
  int end = 0;
  for (const ShaderMember& c : constants) {
    const Std140Type t = std140Type(c.type);
    const int offset = (end + t.align - 1) / t.align * t.align;
    l.offsets.push_back(offset);
    end = offset + t.size;
  }
  l.size = (end + 15) / 16 * 16;
  return l;
}

std::string webgpuDeclarations(const ShaderInterface& i) {
  std::string s;
  if (!i.constants.empty()) {
    s += "layout(set = 0, binding = " + std::to_string(kWebgpuBlockBinding) + ", std140) uniform " + i.block + " {\n";
    for (const ShaderMember& c : i.constants) s += "  " + c.type + " " + c.name + ";\n";
    s += "};\n";
  }
  for (size_t t = 0; t < i.textures.size(); ++t) {
    const ShaderMember& texture = i.textures[t];
    const char* prefix = isUintTexture(texture) ? "u" : "";
    s += "layout(set = 0, binding = " + std::to_string(textureBinding(t)) + ") uniform " + prefix + "texture2D " +
         textureName(texture) + ";\n#define " + texture.name + " " + prefix + "sampler2D(" + textureName(texture) + ", " +
         kWebgpuSamplerName + ")\n";
  }
  if (!i.textures.empty())
    s += "layout(set = 0, binding = " + std::to_string(textureBinding(i.textures.size())) + ") uniform sampler " +
         kWebgpuSamplerName + ";\n";
  for (const ShaderVarying& v : i.inputs) s += varying(v, "in");
  for (const ShaderVarying& v : i.outputs) s += varying(v, "out");
  return s;
}

std::string webgpuVertexBodyBefore() { return "#define main wg_runtime_main\n"; }

std::string webgpuVertexBodyAfter() {
  return "#undef main\nvoid main() {\n  wg_runtime_main();\n"
         "  gl_Position = vec4(gl_Position.x, -gl_Position.y, 0.5 * (gl_Position.z + gl_Position.w), gl_Position.w);\n}\n";
}

json webgpuShaderTable(const std::string& stage, const std::string& glsl, const ShaderInterface& i) {
  json t = {{"stage", stage}, {"entry_point", "main"}, {"glsl", glsl}, {"uniform_block", nullptr}};
  if (!i.constants.empty()) {
    const Std140Layout layout = std140Layout(i.constants);
    json members = json::array();
    for (size_t c = 0; c < i.constants.size(); ++c)
      members.push_back({{"name", i.constants[c].name}, {"type", i.constants[c].type}, {"offset", layout.offsets[c]}});
    t["uniform_block"] = {{"name", i.block}, {"group", 0}, {"binding", kWebgpuBlockBinding}, {"size", layout.size},
                          {"members", members}};
  }
  json textures = json::array(), samplers = json::array();
  for (size_t n = 0; n < i.textures.size(); ++n)
    textures.push_back({{"name", i.textures[n].name}, {"glsl_name", textureName(i.textures[n])}, {"group", 0},
                        {"binding", textureBinding(n)},
                        {"sample_type", isUintTexture(i.textures[n]) ? "uint" : "unfilterable-float"},
                        {"view_dimension", "2d"}});
  // Every read is a texelFetch (WGSL textureLoad): one nearest sampler, never filtering.
  if (!i.textures.empty())
    samplers.push_back({{"name", kWebgpuSamplerName}, {"group", 0}, {"binding", textureBinding(i.textures.size())},
                        {"type", "non-filtering"}});
  t["textures"] = textures;
  t["samplers"] = samplers;
  t["inputs"] = varyingsTable(i.inputs, stage == "vertex");
  t["outputs"] = varyingsTable(i.outputs);
  return t;
}

}  // namespace wg::rt
