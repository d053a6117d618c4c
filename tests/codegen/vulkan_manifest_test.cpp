// The manifest's "vulkan" section: the std140 offsets it lists are glslang's own offsets of
// the WgUniforms block in the vk450 shaders of every example graph; the layout rules by
// hand for every member type; a manifest whose section disagrees with its uniforms is
// refused when read.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/glslang_reflection.h"
#include "codegen/uniform_block_layout.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

CompileResult compileVk450(const std::string& path) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  EXPECT_TRUE(graph) << path;
  CompileOptions options;
  options.targets = {Target::Vk450};
  auto r = graph ? compileGraph(*graph, defaultRegistry(), options, diags) : std::nullopt;
  EXPECT_TRUE(r) << path;
  return r ? std::move(*r) : CompileResult{};
}

TEST(Std140, OffsetsOfEveryMemberType) {
  // float, vec3 (aligned to 16), float packed into the vec3's last 4 bytes, vec2 (8),
  // mat3 (three 16-byte columns), vec4, mat4, int, bool.
  auto l = std140Layout({Type::Float, Type::Vec3, Type::Float, Type::Vec2, Type::Mat3, Type::Vec4, Type::Mat4, Type::Int,
                         Type::Bool});
  std::vector<size_t> offsets;
  for (const auto& m : l) offsets.push_back(m.offset);
  EXPECT_EQ(offsets, (std::vector<size_t>{0, 16, 28, 32, 48, 96, 112, 176, 180}));
  EXPECT_EQ(std140BlockSize(l), 192u);
  EXPECT_EQ(std140BlockSize({}), 0u);
}

TEST(VulkanManifest, BlockOffsetsAreGlslangsForEveryExampleGraph) {
  for (const auto& path : test::exampleGraphs()) {
    SCOPED_TRACE(path);
    CompileResult r = compileVk450(path);
    std::vector<ShaderSource> shaders;
    for (const auto& f : r.manifest.target("vk450")->files)
      for (const auto& o : r.files)
        if (o.name == f.file) shaders.push_back({f.stage, f.file, o.contents});
    auto glslang = uniformBlockOffsets(Target::Vk450, shaders);
    ASSERT_TRUE(glslang);
    const nlohmann::json vulkan = r.manifest.toJson().at("vulkan");
    if (r.manifest.uniforms.empty()) {
      EXPECT_FALSE(vulkan.contains("uniform_block"));
      continue;
    }
    const auto& members = vulkan.at("uniform_block").at("members");
    ASSERT_EQ(members.size(), r.manifest.uniforms.size());
    ASSERT_EQ(glslang->size(), members.size());
    for (const auto& m : members) EXPECT_EQ(m.at("offset").get<int>(), glslang->at(m.at("name").get<std::string>())) << m.dump();
    EXPECT_EQ(vulkan.at("uniform_block").at("binding"), 0);
    for (size_t i = 0; i < r.manifest.textures.size(); ++i)
      EXPECT_EQ(vulkan.at("textures")[i].at("binding").get<int>(), r.manifest.textures[i].binding);
  }
}

TEST(VulkanManifest, ASectionThatDisagreesIsRefused) {
  CompileResult r = compileVk450(test::sourcePath("graphs/lake.json"));
  nlohmann::json j = r.manifest.toJson();
  EXPECT_NO_THROW(Manifest::fromJson(j));
  nlohmann::json moved = j;
  moved["vulkan"]["uniform_block"]["members"][1]["offset"] = 68;
  EXPECT_THROW(Manifest::fromJson(moved), ManifestError);
  nlohmann::json missing = j;
  missing.erase("vulkan");
  EXPECT_THROW(Manifest::fromJson(missing), ManifestError);
}

}  // namespace
}  // namespace wg
