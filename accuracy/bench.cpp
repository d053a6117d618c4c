#include "accuracy/bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "accuracy/spirv_count.h"
#include "accuracy/tune_knobs.h"
#include "codegen/compile.h"
#include "codegen/output_files.h"
#include "core/file_read.h"
#include "core/load_limits.h"
#include "core/graph_io.h"
#include "core/preset.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/memory_budget.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime/median.h"

namespace wg::accuracy {
namespace {

using ordered = nlohmann::ordered_json;

// Errors name the configuration file, or the graph for `bench GRAPH`.
[[noreturn]] void configError(const BenchSettings& s, const std::string& m) {
  throw std::runtime_error((s.graphFile.empty() ? s.configFile : s.graphFile) + ": error: " + m);
}

using rt::median;

std::string diagText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.all()) s += "\n  " + formatText(x);
  return s;
}

// The graph of a family with one level's option values applied.
Graph withOptions(const Graph& base, const ordered& overrides, const BenchSettings& s, const std::string& where) {
  Graph g = base;
  for (auto it = overrides.begin(); it != overrides.end(); ++it) {
    if (it.key().find('/') != std::string::npos) {  // a node inside a subgraph instance ("foam/edge")
      Preset preset;
      for (auto o = it.value().begin(); o != it.value().end(); ++o) {
        PresetValue v;
        v.node = it.key();
        v.option = o.key();
        v.optionValue = nlohmann::json::parse(o.value().dump());
        preset.values.push_back(std::move(v));
      }
      writePresetInto(g, preset);
      continue;
    }
    Node* node = nullptr;
    for (auto& n : g.nodes)
      if (n.id == it.key()) node = &n;
    if (!node) configError(s, where + ": no node '" + it.key() + "' in the graph");
    for (auto o = it.value().begin(); o != it.value().end(); ++o) {
      nlohmann::json value = nlohmann::json::parse(o.value().dump());
      bool found = false;
      for (auto& opt : node->options)
        if (opt.name == o.key()) opt.value = value, found = true;
      if (!found) node->options.push_back({o.key(), value, {}, {}});
    }
  }
  return g;
}

// One family to measure: a graph and its levels (option values per node id), one of
// which is the reference the others' error is measured against.
struct Family {
  std::string name, node, camera;
  Graph base;
  std::vector<std::pair<std::string, ordered>> levels;
  std::string reference;
};

// A level's name: the knob's value as a user writes it ("3x3", 10, true).
std::string levelName(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// The levels of quality knob `option` of node `nodeId` (fixed, or following the node's
// written options), or none when it is no knob there.
std::vector<nlohmann::json> knobLevelsOf(const Graph& g, const std::string& nodeId, const std::string& option) {
  for (const auto& n : g.nodes)
    if (n.id == nodeId)
      if (const NodeSpec* spec = defaultRegistry().find(n.type)) {
        int i = spec->optionIndex(option);
        if (i >= 0) {
          std::vector<nlohmann::json> levels = knobLevels(spec->options[static_cast<size_t>(i)], writtenOptions(n));
          if (levels.size() >= 2) return levels;
        }
      }
  return {};
}

// A graph's own families: one per quality knob, each level with every other knob at its
// most exact level (together: the reference), and "as written" against that reference.
std::vector<Family> knobFamilies(const Graph& g, const BenchSettings& s) {
  // The graph's own nodes' knobs and those inside its subgraph instances ("foam/edge.bypass").
  auto knobs = graphKnobs(g);
  if (knobs.empty()) configError(s, "the graph has no node with a quality knob (`watergraph nodes` lists them)");
  ordered exact = ordered::object();
  for (const auto& k : knobs) exact[k.node][k.option] = k.levels.back();
  std::vector<Family> families;
  for (const auto& k : knobs) {
    Family f{k.name(), k.node, s.camera, g, {}, levelName(k.levels.back())};
    for (const auto& level : k.levels) {
      ordered options = exact;
      options[k.node][k.option] = level;
      f.levels.push_back({levelName(level), options});
    }
    families.push_back(std::move(f));
  }
  families.push_back({"as written", "graph", s.camera, g, {{"reference", exact}, {"as written", ordered::object()}}, "reference"});
  return families;
}

// Every --family asked for must exist: a misspelt one would otherwise be skipped without a
// word, or, alone, end in "no family to run".
void requireRequestedFamilies(const BenchSettings& settings, const std::vector<std::string>& available) {
  for (const auto& wanted : settings.families) {
    if (std::find(available.begin(), available.end(), wanted) != available.end()) continue;
    std::string list;
    for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
    throw BenchUsageError((settings.graphFile.empty() ? settings.configFile : settings.graphFile) + ": error: no family '" +
                          wanted + "'; " +
                          (settings.graphFile.empty() ? "the configuration has: " : "the graph's knobs give: ") + list);
  }
}

// The configuration file as JSON: a syntax error at its line and column.
ordered readConfig(const BenchSettings& settings) {
  FileReadRule rule;
  rule.maxBytes = kMaxFileBytes;
  FileReadFailure failure;
  auto file = readFileChecked(settings.configFile, rule, &failure);  // one open, one read (core/file_read.h)
  if (!file) configError(settings, "[WG050] cannot read the bench configuration: " + failure.why());
  std::string text = std::move(file->bytes);
  try {
    return ordered::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    size_t at = std::min<size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size()), line = 1, column = 1;
    for (size_t i = 0; i < at; ++i) text[i] == '\n' ? (++line, column = 1) : ++column;
    throw std::runtime_error(settings.configFile + ":" + std::to_string(line) + ":" + std::to_string(column) +
                             ": error: [WG001] the bench configuration is not valid JSON");
  } catch (const nlohmann::json::exception& e) {  // a number past double's range (1e999)
    configError(settings, std::string("[WG001] the bench configuration is not valid JSON: ") + e.what());
  }
}

// A family's member that must be a string when present: its value, or `fallback`.
std::string familyText(const BenchSettings& settings, const ordered& family, size_t index, const char* key,
                       const std::string& fallback) {
  if (!family.contains(key)) return fallback;
  if (!family[key].is_string())
    configError(settings, "[WG004] family " + std::to_string(index + 1) + ": \"" + key + "\" must be a string (got " +
                              family[key].dump() + ")");
  return family[key].get<std::string>();
}

// The families of a configuration file (bench/variants.json). A family lists its levels,
// or names a quality knob ("knob": "node.option") whose levels the node declares.
std::vector<Family> configFamilies(const BenchSettings& settings) {
  ordered config = readConfig(settings);
  if (!config.is_object() || !config.contains("families") || !config["families"].is_array())
    configError(settings, "[WG004] needs \"families\": [...]");
  std::vector<std::string> names;
  for (size_t i = 0; i < config["families"].size(); ++i) {
    const ordered& fam = config["families"][i];
    if (!fam.is_object()) configError(settings, "[WG004] family " + std::to_string(i + 1) + " must be an object (got " + fam.dump() + ")");
    names.push_back(familyText(settings, fam, i, "name", ""));
    for (const char* key : {"node", "camera", "reference", "graph_file", "knob"}) familyText(settings, fam, i, key, "");
  }
  requireRequestedFamilies(settings, names);
  std::vector<Family> families;
  for (const auto& fam : config["families"]) {
    std::string name = fam.value("name", "");
    if (!settings.families.empty() &&
        std::find(settings.families.begin(), settings.families.end(), name) == settings.families.end())
      continue;
    Diagnostics diags;
    std::optional<Graph> base;
    if (fam.contains("graph_file"))
      base = loadGraphFile((std::filesystem::path(settings.root) / fam["graph_file"].get<std::string>()).string(), diags);
    else if (fam.contains("graph"))
      base = parseGraph(fam["graph"].dump(), settings.configFile + " (family '" + name + "')", diags);
    else
      configError(settings, "[WG005] family '" + name + "' has neither \"graph\" nor \"graph_file\"");
    if (!base) configError(settings, "family '" + name + "': the graph does not load:" + diagText(diags));
    Family f{name, fam.value("node", ""), fam.value("camera", "above"), *base, {}, fam.value("reference", "")};
    if (fam.contains("knob")) {
      std::string knob = fam["knob"].is_string() ? fam["knob"].get<std::string>() : "";
      size_t dot = knob.find('.');
      const std::vector<nlohmann::json> levels =
          dot == std::string::npos ? std::vector<nlohmann::json>{} : knobLevelsOf(*base, knob.substr(0, dot), knob.substr(dot + 1));
      if (levels.empty()) configError(settings, "[WG004] family '" + name + "': \"knob\" must name a quality knob as \"node.option\" (got '" + knob + "')");
      for (const auto& level : levels)
        f.levels.push_back({levelName(level), ordered{{knob.substr(0, dot), {{knob.substr(dot + 1), level}}}}});
      f.reference = levelName(levels.back());
    } else {
      if (!fam.contains("levels")) configError(settings, "[WG005] family '" + name + "' needs \"levels\" or \"knob\"");
      if (!fam["levels"].is_object())
        configError(settings, "[WG004] family '" + name + "': \"levels\" must be an object, level name -> settings (got " +
                                  fam["levels"].dump() + ")");
      for (auto it = fam["levels"].begin(); it != fam["levels"].end(); ++it) f.levels.push_back({it.key(), it.value()});
      bool found = false;
      for (const auto& l : f.levels) found |= l.first == f.reference;
      if (!found) configError(settings, "[WG004] family '" + name + "': reference level '" + f.reference + "' is not among its levels");
    }
    families.push_back(std::move(f));
  }
  return families;
}

std::vector<Family> familiesToRun(const BenchSettings& settings) {
  if (settings.graphFile.empty()) return configFamilies(settings);
  Diagnostics diags;
  auto g = loadGraphFile(settings.graphFile, diags);
  if (!g) configError(settings, "the graph does not load:" + diagText(diags));
  if (!settings.preset.empty() && !applyPreset(*g, settings.preset, diags))
    configError(settings, "the preset does not apply:" + diagText(diags));
  std::vector<Family> all = knobFamilies(*g, settings);
  std::vector<std::string> names;
  for (const auto& f : all) names.push_back(f.name);
  requireRequestedFamilies(settings, names);
  std::vector<Family> families;
  for (auto& f : all)
    if (settings.families.empty() || std::find(settings.families.begin(), settings.families.end(), f.name) != settings.families.end())
      families.push_back(std::move(f));
  return families;
}

struct Prepared {
  BenchLevel level;
  CompileResult compiled;
  std::unique_ptr<rt::Renderer> renderer;
  std::vector<double> ms, ratios;
  rt::Image image;
};

}  // namespace

BenchResult runBench(const BenchSettings& settings) {
  Target target = settings.target;
  std::vector<Prepared> levels;
  for (const Family& fam : familiesToRun(settings)) {
    for (const auto& [levelName, overrides] : fam.levels) {
      Prepared p;
      p.level.family = fam.name;
      p.level.level = levelName;
      p.level.node = fam.node;
      p.level.camera = fam.camera;
      p.level.reference = levelName == fam.reference;
      Graph g = withOptions(fam.base, overrides, settings, "family '" + fam.name + "' level '" + levelName + "'");
      Diagnostics diags;
      CompileOptions options;
      options.targets = {target, Target::Vk450};
      options.checkPresets = false;  // a level of the family's graph: its presets are not what is measured
      auto compiled = compileGraph(g, defaultRegistry(), options, diags);
      if (!compiled) configError(settings, "family '" + fam.name + "' level '" + levelName + "' does not compile:" + diagText(diags));
      for (const auto& f : compiled->files)
        if (f.name.size() > 15 && f.name.compare(f.name.size() - 15, 15, ".vk450.frag.spv") == 0)
          p.level.spirvInstructions = optimisedInstructionCount(spirvWords(f.contents));
      p.compiled = std::move(*compiled);
      levels.push_back(std::move(p));
    }
  }
  if (levels.empty()) configError(settings, "no family to run");

  // The pass-through: the interpolated normal as colour, per camera used.
  Diagnostics diags;
  auto passGraph = parseGraph(R"({"version": 1, "name": "pass_through", "nodes": [{"id": "n", "type": "normal"}],
    "outputs": {"fragment": {"color": "n.out"}}})", "pass-through", diags);
  CompileOptions passOptions;
  passOptions.targets = {target};
  auto passCompiled = compileGraph(*passGraph, defaultRegistry(), passOptions, diags);
  if (!passCompiled) throw std::logic_error("the pass-through graph does not compile:" + diagText(diags));

  auto context = rt::EglContext::create(rt::apiFor(target));
  BenchResult result;
  result.settings = settings;
  result.renderer = context->renderer();
  auto makeRenderer = [&](const CompileResult& c, const std::string& camera) {
    rt::RenderSettings rs;
    rs.width = settings.width;
    rs.height = settings.height;
    rs.camera = camera;
    rs.floatColor = true;
    return std::make_unique<rt::Renderer>(c.manifest, rt::waterShaderSources(c, target), rs, context->isEs(),
                                          rt::textureOrigins(c));
  };
  std::map<std::string, std::unique_ptr<rt::Renderer>> passThrough;
  std::map<std::string, std::vector<double>> passMs;
  {
    // Every level's renderer and a pass-through per camera are held at once: their targets
    // and read-back, estimated before the first is made (docs/robustness.md).
    rt::RenderSettings rs;
    rs.width = settings.width;
    rs.height = settings.height;
    rs.floatColor = true;
    size_t bytes = 0;
    std::set<std::string> cameras;
    for (const auto& p : levels) {
      bytes = rt::saturatedSum(bytes, rt::rendererBytes(p.compiled.manifest, rs));
      cameras.insert(p.level.camera);
    }
    bytes = rt::saturatedSum(bytes, rt::saturatedProduct(cameras.size(), rt::rendererBytes(passCompiled->manifest, rs)));
    rt::checkMemoryBudget(bytes, "bench at " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " (" +
                                     std::to_string(levels.size() + cameras.size()) + " renderers' targets and read-back)");
  }
  for (auto& p : levels) {
    p.renderer = makeRenderer(p.compiled, p.level.camera);
    if (!passThrough.count(p.level.camera)) passThrough[p.level.camera] = makeRenderer(*passCompiled, p.level.camera);
  }
  // Warm-up: llvmpipe compiles shaders at the first draw.
  for (auto& p : levels) p.renderer->renderFrame();
  for (auto& [cam, r] : passThrough) r->renderFrame();
  for (int run = 0; run < std::max(settings.runs, 1); ++run) {
    std::map<std::string, double> passNow;
    for (auto& [cam, r] : passThrough) passNow[cam] = r->renderFrame(), passMs[cam].push_back(passNow[cam]);
    for (auto& p : levels) {
      double ms = p.renderer->renderFrame();
      p.ms.push_back(ms);
      p.ratios.push_back(ms / passNow[p.level.camera]);
    }
  }
  double megapixels = settings.width * static_cast<double>(settings.height) / 1e6;
  std::vector<double> allPass;
  for (auto& [cam, v] : passMs) allPass.insert(allPass.end(), v.begin(), v.end());
  result.passThroughMs = median(allPass);
  result.passThroughMsPerMegapixel = result.passThroughMs / megapixels;
  for (auto& p : levels) {
    p.image = p.renderer->readRgba32f();
    p.level.medianMs = median(p.ms);
    p.level.msPerMegapixel = p.level.medianMs / megapixels;
    p.level.ratio = median(p.ratios);
  }
  // Error against the family's reference level.
  for (auto& p : levels) {
    const Prepared* ref = nullptr;
    for (const auto& q : levels)
      if (q.level.family == p.level.family && q.level.reference) ref = &q;
    double sum = 0, sq = 0, mx = 0;
    size_t n = 0;
    for (size_t i = 0; i < p.image.rgba32f.size(); ++i) {
      if (i % 4 == 3) continue;
      // Clamped to [0, 1] as exposure 0 shows them (a graph family's frame is HDR: a sun
      // glint would outweigh the picture); a non-finite value is an infinite error.
      const double a = p.image.rgba32f[i], b = ref->image.rgba32f[i];
      double e = std::isfinite(a) && std::isfinite(b) ? std::abs(std::clamp(a, 0.0, 1.0) - std::clamp(b, 0.0, 1.0)) : INFINITY;
      sum += e, sq += e * e, mx = std::max(mx, e), ++n;
    }
    p.level.maxError = mx;
    p.level.meanError = n ? sum / static_cast<double>(n) : 0;
    double mse = n ? sq / static_cast<double>(n) : 0;
    p.level.psnr = mse > 0 ? 10 * std::log10(1.0 / mse) : INFINITY;
  }
  // Pareto front per family: no other level is both cheaper (ratio) and more accurate.
  for (auto& p : levels) {
    p.level.pareto = true;
    for (const auto& q : levels)
      if (&q != &p && q.level.family == p.level.family && q.level.ratio <= p.level.ratio &&
          q.level.meanError <= p.level.meanError && (q.level.ratio < p.level.ratio || q.level.meanError < p.level.meanError))
        p.level.pareto = false;
  }
  for (auto& p : levels) result.levels.push_back(p.level);
  levels.clear();  // GL objects before the context
  passThrough.clear();
  return result;
}

std::string benchMarkdown(const BenchResult& r) {
  std::ostringstream o;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%dx%d RGBA32F frames on %s (%s), median of %d interleaved runs; pass-through (the interpolated normal "
                "as colour) %.1f ms/MP. Error against each family's reference level over the frame; Pareto: no other "
                "level of the family is both cheaper and more accurate (mean error).\n\n",
                r.settings.width, r.settings.height, std::string(targetName(r.settings.target)).c_str(), r.renderer.c_str(),
                r.settings.runs, r.passThroughMsPerMegapixel);
  o << buf;
  o << "| family | level | ms/MP | x pass-through | SPIR-V instr. (-O) | max abs error | mean abs error | PSNR dB | Pareto |\n";
  o << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& l : r.levels) {
    std::string psnr = std::isinf(l.psnr) ? "ref" : (std::snprintf(buf, sizeof buf, "%.1f", l.psnr), std::string(buf));
    std::snprintf(buf, sizeof buf, "| %s | %s%s | %.1f | %.2f | %d | %.3g | %.3g | %s | %s |\n", l.family.c_str(),
                  l.level.c_str(), l.reference ? " (reference)" : "", l.msPerMegapixel, l.ratio, l.spirvInstructions,
                  l.maxError, l.meanError, psnr.c_str(), l.pareto ? "yes" : "");
    o << buf;
  }
  return o.str();
}

namespace {

// A string inside single quotes in a gnuplot script: a quote is doubled there, so a family
// or file name cannot end the string and run a command of its own (gnuplot has `system`).
std::string gnuplotQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out + "'";
}

// A label in the data file, inside double quotes: no quote or line break of its own.
std::string dataLabel(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '"' || c == '\\' || c == '\n' || c == '\r') ? '_' : c;
  return out;
}

// A folder of our own under the temporary folder (mkdtemp: a new name, mode 0700), so no
// one can plant a link at the names gnuplot reads and writes; removed with its files.
class PrivateFolder {
 public:
  PrivateFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "wg_bench_XXXXXX").string();
    if (::mkdtemp(pattern.data())) path_ = pattern;
  }
  ~PrivateFolder() {
    std::error_code ec;
    if (!path_.empty()) std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

std::string writeBenchPlot(const BenchResult& r, const std::string& png) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    return "gnuplot not found; install gnuplot-nox (scripts/setup.sh installs it)";
  PrivateFolder work;
  if (work.path().empty()) return std::string("cannot make a temporary folder: ") + std::strerror(errno);
  // gnuplot draws into the private folder; the picture is then written to `png` as every
  // output is (codegen/output_files.h): atomically, replacing a link rather than following it.
  const std::filesystem::path dataPath = work.path() / "plot.dat", scriptPath = work.path() / "plot.gp",
                              drawn = work.path() / "plot.png";
  // Families in order; errors of 0 (the references) sit on a floor line.
  const double floor = 1e-6;
  std::vector<std::string> families;
  for (const auto& l : r.levels)
    if (std::find(families.begin(), families.end(), l.family) == families.end()) families.push_back(l.family);
  std::ostringstream d;
  for (const auto& f : families) {
    d << "# " << dataLabel(f) << "\n";
    for (const auto& l : r.levels)
      if (l.family == f)
        d << l.ratio << " " << std::max(l.meanError, floor) << " \"" << (l.reference ? "" : dataLabel(l.level)) << "\" "
          << (l.pareto ? 1 : 0) << "\n";
    d << "\n\n";
  }
  std::ostringstream s;
  s << "set terminal pngcairo size 1100,700 font 'sans,10'\n";
  s << "set output " << gnuplotQuoted(drawn.string()) << "\n";
  s << "set title 'watergraph: cost against error (" << r.settings.width << "x" << r.settings.height << ", "
    << targetName(r.settings.target) << ", llvmpipe)'\n";
  s << "set xlabel 'cost: frame time / pass-through frame time (same run)'\n";
  s << "set ylabel 'mean abs error vs the reference level (references at 1e-6)'\n";
  s << "set label 1 'ringed and dashed: Pareto front of each family' at graph 0.02, graph 0.97 font 'sans,9'\n";
  s << "set logscale y\nset format y '10^{%L}'\nset grid\nset key outside right top\n";
  s << "plot ";
  for (size_t i = 0; i < families.size(); ++i) {
    std::string idx = std::to_string(i);
    s << (i ? ", \\\n     " : "") << gnuplotQuoted(dataPath.string()) << " index " << idx
      << " using 1:2 with points pt 7 ps 1.3 lc " << (i + 1) << " title " << gnuplotQuoted(families[i]);
    s << ", '' index " << idx << " using 1:($4 > 0 ? $2 : 1/0) with points pt 6 ps 2.6 lw 2 lc " << (i + 1)
      << " notitle";
    s << ", '' index " << idx << " using 1:($4 > 0 ? $2 : 1/0) smooth unique with lines lw 1.5 dt 2 lc " << (i + 1)
      << " notitle";
    s << ", '' index " << idx << " using 1:2:3 with labels offset 0.8,0.6 left font 'sans,8' tc lt " << (i + 1)
      << " notitle";
  }
  s << "\n";
  int err = 0;
  for (const auto& [path, text] : {std::pair{dataPath, d.str()}, std::pair{scriptPath, s.str()}}) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f.flush()) err = EIO;
  }
  if (err) return "cannot write gnuplot's input in " + work.path().string();
  std::string quotedScript = "'";
  for (char c : scriptPath.string()) quotedScript += c == '\'' ? std::string("'\\''") : std::string(1, c);
  std::string cmd = "gnuplot " + quotedScript + "' 2>&1";
  int rc = std::system(cmd.c_str());
  if (rc != 0) return "gnuplot failed (exit " + std::to_string(rc) + ")";
  FileReadRule rule;
  rule.maxBytes = std::size_t{256} << 20;
  FileReadFailure failure;
  auto picture = readFileChecked(drawn.string(), rule, &failure);
  if (!picture) return "gnuplot drew nothing readable: " + failure.why();
  Diagnostics io;
  if (!writeFileAtomically(png, picture->bytes, io))
    return io.all().empty() ? "cannot write" : io.all().front().message;
  return "";
}

}  // namespace wg::accuracy
