#pragma once
// The measurements of `watergraph tune` on the GL runtime: each configuration of a graph's
// quality knobs is compiled, rendered into RGBA32F frames over a sweep of views (cameras x
// times) and compared frame by frame with the reference's (every knob at its most exact
// level); its cost is CPU ms per megapixel (the process's CPU time, llvmpipe's threads
// included, across each frame of an animation: a spectral ocean's simulation included),
// timed in interleaved repeats beside the other configurations of the same round, plus the
// fragment shader's SPIR-V instruction count after spirv-opt -O.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accuracy/tune_knobs.h"
#include "accuracy/tune_search.h"
#include "codegen/target.h"
#include "core/graph.h"
#include "runtime/memory_budget.h"
#include "runtime/scene.h"

namespace wg::rt {
class EglContext;
}

namespace wg::accuracy {

struct TuneSweep {
  std::vector<std::string> cameras;  // camera presets; empty: above, grazing, topdown (+ underwater for deferred water)
  std::vector<double> times{1.0, 3.5, 20.0};
  int width = 160, height = 90;
  int runs = 9;  // interleaved timed repeats (tune_search.h: how many must agree)
  Target target = Target::Glsl330;
};

class GlTuneMeasurements : public TuneMeasurements {
 public:
  // Creates its GL context and renders the reference. Throws std::runtime_error for a
  // configuration that does not compile or an unknown camera, rt::RuntimeError for GL.
  GlTuneMeasurements(const Graph& graph, std::vector<TuneKnob> knobs, TuneSweep sweep);
  ~GlTuneMeasurements() override;

  TuneError error(const TuneConfig& config) override;
  std::vector<TuneCost> cost(const std::vector<TuneConfig>& configs) override;
  TuneError verify(const TuneConfig& config) override;

  // Configurations or the graph as written (nullopt), timed together.
  std::vector<TuneCost> costOf(const std::vector<std::optional<TuneConfig>>& configs);
  TuneError asWrittenError();

  const std::vector<std::string>& viewLabels() const { return labels_; }
  const TuneSweep& sweep() const { return sweep_; }
  // The spectral ocean simulation updates that ran inside timed frames (over every
  // configuration timed so far): each timed frame is a new time of an animation, so a graph
  // with an ocean runs one per timed frame; 0 without an ocean.
  long timedSimulationUpdates() const { return timedSimulationUpdates_; }
  std::string renderer() const;

 private:
  struct Entry;
  struct View {
    std::string label;
    rt::Camera camera;
    rt::SceneOptions scene;
  };
  Entry& entry(const std::optional<TuneConfig>& config);
  std::unique_ptr<Entry> make(const std::optional<TuneConfig>& config);
  TuneError compare(Entry& e);

  Graph graph_;
  std::vector<TuneKnob> knobs_;
  TuneSweep sweep_;
  std::unique_ptr<rt::EglContext> context_;
  std::vector<View> views_;
  std::vector<std::string> labels_;
  std::vector<std::vector<float>> reference_;  // RGBA32F per view
  std::optional<rt::MemoryReservation> referenceMemory_;  // reference_'s share of the memory budget
  std::map<std::string, std::unique_ptr<Entry>> cache_;
  long timedSimulationUpdates_ = 0;
};

}  // namespace wg::accuracy
