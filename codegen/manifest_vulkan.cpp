// The manifest's "vulkan" section: what an engine loading the vk450 SPIR-V must bind and
// assume, derived from the interface (nothing here is stored in the Manifest value; it is
// written whenever vk450 was compiled, and a manifest read back must carry the same).
#include "codegen/manifest_vulkan.h"

#include "codegen/shader_interface.h"
#include "codegen/uniform_block_layout.h"

namespace wg {
namespace {

const char* vertexFormat(Type t) {
  switch (t) {
    case Type::Float: return "VK_FORMAT_R32_SFLOAT";
    case Type::Vec2: return "VK_FORMAT_R32G32_SFLOAT";
    case Type::Vec3: return "VK_FORMAT_R32G32B32_SFLOAT";
    case Type::Vec4: return "VK_FORMAT_R32G32B32A32_SFLOAT";
    default: return "";
  }
}

// The conventions the generated shaders assume (docs/ecosystem.md, "Loading vk450 in your
// engine", says the same at length). Keys in byte order.
constexpr std::pair<const char*, const char*> kConventions[] = {
    {"clip_space",
     "OpenGL's x right, y up; no y flip in the shaders or the projection. Depth is Vulkan's: "
     "u_projection and u_view_projection are a GL projection times the correction z' = (z + w) / 2"},
    {"depth_range", "[0, 1], compare LESS_OR_EQUAL, cleared to 1; depth values the graph reads equal OpenGL's window depths"},
    {"front_face",
     "triangles counter-clockwise in OpenGL's y-up window are front faces: VK_FRONT_FACE_CLOCKWISE; the water is drawn "
     "without culling"},
    {"image_rows",
     "row 0 of every image the water draws into or samples is the bottom row of the view (OpenGL's order): the viewport "
     "is (0, 0, width, height), positive height; flip the frame when presenting it"},
    {"matrices", "column-major, std140: mat4 64 bytes, mat3 three 16-byte columns"},
};

}  // namespace

void writeVulkanSection(JsonTextWriter& w, const Manifest& m) {
  w.beginObject();
  w.key("conventions");
  w.beginObject();
  for (const auto& [k, v] : kConventions) w.member(k, v);
  w.endObject();
  w.key("push_constants");  // none: every value is in the uniform block
  w.beginArray();
  w.endArray();
  w.key("textures");
  w.beginArray();
  for (const auto& t : m.textures) {
    w.beginObject();
    w.memberInteger("binding", t.binding);
    w.member("descriptor", "VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER");
    w.member("name", t.name);
    w.memberInteger("set", 0);
    w.endObject();
  }
  w.endArray();
  std::vector<Type> types;
  for (const auto& u : m.uniforms) types.push_back(u.type);
  const std::vector<BlockMember> layout = std140Layout(types);
  if (!m.uniforms.empty()) {
    w.key("uniform_block");
    w.beginObject();
    w.memberInteger("binding", iface::kUniformBlockBinding);
    w.member("layout", "std140");
    w.key("members");
    w.beginArray();
    for (size_t i = 0; i < m.uniforms.size(); ++i) {
      w.beginObject();
      w.member("name", m.uniforms[i].name);
      w.memberInteger("offset", static_cast<long long>(layout[i].offset));
      w.member("type", typeName(m.uniforms[i].type));
      w.endObject();
    }
    w.endArray();
    w.member("name", iface::kUniformBlock);
    w.memberInteger("set", 0);
    w.memberInteger("size", static_cast<long long>(std140BlockSize(layout)));
    w.endObject();
  }
  writeVertexInterface(w, m, vertexFormat);
  w.endObject();
}

void writeVertexInterface(JsonTextWriter& w, const Manifest& m, const char* (*format)(Type)) {
  w.key("varyings");  // between the last geometry stage and the fragment stage
  w.beginArray();
  for (size_t i = 0; i < m.varyings.size(); ++i) {
    w.beginObject();
    w.memberInteger("location", static_cast<long long>(i));
    w.member("name", m.varyings[i].name);
    w.endObject();
  }
  w.endArray();
  w.key("vertex_inputs");
  w.beginArray();
  for (const auto& a : m.attributes) {
    w.beginObject();
    w.member("format", format(a.type));
    w.memberInteger("location", a.location);
    w.member("name", a.name);
    w.endObject();
  }
  w.endArray();
}

bool writesVulkanSection(const Manifest& m) { return m.target(targetName(Target::Vk450)) != nullptr; }

}  // namespace wg
