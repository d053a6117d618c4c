// The scene description's WebGPU forms (runtime/webgpu_shader_form.h): a WebGPU host lays out
// its bind groups and uniform buffers from each form's declaration table and hands the GLSL
// to naga unchanged, so the table must say exactly what the text declares. glslang compiles
// each form on its own (the Vulkan rules naga's front end also follows) and its reflection
// gives the bindings, block offsets and sizes and the varyings' locations independently.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "codegen/glslang_reflection.h"
#include "runtime/scene_description.h"
#include "runtime/webgpu_shader_form.h"

namespace wg::rt {
namespace {

using nlohmann::json;

json webgpuForms() { return json::parse(sceneDescriptionJson({}))["webgpu"]["shaders"]; }

ReflectedInterface reflect(const std::string& name, const json& form) {
  const ShaderStage stage = form["stage"] == "vertex" ? ShaderStage::Vertex : ShaderStage::Fragment;
  std::vector<ShaderMessage> errors;
  auto r = reflectedInterface(Target::Vk450, {stage, name, form["glsl"].get<std::string>()}, &errors);
  std::string text;
  for (const auto& e : errors) text += "\n  " + std::to_string(e.line) + ": " + e.text;
  EXPECT_TRUE(r.has_value()) << name << " does not compile:" << text;
  return r.value_or(ReflectedInterface{});
}

std::map<std::string, int> locations(const json& varyings) {
  std::map<std::string, int> out;
  for (const auto& v : varyings) out[v["name"]] = v["location"].get<int>();
  return out;
}

// Every shader the description carries has a WebGPU form.
TEST(WebgpuShaderForms, EveryDescriptionShaderHasOne) {
  const json d = json::parse(sceneDescriptionJson({}));
  std::set<std::string> shaders, forms;
  for (const auto& [name, text] : d["shaders"].items()) shaders.insert(name);
  for (const auto& [name, form] : d["webgpu"]["shaders"].items()) forms.insert(name);
  EXPECT_EQ(forms, shaders);
  EXPECT_GE(forms.size(), 16u);
}

TEST(WebgpuShaderForms, TablesAgreeWithGlslangsReflectionOfTheText) {
  size_t blocks = 0, textures = 0, varyings = 0;
  const json forms = webgpuForms();
  for (const auto& [name, form] : forms.items()) {
    SCOPED_TRACE(name);
    const ReflectedInterface r = reflect(name, form);
    // The uniform block: its binding, every member's offset, the size a buffer must have.
    const json& block = form["uniform_block"];
    if (block.is_null()) {
      EXPECT_TRUE(r.blocks.empty());
      EXPECT_TRUE(r.memberOffsets.empty());
    } else {
      ++blocks;
      ASSERT_EQ(r.blocks.count(block["name"]), 1u);
      const ReflectedInterface::Block& b = r.blocks.at(block["name"]);
      EXPECT_EQ(block["binding"].get<int>(), b.binding);
      EXPECT_EQ(block["size"].get<int>(), (b.size + 15) / 16 * 16);
      std::map<std::string, int> offsets;
      for (const auto& m : block["members"]) offsets[m["name"]] = m["offset"].get<int>();
      EXPECT_EQ(offsets, r.memberOffsets);
    }
    // Textures and samplers: each binding, and nothing bound the table leaves out.
    std::map<std::string, int> bindings;
    for (const auto& t : form["textures"]) bindings[t["glsl_name"]] = t["binding"].get<int>();
    for (const auto& s : form["samplers"]) bindings[s["name"]] = s["binding"].get<int>();
    textures += form["textures"].size();
    EXPECT_EQ(bindings, r.opaqueBindings);
    // Varyings (and a vertex stage's attributes) at the locations the table gives.
    EXPECT_EQ(locations(form["inputs"]), r.inputLocations);
    if (form["stage"] == "vertex") {
      EXPECT_EQ(locations(form["outputs"]), r.outputLocations);
    }
    varyings += form["inputs"].size() + form["outputs"].size();
  }
  // The comparison reached blocks, textures and varyings (not only empty tables).
  EXPECT_GE(blocks, 13u);
  EXPECT_GE(textures, 15u);
  EXPECT_GE(varyings, 20u);
}

// std140 as the runtime's programs need it: a vec3 after a mat4 at 64, a vec3 after a vec4 at
// 80 (16-byte aligned), scalars packed, the size rounded up to 16.
TEST(WebgpuShaderForms, Std140LayoutOfTheRuntimesBlocks) {
  const Std140Layout opaque = std140Layout({{"mat4", "a"}, {"vec4", "b"}, {"vec3", "c"}});
  EXPECT_EQ(opaque.offsets, (std::vector<int>{0, 64, 80}));
  EXPECT_EQ(opaque.size, 96);
  const Std140Layout scalars = std140Layout({{"uint", "a"}, {"float", "b"}, {"int", "c"}});
  EXPECT_EQ(scalars.offsets, (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(scalars.size, 16);
  const Std140Layout mixed = std140Layout({{"float", "a"}, {"vec3", "b"}, {"float", "c"}, {"vec2", "d"}});
  EXPECT_EQ(mixed.offsets, (std::vector<int>{0, 16, 28, 32}));
  EXPECT_EQ(mixed.size, 48);
}

}  // namespace
}  // namespace wg::rt
