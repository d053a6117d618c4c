// The ocean simulation runs once per time (runtime/ocean_simulation.h): an update to the time
// its maps hold runs nothing, and Renderers of the same oceans can share one simulation
// (check's frames and its read-back frames), which then runs once for all of them and gives
// each the frame it would render with its own.
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/ocean_simulation.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
// Named, not anonymous: the unity build joins this file with the other runtime tests.
namespace ocean_sharing_test {

// A 64^2 sea with foam on its first cascade; `shortTile` changes the oceans (not shareable).
CompileResult compileSea(int shortTile) {
  Diagnostics diags;
  auto graph = parseGraph(R"({"version": 1, "name": "sharing_test", "nodes": [
      {"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [100, )" +
                              std::to_string(shortTile) + R"(], "foam_cascades": 1, "foam_decay": 0.3}},
      {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
      {"id": "foam", "type": "ocean_foam", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}}],
      "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": "foam.foam"}}})",
                          "sharing_test.json", diags);
  CompileOptions o;
  o.targets = {Target::Glsl330};
  auto result = graph ? compileGraph(*graph, defaultRegistry(), o, diags) : std::nullopt;
  if (!result) throw std::runtime_error("the test graph does not compile");
  return std::move(*result);
}

TEST(OceanSimulationSharing, AnUpdateToTheTimeTheMapsHoldRunsNothing) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  CompileResult sea = compileSea(10);
  OceanSimulation sim(sea.manifest.oceans, sea.manifest.textures, SceneShaderApi::Gl330);
  sim.update(2.0);
  EXPECT_EQ(sim.updatesRun(), 1);
  EXPECT_EQ(sim.lastFoamSteps(), 16);  // K = 15 (5 x 0.3 s / 0.1 s) + 1
  sim.update(2.0);
  EXPECT_EQ(sim.updatesRun(), 1);
  EXPECT_EQ(sim.lastFoamSteps(), 0);
  sim.update(2.05);  // the same foam step, another time: the cascades run again
  EXPECT_EQ(sim.updatesRun(), 2);
  sim.setFoamHistory(FoamHistory::Continue);  // the same time, another history: it runs
  sim.update(2.05);
  EXPECT_EQ(sim.updatesRun(), 3);
}

TEST(OceanSimulationSharing, RenderersOfTheSameOceansShareOneSimulation) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  CompileResult sea = compileSea(10);
  RenderSettings settings = test::smallSettings();
  settings.width = 64, settings.height = 36;
  const auto water = waterShaderSources(sea, Target::Glsl330);
  Renderer own(sea.manifest, water, settings, false, textureOrigins(sea));
  Renderer first(sea.manifest, water, settings, false, textureOrigins(sea));
  Renderer second(sea.manifest, water, settings, false, textureOrigins(sea), nullptr, first.oceanSimulation());
  ASSERT_NE(first.oceanSimulation(), nullptr);
  EXPECT_EQ(second.oceanSimulation(), first.oceanSimulation());
  EXPECT_NE(own.oceanSimulation(), first.oceanSimulation());

  own.renderFrame();
  first.renderFrame();
  second.renderFrame();
  EXPECT_EQ(first.oceanSimulation()->updatesRun(), 1);  // once for both
  // Bit for bit: also the GL state the frame's passes find after a simulation that ran and
  // after one that did not (the simulation turns depth testing off; the water pass needs it
  // on: without it 1,176 of these values differed).
  const Image alone = own.readRgba32f(), shared = second.readRgba32f();
  ASSERT_EQ(alone.rgba32f.size(), shared.rgba32f.size());
  size_t differ = 0;
  for (size_t i = 0; i < alone.rgba32f.size(); ++i)
    if (alone.rgba32f[i] != shared.rgba32f[i]) {
      if (differ < 5) ADD_FAILURE() << "value " << i << ": " << alone.rgba32f[i] << " vs " << shared.rgba32f[i];
      ++differ;
    }
  EXPECT_EQ(differ, 0u);
  double lit = 0;  // the frame shows foam, so the comparison reaches the shared foam map
  for (size_t i = 0; i < alone.rgba32f.size(); i += 4) lit += alone.rgba32f[i];
  EXPECT_GT(lit, 0.0);

  // Another time for both: the simulation runs once more.
  SceneOptions later = settings.scene;
  later.time = 9.25f;
  first.setScene(later);
  second.setScene(later);
  first.renderFrame();
  second.renderFrame();
  EXPECT_EQ(first.oceanSimulation()->updatesRun(), 2);

  // A simulation of other oceans is refused, not silently read.
  CompileResult other = compileSea(20);
  EXPECT_THROW(Renderer(other.manifest, waterShaderSources(other, Target::Glsl330), settings, false, textureOrigins(other),
                        nullptr, first.oceanSimulation()),
               std::logic_error);
}

}  // namespace ocean_sharing_test
}  // namespace wg::rt
