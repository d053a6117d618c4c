// The manifest's "webgpu" section (codegen/manifest_webgpu.h).
#include "codegen/manifest_webgpu.h"

#include "codegen/emit_wgsl.h"
#include "codegen/manifest_vulkan.h"

namespace wg {
namespace {

const char* webgpuVertexFormat(Type t) {
  switch (t) {
    case Type::Float: return "float32";
    case Type::Vec2: return "float32x2";
    case Type::Vec3: return "float32x3";
    case Type::Vec4: return "float32x4";
    default: return "";
  }
}

// What a host must set up around GRAPH.wgsl (docs/integration.md, "WebGPU"). Keys in byte order.
constexpr std::pair<const char*, const char*> kWebgpuConventions[] = {
    {"clip_space",
     "the matrices are OpenGL's (the same uniforms as every GLSL target); vs_main converts its clip position to "
     "WebGPU's: y negated, z' = (z + w) / 2"},
    {"depth", "depth values the graph reads equal OpenGL's window depths in [0, 1]; compare less-equal, cleared to 1"},
    {"front_face", "y is negated in clip space, so triangles counter-clockwise in OpenGL are clockwise here: frontFace \"cw\"; "
                   "the water is drawn without culling"},
    {"image_rows",
     "row 0 of every target the water draws into or samples is the bottom row of the view (OpenGL's order), and "
     "@builtin(position) equals gl_FragCoord; flip the frame when presenting it"},
    {"uniform_bools", "a bool uniform is a u32 in the buffer (WGSL's bool is not host-shareable): 0 false, 1 true"},
};

}  // namespace

void writeWebgpuSection(JsonTextWriter& w, const Manifest& m) {
  w.beginObject();
  w.key("bindings");
  w.beginArray();
  bool anyUniform = false;
  for (const auto& u : m.uniforms) anyUniform |= !isSampler(u.type);
  auto binding = [&w](int number, const char* kind, const std::string& name, const std::string& of) {
    w.beginObject();
    w.memberInteger("binding", number);
    w.memberInteger("group", 0);
    w.member("kind", kind);
    w.member("name", name);
    if (!of.empty()) w.member("texture", of);
    w.endObject();
  };
  if (anyUniform) binding(kWgslUniformBinding, "uniform_buffer", kWgslUniformVariable, "");
  for (size_t i = 0; i < m.textures.size(); ++i) {
    const TextureInfo& t = m.textures[i];
    binding(wgslTextureBinding(i), t.type == Type::SamplerCube ? "texture_cube" : "texture_2d", t.name, t.name);
    binding(wgslTextureBinding(i) + 1, "sampler", t.name + kWgslSamplerSuffix, t.name);
  }
  w.endArray();
  w.key("conventions");
  w.beginObject();
  for (const auto& [k, v] : kWebgpuConventions) w.member(k, v);
  w.endObject();
  w.key("entry_points");
  w.beginObject();
  w.member("fragment", "fs_main");
  w.member("vertex", "vs_main");
  w.endObject();
  if (anyUniform) {
    w.key("uniform_buffer");
    w.beginObject();
    w.member("layout", "wgsl uniform address space");
    w.key("members");
    w.beginArray();
    size_t offset = 0;
    for (const auto& u : m.uniforms) {
      if (isSampler(u.type)) continue;
      WgslUniformMember member = wgslUniformMember(offset, u.type);
      offset = member.offset + member.size;
      w.beginObject();
      w.member("name", u.name);
      w.memberInteger("offset", static_cast<long long>(member.offset));
      w.memberInteger("size", static_cast<long long>(member.size));
      w.member("type", typeName(u.type));
      w.endObject();
    }
    w.endArray();
    w.member("name", kWgslUniformVariable);
    w.memberInteger("size", static_cast<long long>(wgslUniformBufferSize(offset)));
    w.endObject();
  }
  writeVertexInterface(w, m, webgpuVertexFormat);
  w.endObject();
}

bool writesWebgpuSection(const Manifest& m) { return m.target(kWgslTargetName) != nullptr; }

}  // namespace wg
