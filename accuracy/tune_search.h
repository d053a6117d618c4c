#pragma once
// The search of `watergraph tune`, apart from any renderer: a greedy descent over a graph's
// quality knobs. It starts at the reference (every knob at its most exact level) and, in
// rounds, tries lowering each knob one level from the current configuration; a candidate
// qualifies when every frame of the sweep meets the budget, nothing in it is NaN or Inf,
// and it saves cost (time, or SPIR-V instructions when no time saving is measured: the
// candidate must be faster than the configuration it was tried from in the interleaved
// repeats, see timeSaved, so a median that is lower by chance does not count).
// The qualifying candidate with the least error increase per unit of saved time is taken
// (ties: fewer SPIR-V instructions, then the knob's name); the descent stops when none
// qualifies. The chosen configuration is then rendered again and checked once more
// (verification); a configuration that fails it is undone step by step.
//
// Every number comes from TuneMeasurements, so for a given set of measurements the path
// is deterministic; tests drive the search with made-up measurements.
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg::accuracy {

struct TuneKnob {
  std::string node, option;
  std::vector<nlohmann::json> levels;  // cheapest to most exact
  std::string name() const { return node + "." + option; }
};

// The level index of each knob, in the knobs' order.
using TuneConfig = std::vector<int>;

// A configuration's error against the reference over the sweep: the worst frame counts.
struct TuneError {
  double worstPsnr = INFINITY;  // lowest per-frame PSNR (peak 1, RGB); inf: identical
  double maxAbsError = 0;       // largest per-pixel, per-channel absolute error of any frame
  bool finite = true;           // false: some pixel of some frame is NaN or Inf
  std::string worstFrame;       // the frame of the lowest PSNR ("grazing t=3.5")
};

struct TuneCost {
  double msPerMegapixel = 0;  // median over interleaved repeats
  int spirvInstructions = 0;  // the fragment shader after spirv-opt -O
  // ms/MP of each repeat, in order; the configurations of one cost() call share them
  // repeat by repeat (paired). Empty: the median is exact (made-up measurements).
  std::vector<double> repeats;
};

// The time `candidate` saves against `current`, both from one cost() call: the difference
// of the medians when the candidate was faster in enough of the paired repeats that chance
// is an unlikely cause (a one-sided sign test at kSavingTestLevel: repeatsToShowASaving),
// otherwise 0: a saving the repeats do not show is the machine's noise, not the knob's. Too
// few repeats (under 4) show nothing, and the search then goes by SPIR-V instructions.
inline constexpr double kSavingTestLevel = 0.1;
// At 10 %: 4 of 4, 5 of 5, 6 of 6, 6 of 7, 7 of 9, 8 of 10; n + 1 when no count is rare enough.
size_t repeatsToShowASaving(size_t n, double level = kSavingTestLevel);
double timeSaved(const TuneCost& candidate, const TuneCost& current);

struct TuneBudget {
  std::optional<double> minPsnr, maxAbsError;
  bool met(const TuneError& e) const;
  // How much of the budget the error uses (the larger of MSE / allowed MSE and max error /
  // allowed max error); what the search trades against saved time.
  double usage(const TuneError& e) const;
  std::string text() const;  // "PSNR >= 45 dB, max abs error <= 0.01"
};

class TuneMeasurements {
 public:
  virtual ~TuneMeasurements() = default;
  // Renders `config` over the sweep and compares every frame with the reference's.
  virtual TuneError error(const TuneConfig& config) = 0;
  // The costs of `configs`, timed in interleaved repeats in one run (comparable).
  virtual std::vector<TuneCost> cost(const std::vector<TuneConfig>& configs) = 0;
  // The final check of the chosen configuration: rendered again, from scratch.
  virtual TuneError verify(const TuneConfig& config) { return error(config); }
};

struct TuneStep {
  TuneConfig config;
  std::string knob, level;  // what this step lowered, to which level ("" for the reference)
  TuneError error;
  TuneCost cost;
};

struct TuneTried {
  TuneConfig config;
  std::string label;  // the step from the configuration it was tried from: "fresnel.model=schlick"
  TuneError error;
  TuneCost cost;
  bool meetsBudget = false;
  bool pareto = false;  // no other tried configuration is both cheaper and closer (worst PSNR)
};

struct TuneResult {
  std::vector<TuneStep> path;    // path[0]: the reference; the last step: the chosen one
  std::vector<TuneTried> tried;  // every configuration measured, in order
  size_t lastRound = 0;          // tried[lastRound..]: the candidates of the round that ended the descent
  TuneCost lastRoundCurrent;     // the configuration they were tried from, timed beside them
  TuneError verified;            // the chosen configuration rendered again
  bool found = false;            // a configuration cheaper than the reference meets the budget
  std::string why;               // when not found: why, as a sentence
  const TuneStep& chosen() const { return path.back(); }
};

// One line of progress per measured configuration (for a terminal), or nothing.
using TuneProgress = std::function<void(const std::string&)>;

TuneResult tuneSearch(const std::vector<TuneKnob>& knobs, const TuneBudget& budget, TuneMeasurements& measure,
                      const TuneProgress& progress = {});

// The level values of `config`, as a user writes them: "fresnel.model=schlick, cv.bypass=true".
std::string configText(const std::vector<TuneKnob>& knobs, const TuneConfig& config);
std::string levelText(const nlohmann::json& level);

}  // namespace wg::accuracy
