// The editor's preview floats the built-in scene's buoys (the "buoys" box beside the time
// and sun controls): LivePreview::floatingBuoys places them on the compiled graph's water
// with the parameter values the preview shows, those set since the last compile included,
// clamped into their ranges as the renderer clamps them.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/graph_io.h"
#include "editor/live_preview.h"
#include "nodes/registry.h"
#include "query_samples.h"
#include "runtime/egl_context.h"
#include "runtime/floating_buoys.h"
#include "test_support.h"

namespace wg::editor {
namespace preview_buoys_test {

TEST(LivePreviewBuoys, FloatOnTheShownWaterWithTheParametersSetSinceTheCompile) {
  auto ctx = rt::EglContext::create(rt::GlApi::DesktopGl45);
  const std::string dir = test::makeTempDir("wg_preview_buoys");
  Diagnostics diags;
  auto graph = loadGraphFile(test::writeMixedGraph(dir), diags);
  ASSERT_TRUE(graph);
  rt::RenderSettings settings;
  settings.width = 64, settings.height = 36;
  LivePreview preview(settings);
  ASSERT_TRUE(preview.rebuild(*graph, defaultRegistry(), diags));
  const wg::Program& program = preview.compiled()->program;
  std::vector<Value> parameters;
  size_t lift = program.parameters.size();
  for (size_t i = 0; i < program.parameters.size(); ++i) {
    parameters.push_back(program.parameters[i].defaultValue);
    if (program.parameters[i].name == "lift") lift = i;
  }
  ASSERT_LT(lift, parameters.size());
  const std::vector<rt::FloatingPose> before = preview.floatingBuoys(2.0);
  EXPECT_EQ(before, rt::floatingBuoys(program, parameters, 2.0));
  // A uniform set from the inspector moves them as it moves the water.
  ASSERT_TRUE(preview.setParameter("lift", {0.9}));
  parameters[lift] = Value::scalar(0.9);
  const std::vector<rt::FloatingPose> after = preview.floatingBuoys(2.0);
  EXPECT_EQ(after, rt::floatingBuoys(program, parameters, 2.0));
  EXPECT_NE(after, before);
  // Out of its range [0, 1] it is clamped as the renderer clamps the uniform: 5 rides as 1,
  // NaN as the lower end 0.
  ASSERT_TRUE(preview.setParameter("lift", {5.0}));
  parameters[lift] = Value::scalar(1.0);
  EXPECT_EQ(preview.floatingBuoys(2.0), rt::floatingBuoys(program, parameters, 2.0));
  ASSERT_TRUE(preview.setParameter("lift", {std::nan("")}));
  parameters[lift] = Value::scalar(0.0);
  const std::vector<rt::FloatingPose> low = preview.floatingBuoys(2.0);
  EXPECT_EQ(low, rt::floatingBuoys(program, parameters, 2.0));
  for (const auto& pose : low) EXPECT_TRUE(std::isfinite(pose.position.y));
  // A rebuild takes its values from the graph again.
  ASSERT_TRUE(preview.rebuild(*graph, defaultRegistry(), diags));
  EXPECT_EQ(preview.floatingBuoys(2.0), before);
  std::filesystem::remove_all(dir);
}

}  // namespace preview_buoys_test
}  // namespace wg::editor
