// Named configurations of a graph's quality knobs measured as `watergraph tune` measures
// them (accuracy/tune_render.h): each configuration's worst PSNR and max abs error over
// tune's sweep (cameras x times) against tune's reference (every knob at its most exact
// level), and all of them timed together beside the reference in interleaved repeats (CPU
// ms per megapixel over frames of an animation). tune itself only ever measures one knob
// lowered from the configuration it stands at; this compares chosen points directly, e.g.
// two long cascades at a quarter of the size together with the knobs tune takes first.
//
//   build/bin/wg_bench_tune_configs [--cameras above,grazing,topdown] [--times 1,3.5,20]
//       [--size 160x90] [--runs 9] GRAPH 'node.option=JSON;node.option=JSON' ...
//
// Each configuration lists knob levels (as `watergraph tune` prints them); knobs it does not
// name stay at their most exact level. A value that is not one of the knob's levels is refused.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy/tune_knobs.h"
#include "accuracy/tune_render.h"
#include "core/frame_size_text.h"
#include "core/graph_io.h"

namespace {

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "wg_bench_tune_configs: %s\nusage: wg_bench_tune_configs [--cameras LIST] [--times LIST] [--size WxH] "
               "[--runs N] GRAPH 'node.option=JSON;...' ...\n",
               why.c_str());
  std::exit(2);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);)
    if (!item.empty()) out.push_back(item);
  return out;
}

// The configuration `text` names, every other knob at its most exact level.
wg::accuracy::TuneConfig parseConfig(const std::string& text, const std::vector<wg::accuracy::TuneKnob>& knobs) {
  wg::accuracy::TuneConfig config;
  for (const auto& k : knobs) config.push_back(static_cast<int>(k.levels.size()) - 1);
  for (const auto& item : split(text, ';')) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos) usage("'" + item + "' is not node.option=JSON");
    const std::string name = item.substr(0, eq);
    const nlohmann::json value = nlohmann::json::parse(item.substr(eq + 1), nullptr, false);
    size_t k = 0;
    while (k < knobs.size() && knobs[k].name() != name) ++k;
    if (k == knobs.size()) usage("'" + name + "' is no knob of this graph (tune names them node.option)");
    size_t l = 0;
    while (l < knobs[k].levels.size() && knobs[k].levels[l] != value) ++l;
    if (l == knobs[k].levels.size()) usage("'" + item.substr(eq + 1) + "' is no level of " + name);
    config[k] = static_cast<int>(l);
  }
  return config;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace wg;
  accuracy::TuneSweep sweep;
  std::string graphPath;
  std::vector<std::string> configTexts;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage("missing value after " + a);
      return argv[++i];
    };
    if (a == "--cameras") {
      sweep.cameras = split(next(), ',');
    } else if (a == "--times") {
      sweep.times.clear();
      for (const auto& t : split(next(), ',')) sweep.times.push_back(std::strtod(t.c_str(), nullptr));
    } else if (a == "--size") {
      const auto size = parseFrameSizeText(next(), 8, 9999);
      if (!size) usage("--size is WIDTHxHEIGHT, each side 8..9999");
      sweep.width = size->width;
      sweep.height = size->height;
    } else if (a == "--runs") {
      sweep.runs = std::max(1, std::atoi(next().c_str()));
    } else if (graphPath.empty()) {
      graphPath = a;
    } else {
      configTexts.push_back(a);
    }
  }
  if (graphPath.empty()) usage("no graph");
  try {
    Diagnostics diags;
    auto graph = loadGraphFile(graphPath, diags);
    if (!graph) {
      for (const auto& d : diags.all()) std::fprintf(stderr, "%s\n", formatText(d).c_str());
      return 1;
    }
    std::vector<accuracy::TuneKnob> knobs = accuracy::graphKnobs(*graph);
    std::vector<accuracy::TuneConfig> configs;
    for (const auto& t : configTexts) configs.push_back(parseConfig(t, knobs));
    accuracy::GlTuneMeasurements gl(*graph, knobs, sweep);
    std::printf("%s, %dx%d, %zu frames, %s\n\n| configuration | worst PSNR dB (frame) | max abs error |\n|---|---|---|\n",
                graphPath.c_str(), sweep.width, sweep.height, gl.viewLabels().size(), gl.renderer().c_str());
    std::vector<std::optional<accuracy::TuneConfig>> timed{knobs.empty() ? accuracy::TuneConfig{} : parseConfig("", knobs)};
    for (size_t c = 0; c < configs.size(); ++c) {
      const accuracy::TuneError e = gl.error(configs[c]);
      std::printf("| %s | %.1f (%s) | %.3g |\n", configTexts[c].c_str(), e.worstPsnr, e.worstFrame.c_str(), e.maxAbsError);
      std::fflush(stdout);
      timed.push_back(configs[c]);
    }
    const std::vector<accuracy::TuneCost> costs = gl.costOf(timed);
    std::printf("\n| configuration | ms/MP (median of %d) | x reference |\n|---|---|---|\n", sweep.runs);
    for (size_t c = 0; c < timed.size(); ++c)
      std::printf("| %s | %.1f | %.2f |\n", c == 0 ? "reference" : configTexts[c - 1].c_str(), costs[c].msPerMegapixel,
                  costs[0].msPerMegapixel / costs[c].msPerMegapixel);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wg_bench_tune_configs: %s\n", e.what());
    return 1;
  }
  return 0;
}
