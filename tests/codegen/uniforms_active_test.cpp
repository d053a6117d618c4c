// "Model only what a scene needs": every uniform and sampler a shader declares is read.
// For every example graph and every target, glslang's reflection (TProgram::buildReflection,
// which lists only what the linked code reads) must report each declared uniform active.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "codegen/glslang_validate.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

std::vector<ShaderSource> sourcesOf(const EmitResult& er, Target target) {
  std::vector<ShaderSource> out;
  for (const auto& sh : er.shaders)
    out.push_back({sh.stage, "g." + std::string(targetName(target)) + "." + std::string(stageExtension(sh.stage)), sh.text});
  return out;
}

// The declared uniforms and samplers of `er` that reflection does not find read.
std::vector<std::string> inactiveDeclarations(const EmitResult& er, Target target) {
  auto active = activeUniforms(target, sourcesOf(er, target));
  if (!active) return {"<the shaders do not link>"};
  std::vector<std::string> declared;
  for (const auto& u : er.uniforms) declared.push_back(u.name);
  for (const auto& t : er.textures) declared.push_back(t.name);
  std::vector<std::string> inactive;
  for (const auto& d : declared)
    if (!std::binary_search(active->begin(), active->end(), d)) inactive.push_back(d);
  return inactive;
}

TEST(UniformsActive, EveryDeclaredUniformOfEveryExampleGraphIsRead) {
  auto graphs = test::exampleGraphs();
  ASSERT_FALSE(graphs.empty());
  for (const auto& path : graphs) {
    Diagnostics diags;
    auto g = loadGraphFile(path, diags);
    ASSERT_TRUE(g) << path;
    auto p = buildProgram(*g, defaultRegistry(), diags);
    ASSERT_TRUE(p) << path;
    for (Target t : allTargets()) {
      EmitResult er = emitProgram(*p, t, "g.json");
      EXPECT_FALSE(er.uniforms.empty()) << path;  // every example reads at least a builtin
      auto inactive = inactiveDeclarations(er, t);
      std::string list;
      for (const auto& n : inactive) list += " " + n;
      EXPECT_TRUE(inactive.empty()) << std::filesystem::path(path).filename().string() << " " << targetName(t)
                                    << ": declared but never read:" << list;
    }
  }
}

// The check itself: a uniform declared and never read is reported, so the test above can
// fail (reflection is not simply listing declarations).
TEST(UniformsActive, ReflectionLeavesOutAnUnreadUniform) {
  std::vector<ShaderSource> shaders = {
      {ShaderStage::Vertex, "t.vert",
       "#version 330 core\nlayout(location = 0) in vec3 a_position;\nuniform mat4 u_view_projection;\n"
       "void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); }\n"},
      {ShaderStage::Fragment, "t.frag",
       "#version 330 core\nlayout(location = 0) out vec4 o_color;\nuniform float u_read;\nuniform float u_unread;\n"
       "void main() { o_color = vec4(u_read); }\n"}};
  auto active = activeUniforms(Target::Glsl330, shaders);
  ASSERT_TRUE(active);
  EXPECT_TRUE(std::binary_search(active->begin(), active->end(), "u_read"));
  EXPECT_TRUE(std::binary_search(active->begin(), active->end(), "u_view_projection"));
  EXPECT_FALSE(std::binary_search(active->begin(), active->end(), "u_unread"));
}

}  // namespace
}  // namespace wg
