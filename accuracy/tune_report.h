#pragma once
// What `watergraph tune` prints and writes: the path it took, the summary against the
// reference and the graph as written, the plot of every tried configuration (SVG), and the
// graph file with the chosen configuration as a preset, in canonical form.
#include <optional>
#include <string>
#include <vector>

#include "accuracy/tune_search.h"
#include "core/diagnostic.h"

namespace wg::accuracy {

// The path as a markdown table: step, knob, level, worst PSNR (its frame), max abs error,
// ms/MP and SPIR-V instructions.
std::string tunePathTable(const TuneResult& result);

// What ended the descent: each candidate of the last round, and why it was not taken
// ("fails the budget: worst PSNR ...", "saves nothing: ..."); "" when there was none.
std::string tuneStopText(const TuneResult& result);

// Every tried configuration on cost (ms/MP) against worst PSNR; configurations that meet
// the budget filled, the others hollow; the Pareto front ringed and joined; the chosen
// configuration labelled; the PSNR budget (if any) a dashed line.
std::string tunePlotSvg(const TuneResult& result, const TuneBudget& budget, const std::string& title);

// `text` (the graph file `file`) with preset `name` setting every knob to its level in
// `config` (replacing a preset of that name, in its place; otherwise added last), in the
// canonical form of `watergraph fmt`. nullopt, with diagnostics, when the text does not
// parse or the result would not load back.
std::optional<std::string> graphWithPreset(const std::string& text, const std::string& file, const std::string& name,
                                           const std::vector<TuneKnob>& knobs, const TuneConfig& config,
                                           Diagnostics& diags);

}  // namespace wg::accuracy
