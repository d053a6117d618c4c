// emitPrograms writes the stage bodies once for every target that tessellates alike: each
// of its results must equal emitProgram's for that target alone (text, line map and
// interface), with tessellation allowed (stylized tessellates glsl330 and vk450, not
// es300) and not.
#include <gtest/gtest.h>

#include <algorithm>

#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

void expectSame(const EmitResult& alone, const EmitResult& shared, const std::string& what) {
  ASSERT_EQ(alone.shaders.size(), shared.shaders.size()) << what;
  for (size_t s = 0; s < alone.shaders.size(); ++s) {
    EXPECT_EQ(alone.shaders[s].stage, shared.shaders[s].stage) << what;
    EXPECT_EQ(alone.shaders[s].text, shared.shaders[s].text) << what << " shader " << s;
    EXPECT_EQ(alone.shaders[s].lineOp, shared.shaders[s].lineOp) << what << " shader " << s;
  }
  EXPECT_EQ(alone.functions, shared.functions) << what;
  EXPECT_EQ(alone.uniforms.size(), shared.uniforms.size()) << what;
  EXPECT_EQ(alone.textures.size(), shared.textures.size()) << what;
  EXPECT_EQ(alone.varyings.size(), shared.varyings.size()) << what;
  EXPECT_EQ(alone.tessellation.has_value(), shared.tessellation.has_value()) << what;
}

TEST(EmitShared, EveryTargetMatchesItsOwnEmitForEveryExampleGraph) {
  bool sawSplit = false;  // a graph where the targets tessellate differently
  for (const auto& path : test::exampleGraphs()) {
    Diagnostics diags;
    auto graph = loadGraphFile(path, diags);
    ASSERT_TRUE(graph) << path;
    auto program = buildProgram(*graph, defaultRegistry(), diags);
    ASSERT_TRUE(program) << path;
    for (bool tess : {true, false}) {
      std::vector<EmitResult> shared = emitPrograms(*program, allTargets(), "g.json", tess);
      ASSERT_EQ(shared.size(), allTargets().size());
      std::vector<bool> tessellated;
      for (size_t t = 0; t < allTargets().size(); ++t) {
        EmitResult alone = emitProgram(*program, allTargets()[t], "g.json", EmitMode::Shader, tess);
        tessellated.push_back(alone.tessellation.has_value());
        expectSame(alone, shared[t], path + " " + std::string(targetName(allTargets()[t])) + (tess ? "" : " flat"));
      }
      sawSplit = sawSplit || std::count(tessellated.begin(), tessellated.end(), true) % tessellated.size() != 0;
    }
  }
  EXPECT_TRUE(sawSplit) << "no example graph tessellates on some targets only: the grouping is untested";
}

}  // namespace
}  // namespace wg
