#include "accuracy/tune_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/graph_io.h"

namespace wg::accuracy {
namespace {

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string psnrText(double psnr) { return std::isinf(psnr) ? "inf" : fixed(psnr, 1); }

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string tunePathTable(const TuneResult& result) {
  std::string o = "| step | knob | level | worst PSNR dB | worst frame | max abs error | ms/MP | SPIR-V instr. (-O) |\n";
  o += "|---|---|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < result.path.size(); ++i) {
    const TuneStep& s = result.path[i];
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.3g", s.error.maxAbsError);
    o += "| " + std::to_string(i) + " | " + (i ? s.knob : "reference") + " | " + (i ? s.level : "most exact") + " | " +
         psnrText(s.error.worstPsnr) + " | " + (std::isinf(s.error.worstPsnr) ? "" : s.error.worstFrame) + " | " + buf +
         " | " + fixed(s.cost.msPerMegapixel, 1) + " | " + std::to_string(s.cost.spirvInstructions) + " |\n";
  }
  return o;
}

std::string tuneStopText(const TuneResult& result) {
  std::string o;
  for (size_t i = std::max<size_t>(result.lastRound, 1); i < result.tried.size(); ++i) {
    const TuneTried& t = result.tried[i];
    if (t.config == result.chosen().config) continue;
    char buf[200];
    if (!t.error.finite)
      std::snprintf(buf, sizeof buf, "NaN/Inf in %s", t.error.worstFrame.c_str());
    else if (!t.meetsBudget)
      std::snprintf(buf, sizeof buf, "fails the budget: worst PSNR %s dB (%s), max abs error %.3g", psnrText(t.error.worstPsnr).c_str(),
                    t.error.worstFrame.c_str(), t.error.maxAbsError);
    else
      std::snprintf(buf, sizeof buf, "%s: %.1f ms/MP, %d SPIR-V instr. (the configuration it was tried from: %.1f, %d)",
                    timeSaved(result.lastRoundCurrent, t.cost) > 0 ? "slower in the repeats"
                                                                    : "saves nothing the repeats show",
                    t.cost.msPerMegapixel, t.cost.spirvInstructions, result.lastRoundCurrent.msPerMegapixel,
                    result.lastRoundCurrent.spirvInstructions);
    o += "  " + t.label + ": " + buf + "\n";
  }
  return o.empty() ? o : "the descent stopped; the last round's candidates:\n" + o;
}

std::string tunePlotSvg(const TuneResult& result, const TuneBudget& budget, const std::string& title) {
  const double W = 760, H = 500, left = 70, right = 20, top = 40, bottom = 60;
  std::vector<const TuneTried*> pts;
  for (const auto& t : result.tried)
    if (t.error.finite) pts.push_back(&t);
  double maxCost = 0, minPsnr = INFINITY, maxPsnr = -INFINITY;
  for (const auto* t : pts) {
    maxCost = std::max(maxCost, t->cost.msPerMegapixel);
    if (!std::isinf(t->error.worstPsnr)) minPsnr = std::min(minPsnr, t->error.worstPsnr), maxPsnr = std::max(maxPsnr, t->error.worstPsnr);
  }
  if (budget.minPsnr) minPsnr = std::min(minPsnr, *budget.minPsnr), maxPsnr = std::max(maxPsnr, *budget.minPsnr);
  if (std::isinf(minPsnr)) minPsnr = 0, maxPsnr = 60;
  // Identical frames (PSNR inf) sit on a line above the highest finite PSNR.
  double infRow = maxPsnr + std::max(5.0, 0.1 * (maxPsnr - minPsnr));
  double yLow = std::floor(minPsnr / 5) * 5 - 5, yHigh = infRow + 3;
  double xHigh = maxCost > 0 ? maxCost * 1.08 : 1;
  auto X = [&](double c) { return left + (W - left - right) * c / xHigh; };
  auto Y = [&](double p) { return top + (H - top - bottom) * (1 - ((std::isinf(p) ? infRow : p) - yLow) / (yHigh - yLow)); };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(W, 0) + "\" height=\"" + fixed(H, 0) +
                  "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<text x=\"" + fixed(W / 2, 0) + "\" y=\"20\" text-anchor=\"middle\" font-size=\"13\">" + xmlEscape(title) + "</text>\n";
  // Axes, ticks and grid.
  s += "<line x1=\"" + fixed(left, 1) + "\" y1=\"" + fixed(H - bottom, 1) + "\" x2=\"" + fixed(W - right, 1) + "\" y2=\"" +
       fixed(H - bottom, 1) + "\" stroke=\"black\"/>\n";
  s += "<line x1=\"" + fixed(left, 1) + "\" y1=\"" + fixed(top, 1) + "\" x2=\"" + fixed(left, 1) + "\" y2=\"" +
       fixed(H - bottom, 1) + "\" stroke=\"black\"/>\n";
  double xStep = std::pow(10.0, std::floor(std::log10(xHigh / 2)));
  if (xHigh / xStep > 10) xStep *= xHigh / xStep > 20 ? 5 : 2;
  for (double x = 0; x <= xHigh; x += xStep)
    s += "<line x1=\"" + fixed(X(x), 1) + "\" y1=\"" + fixed(top, 1) + "\" x2=\"" + fixed(X(x), 1) + "\" y2=\"" +
         fixed(H - bottom, 1) + "\" stroke=\"#e4e4e4\"/>\n<text x=\"" + fixed(X(x), 1) + "\" y=\"" + fixed(H - bottom + 15, 1) +
         "\" text-anchor=\"middle\">" + fixed(x, xStep < 1 ? 2 : 0) + "</text>\n";
  for (double y = yLow; y <= maxPsnr + 1e-9; y += 5)
    s += "<line x1=\"" + fixed(left, 1) + "\" y1=\"" + fixed(Y(y), 1) + "\" x2=\"" + fixed(W - right, 1) + "\" y2=\"" +
         fixed(Y(y), 1) + "\" stroke=\"#e4e4e4\"/>\n<text x=\"" + fixed(left - 6, 1) + "\" y=\"" + fixed(Y(y) + 4, 1) +
         "\" text-anchor=\"end\">" + fixed(y, 0) + "</text>\n";
  s += "<text x=\"" + fixed(left - 6, 1) + "\" y=\"" + fixed(Y(INFINITY) + 4, 1) + "\" text-anchor=\"end\">identical</text>\n";
  s += "<text x=\"" + fixed((left + W - right) / 2, 1) + "\" y=\"" + fixed(H - 20, 1) +
       "\" text-anchor=\"middle\">cost: CPU ms per megapixel (median of interleaved repeats)</text>\n";
  s += "<text transform=\"translate(18," + fixed((top + H - bottom) / 2, 1) +
       ") rotate(-90)\" text-anchor=\"middle\">worst-frame PSNR against the reference, dB</text>\n";
  if (budget.minPsnr)
    s += "<line x1=\"" + fixed(left, 1) + "\" y1=\"" + fixed(Y(*budget.minPsnr), 1) + "\" x2=\"" + fixed(W - right, 1) +
         "\" y2=\"" + fixed(Y(*budget.minPsnr), 1) + "\" stroke=\"#c03030\" stroke-dasharray=\"6,4\"/>\n<text x=\"" +
         fixed(W - right - 4, 1) + "\" y=\"" + fixed(Y(*budget.minPsnr) - 4, 1) + "\" text-anchor=\"end\" fill=\"#c03030\">budget " +
         fixed(*budget.minPsnr, 1) + " dB</text>\n";
  // The Pareto front, joined in order of cost.
  std::vector<const TuneTried*> front;
  for (const auto* t : pts)
    if (t->pareto) front.push_back(t);
  std::sort(front.begin(), front.end(), [](const TuneTried* a, const TuneTried* b) {
    return a->cost.msPerMegapixel < b->cost.msPerMegapixel;
  });
  if (front.size() > 1) {
    s += "<polyline fill=\"none\" stroke=\"#d08000\" stroke-width=\"1.5\" stroke-dasharray=\"4,3\" points=\"";
    for (const auto* t : front) s += fixed(X(t->cost.msPerMegapixel), 1) + "," + fixed(Y(t->error.worstPsnr), 1) + " ";
    s += "\"/>\n";
  }
  for (const auto* t : pts) {
    std::string cx = fixed(X(t->cost.msPerMegapixel), 1), cy = fixed(Y(t->error.worstPsnr), 1);
    if (t->pareto) s += "<circle cx=\"" + cx + "\" cy=\"" + cy + "\" r=\"8\" fill=\"none\" stroke=\"#d08000\" stroke-width=\"2\"/>\n";
    s += "<circle cx=\"" + cx + "\" cy=\"" + cy + "\" r=\"4\" " +
         (t->meetsBudget ? "fill=\"#2060c0\"" : "fill=\"white\" stroke=\"#2060c0\"") + "><title>" + xmlEscape(t->label) + ": " +
         psnrText(t->error.worstPsnr) + " dB, " + fixed(t->cost.msPerMegapixel, 1) + " ms/MP</title></circle>\n";
  }
  if (result.found) {
    const TuneStep& c = result.chosen();
    s += "<text x=\"" + fixed(X(c.cost.msPerMegapixel) + 10, 1) + "\" y=\"" + fixed(Y(c.error.worstPsnr) + 14, 1) +
         "\" font-weight=\"bold\">chosen</text>\n";
  }
  s += "<text x=\"" + fixed(left + 8, 1) + "\" y=\"" + fixed(top + 12, 1) +
       "\">filled: meets the budget; hollow: does not; ringed and joined: Pareto front</text>\n";
  s += "</svg>\n";
  return s;
}

std::optional<std::string> graphWithPreset(const std::string& text, const std::string& file, const std::string& name,
                                           const std::vector<TuneKnob>& knobs, const TuneConfig& config,
                                           Diagnostics& diags) {
  auto graph = parseGraph(text, file, diags);
  if (!graph) return std::nullopt;
  Preset preset;
  preset.name = name;
  for (size_t k = 0; k < knobs.size(); ++k) {
    PresetValue v;
    v.node = knobs[k].node;
    v.option = knobs[k].option;
    v.optionValue = knobs[k].levels[static_cast<size_t>(config[k])];
    preset.values.push_back(std::move(v));
  }
  auto same = std::find_if(graph->presets.begin(), graph->presets.end(), [&](const Preset& p) { return p.name == name; });
  if (same != graph->presets.end())
    *same = std::move(preset);
  else
    graph->presets.push_back(std::move(preset));
  std::string out = saveGraph(*graph);
  Diagnostics reload;
  if (!parseGraph(out, file, reload)) {
    diags.append(reload);
    return std::nullopt;
  }
  return out;
}

}  // namespace wg::accuracy
