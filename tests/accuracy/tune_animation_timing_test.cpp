// tune's timed frames are those of an animation (accuracy/tune_render.h): each at a new
// time, so a graph with a spectral ocean pays its simulation in every timed frame, as an
// animation does. Frames at one held time would find the maps already at their time and
// time the drawing alone (runtime/ocean_simulation.h): a knob that saves simulation work
// (fft_size, foam_step) would save nothing tune can see.
#include <gtest/gtest.h>

#include "accuracy/tune_knobs.h"
#include "accuracy/tune_render.h"
#include "core/graph_io.h"

namespace wg::accuracy {
namespace {

Graph smallSea() {
  Diagnostics d;
  auto g = parseGraph(R"({"version": 1, "name": "small_sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [40], "fft_size": 64}},
    {"id": "displaced", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
    {"id": "surface", "type": "vertex_output", "inputs": {"position": "displaced.position", "normal": "displaced.normal"}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": "displaced.undisplaced"}}],
    "outputs": {"vertex": {"position": "surface.position", "normal": "surface.normal"},
                "fragment": {"color": "detail.normal"}}})",
                      "small_sea.json", d);
  EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  return *g;
}

TEST(TuneAnimationTiming, EveryTimedFrameOfAnOceanRunsItsSimulation) {
  Graph g = smallSea();
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, graphKnobs(g), Target::Glsl330, unchanged);
  ASSERT_FALSE(knobs.empty());
  TuneSweep sweep;
  sweep.cameras = {"above", "topdown"};
  sweep.times = {3.5};
  sweep.width = 32, sweep.height = 18;
  sweep.runs = 3;
  GlTuneMeasurements m(g, knobs, sweep);
  TuneConfig exact;
  for (const auto& k : knobs) exact.push_back(static_cast<int>(k.levels.size()) - 1);
  TuneConfig cheap = exact;
  cheap[0] = 0;
  EXPECT_EQ(m.timedSimulationUpdates(), 0);
  std::vector<TuneCost> costs = m.cost({exact, cheap});
  ASSERT_EQ(costs.size(), 2u);
  // Two configurations, three repeats, two cameras: twelve frames, each at its own time.
  EXPECT_EQ(m.timedSimulationUpdates(), 12);
  for (const auto& c : costs) EXPECT_EQ(c.repeats.size(), 3u);
  // The error is still measured on still frames (each at its time alone): the reference
  // rendered again is the reference.
  TuneError e = m.error(exact);
  EXPECT_TRUE(e.finite);
  EXPECT_EQ(e.maxAbsError, 0.0) << e.worstFrame;
}

// A graph without an ocean runs no simulation in its timed frames.
TEST(TuneAnimationTiming, AGraphWithoutAnOceanRunsNoSimulation) {
  Diagnostics d;
  auto g = parseGraph(R"({"version": 1, "name": "plain", "nodes": [{"id": "f", "type": "fresnel"},
    {"id": "tint", "type": "mix", "inputs": {"a": [0, 0.15, 0.25], "b": [0.6, 0.75, 0.9], "t": "f.reflectance"}}],
    "outputs": {"fragment": {"color": "tint.out"}}})",
                      "plain.json", d);
  ASSERT_TRUE(g);
  std::vector<TuneKnob> knobs = graphKnobs(*g);
  ASSERT_FALSE(knobs.empty());
  TuneSweep sweep;
  sweep.cameras = {"above"};
  sweep.times = {1};
  sweep.width = 16, sweep.height = 9;
  sweep.runs = 2;
  GlTuneMeasurements m(*g, knobs, sweep);
  TuneConfig exact;
  for (const auto& k : knobs) exact.push_back(static_cast<int>(k.levels.size()) - 1);
  m.cost({exact});
  EXPECT_EQ(m.timedSimulationUpdates(), 0);
}

}  // namespace
}  // namespace wg::accuracy
