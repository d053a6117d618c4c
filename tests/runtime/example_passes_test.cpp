// Model only what a scene needs: every example graph runs exactly the passes its nodes
// need, and creates only their render targets. A new graph in graphs/ must be added here,
// so its pass set is a decision, not an accident.
#include <algorithm>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "runtime/pass_plan.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

// The passes beyond opaque_scene and water_surface, which every graph runs.
const std::map<std::string, std::set<std::string>>& expectedPasses() {
  static const std::map<std::string, std::set<std::string>> m = {
      // the classic WebGL water renderer: reflection and refraction passes; water depth from the depth buffer
      {"classic_webgl", {"depth_prepass", "planar_reflection", "refraction"}},
      // the deferred water article: the deferred pass with depth, colour and the sky for SSR's fallback
      {"deferred_underwater", {"depth_prepass", "scene_color_copy", "deferred_water", "environment_cubemap"}},
      // the advanced shaders tutorial: cube map and planar reflection, grabbed refraction, depth tint and foam
      {"tutorial_pbr", {"environment_cubemap", "depth_prepass", "planar_reflection", "scene_color_copy"}},
      // the stylized water shader: grabbed refraction, depth colouring and caustics, planar reflection
      {"stylized", {"depth_prepass", "planar_reflection", "scene_color_copy"}},
      // the top-down water plan: top-down water shades from its own waves: no scene pass at all
      {"topdown", {}},
      // open sea: only the sky is reflected
      {"ocean", {"environment_cubemap"}},
      {"pool", {"environment_cubemap", "depth_prepass", "scene_color_copy"}},
      {"river", {"environment_cubemap", "depth_prepass", "scene_color_copy"}},
      // the first examples: depth from the position, the sky as a colour
      {"lake", {}},
      {"lagoon", {}},
      {"caustic_pool", {}},
      {"shelf", {}},
      // the spectral sea: its cascades simulated first, then the sky it reflects
      {"open_ocean", {"ocean_simulation", "environment_cubemap"}},
  };
  return m;
}

TEST(ExamplePasses, EveryGraphRunsExactlyItsPasses) {
  for (const auto& name : test::exampleGraphNames()) {
    SCOPED_TRACE(name);
    auto it = expectedPasses().find(name);
    ASSERT_NE(it, expectedPasses().end()) << "graphs/" << name << ".json has no expected pass set in this test";
    CompileResult r = test::compileExample(name);
    PassPlan plan = planPasses(r.manifest, PlanOptions{});
    std::set<std::string> ran;
    for (PassKind k : plan.passes) ran.insert(passName(k));
    std::set<std::string> want = it->second;
    want.insert({"opaque_scene", "water_surface", "output_transform"});
    EXPECT_EQ(ran, want);
    // One target per pass that makes one, plus the frame; nothing for passes that do not run.
    for (const auto& t : plan.targets)
      EXPECT_TRUE(t.name == "frame" || want.count(passName(t.producedBy))) << t.name;
  }
}

TEST(ExamplePasses, TheTableNamesOnlyExistingGraphs) {
  auto names = test::exampleGraphNames();
  for (const auto& [name, passes] : expectedPasses())
    EXPECT_TRUE(std::find(names.begin(), names.end(), name) != names.end()) << name << " is not in graphs/";
}

}  // namespace
}  // namespace wg::rt
