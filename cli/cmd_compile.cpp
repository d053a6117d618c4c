// compile: graphs -> GLSL files + manifest (and MSL / HLSL through SPIRV-Cross); validate:
// the same checks, nothing written. Batch runs draw a progress bar when stdout is a
// terminal; --watch recompiles a graph when its file changes.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <memory>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "cli/commands.h"
#include "cli/option_values.h"
#include "codegen/compile.h"
#include "codegen/query_header.h"
#include "codegen/depfile.h"
#include "core/node_preview_graph.h"
#include "codegen/frequency_report.h"
#include "codegen/output_files.h"
#include "core/shown_text.h"
#include "codegen/spirv_cross_targets.h"
#include "codegen/compile_wgsl.h"
#include "cli/wgsl_checks.h"
#include "codegen/texture_files.h"
#include "core/graph_imports.h"
#include "core/graph_load.h"
#include "core/graph_io.h"
#include "core/texture_check.h"
#include "nodes/registry.h"

namespace wg::cli {
namespace {

struct CompileArgs {
  std::vector<std::string> graphs;
  std::string outDir;
  std::vector<std::string> targets;
  bool subdirs = false;
  bool summary = false;
  bool quiet = false;
  bool verbose = false;
  bool noProgress = false;
  bool watch = false;
  int watchIntervalMs = 250;
  std::string preset;
  bool textures = false;  // also write <graph>.<sampler>.png for every node texture
  std::string depfile;    // write a Make/Ninja depfile here
  bool explainFrequency = false;  // print each graph's frequency report (codegen/frequency_report.h)
};

constexpr std::string_view kQueryCTarget = "query-c";
constexpr std::string_view kQueryJsTarget = "query-js";
constexpr std::string_view kWgslTarget = "wgsl";
constexpr const char* kTargetNames = "glsl330, es300, vk450, msl, hlsl, wgsl, query-c, query-js";

struct TargetSet {
  std::vector<Target> glsl;
  std::vector<CrossTarget> cross;
  // query-c / query-js: <graph>.query.h / <graph>.query.js, the surface queries of the
  // vertex stage's displacement (codegen/query_header.h).
  bool queryC = false, queryJs = false;
  // wgsl: <graph>.wgsl for WebGPU (codegen/compile_wgsl.h); alone, it compiles glsl330 too,
  // the GLSL its WGSL is written from.
  bool wgsl = false;
  std::string list() const {
    std::string s;
    for (Target t : glsl) s += (s.empty() ? "" : ",") + std::string(targetName(t));
    for (CrossTarget t : cross) s += (s.empty() ? "" : ",") + std::string(crossTargetName(t));
    if (wgsl) s += (s.empty() ? "" : ",") + std::string(kWgslTarget);
    if (queryC) s += (s.empty() ? "" : ",") + std::string(kQueryCTarget);
    if (queryJs) s += (s.empty() ? "" : ",") + std::string(kQueryJsTarget);
    return s;
  }
  size_t size() const {
    return glsl.size() + cross.size() + (wgsl ? 1 : 0) + (queryC ? 1 : 0) + (queryJs ? 1 : 0);
  }
};

bool parseTargets(const std::vector<std::string>& names, TargetSet& out) {
  out = {};
  for (const auto& n : names) {
    std::stringstream ss(n);
    std::string part;
    if (n.empty()) {
      std::cerr << "watergraph: --target is empty (" << kTargetNames << ")\n";
      return false;
    }
    // getline drops a trailing empty entry: "glsl330," would pass as "glsl330".
    if (n.front() == ',' || n.back() == ',' || n.find(",,") != std::string::npos) {
      std::cerr << "watergraph: --target '" << n << "' has an empty entry (a comma too many)\n";
      return false;
    }
    while (std::getline(ss, part, ',')) {
      if (auto t = parseTarget(part)) {
        bool dup = false;
        for (Target have : out.glsl) dup |= have == *t;
        if (!dup) out.glsl.push_back(*t);
      } else if (part == kQueryCTarget) {
        out.queryC = true;
      } else if (part == kQueryJsTarget) {
        out.queryJs = true;
      } else if (part == kWgslTarget) {
        out.wgsl = true;
      } else if (auto c = parseCrossTarget(part)) {
        bool dup = false;
        for (CrossTarget have : out.cross) dup |= have == *c;
        if (!dup) out.cross.push_back(*c);
      } else {
        std::cerr << "watergraph: unknown target '" << part << "' (" << kTargetNames << ")\n";
        return false;
      }
    }
  }
  if (out.glsl.empty() && out.cross.empty()) out.glsl = out.wgsl ? std::vector<Target>{Target::Glsl330} : allTargets();
  return true;
}

struct GraphOutcome {
  std::string name;
  int kept = 0, total = 0;
  bool ok = false;
  size_t errors = 0;
  size_t files = 0;
  double ms = 0;
  DepfileRule dependencies;  // when written: the files written and the files read
  std::string frequency;     // --explain-frequency: the graph's report
  std::vector<std::string> notRun;  // validate --target wgsl: "naga: why it did not run"
};

// validate --target wgsl: naga and Tint on the module (cli/wgsl_checks.h). Their errors are
// diagnostics at the nodes (WG046); a checker that could not run is listed in `notRun`.
bool checkWgslExternally(const CompileResult& result, const std::string& base, GraphOutcome& outcome, Diagnostics& diags) {
  const std::string file = base + ".wgsl";
  const std::string* wgsl = nullptr;
  for (const auto& f : result.files)
    if (f.name == file) wgsl = &f.contents;
  if (!wgsl) return true;
  bool ok = true;
  for (auto run : {runNagaCheck, runTintCheck}) {
    WgslCheckOutcome c = run(*wgsl);
    if (!c.ran) outcome.notRun.push_back(c.checker + ": " + c.notRunBecause);
    for (const auto& e : c.errors) {
      ok = false;
      reportWgslMessage(result.program, result.wgslLineOp, e.line,
                        c.checker + " rejected the generated WGSL at " + file + ":" + std::to_string(e.line) + ":" +
                            std::to_string(e.column) + ": " + e.text,
                        DiagCode::WgslRejected, diags);
    }
  }
  return ok;
}

void printSummary(std::FILE* to, const std::vector<GraphOutcome>& outcomes, const TargetSet& targets) {
  std::string targetList = targets.list();
  size_t w = 5;
  // Printed with printf, so each name is escaped here (core/shown_text.h).
  for (const auto& o : outcomes) w = std::max(w, escapedForTerminal(o.name).size());
  std::fprintf(to, "%-*s  %-11s  %-21s  %s\n", static_cast<int>(w), "graph", "nodes", "targets", "status");
  std::fprintf(to, "%s\n", std::string(w + 2 + 11 + 2 + 21 + 2 + 16, '-').c_str());
  int failed = 0;
  for (const auto& o : outcomes) {
    std::string nodes = o.total ? std::to_string(o.kept) + "/" + std::to_string(o.total) : "-";
    std::string status = o.ok ? "ok" : "FAILED (" + std::to_string(o.errors) + " error" + (o.errors == 1 ? "" : "s") + ")";
    std::fprintf(to, "%-*s  %-11s  %-21s  %s\n", static_cast<int>(w), escapedForTerminal(o.name).c_str(), nodes.c_str(), targetList.c_str(),
                 status.c_str());
    failed += !o.ok;
  }
  std::fprintf(to, "%zu graph%s, %d failed\n", outcomes.size(), outcomes.size() == 1 ? "" : "s", failed);
}

// A one-line bar redrawn in place on a terminal: "[#########.........]  4/10  lake".
class ProgressBar {
 public:
  ProgressBar(bool enabled, size_t total) : enabled_(enabled && total > 1), total_(total) {}
  ~ProgressBar() { clear(); }
  void show(size_t done, const std::string& current) {
    if (!enabled_) return;
    const int width = 30;
    int filled = total_ ? static_cast<int>(width * done / total_) : width;
    std::string bar(static_cast<size_t>(filled), '#');
    bar += std::string(static_cast<size_t>(width - filled), '.');
    std::string name = escapedForTerminal(current.size() > 40 ? current.substr(0, 37) + "..." : current);
    std::fprintf(stdout, "\r\033[K[%s] %zu/%zu  %s", bar.c_str(), done, total_, name.c_str());
    std::fflush(stdout);
    drawn_ = true;
  }
  void clear() {
    if (!drawn_) return;
    std::fputs("\r\033[K", stdout);
    std::fflush(stdout);
    drawn_ = false;
  }

 private:
  bool enabled_;
  size_t total_;
  bool drawn_ = false;
};

std::string nowHms() {
  std::time_t t = std::time(nullptr);
  char buf[16];
  std::strftime(buf, sizeof buf, "%H:%M:%S", std::localtime(&t));
  return buf;
}

// What a build system needs to know about one compiled graph: the files written into
// `dir` depend on the graph's file, every graph it imports, every PNG it samples and every
// .glsl file its function nodes call. The node textures `--textures` writes and a spectral
// ocean's web module (<graph>.ocean.js, es300 and wgsl) are not named as targets: whether
// they exist, and the textures' names, come from the graph, which a build system has not
// read when it declares a rule's outputs (Ninja refuses a depfile naming an output the rule
// did not declare); they are written by the same command as the manifest, so they are
// current whenever it is.
DepfileRule dependenciesOf(const Graph& graph, const CompileResult& result, const std::string& dir) {
  DepfileRule rule;
  auto isNodeTexture = [&](const std::string& name) {
    return std::any_of(result.manifest.textures.begin(), result.manifest.textures.end(),
                       [&](const TextureInfo& t) { return !t.source.empty() && t.file == name; });
  };
  for (const auto& f : result.files)
    if (!isNodeTexture(f.name) && f.name != result.manifest.oceanModule) rule.outputs.push_back(dir + "/" + f.name);
  // The manifest first: Ninja takes a depfile's first target for the build edge's first
  // output, and watergraph_add_shaders (cmake/WatergraphShaders.cmake) lists it first.
  std::stable_partition(rule.outputs.begin(), rule.outputs.end(),
                        [](const std::string& f) { return f.ends_with(".manifest.json"); });
  rule.inputs = graphFilesRead(graph);
  std::filesystem::path graphDir = std::filesystem::path(graph.file).parent_path();
  for (const auto& t : result.manifest.textures)
    if (!t.source.empty() && t.source.rfind(kBuiltinTexturePrefix, 0) != 0)
      rule.inputs.push_back((graphDir / t.source).lexically_normal().string());
  // The .glsl files of its GLSL function nodes (relative to the graph's folder).
  for (const auto& f : result.program.functionFiles) rule.inputs.push_back((graphDir / f).lexically_normal().string());
  return rule;
}

// Compiles one graph (and writes it when `write`). Diagnostics go to `diags`.
GraphOutcome compileOne(const std::string& path, const CompileArgs& args, const TargetSet& targets, bool write,
                        Diagnostics& diags) {
  auto start = std::chrono::steady_clock::now();
  GraphOutcome outcome;
  outcome.name = graphBaseName(path);
  auto graph = loadGraphFile(path, diags);
  // A function graph with no output slots (a library of node types) is compiled through its
  // first interface output, as the editor previews it; validate checks each output so.
  std::optional<Graph> library;
  if (graph && graph->interface && graph->outputs.empty()) {
    std::string why;
    library = *graph;
    if (auto shown = interfaceOutputGraph(*library, &why)) graph = std::move(shown);
  }
  std::optional<CompileResult> result;
  if (graph) {
    CompileOptions options;
    options.targets = targets.glsl;
    options.preset = args.preset;
    options.wgsl = targets.wgsl;
    result = compileGraphWithCross(*graph, defaultRegistry(), options, targets.cross, diags);
    for (size_t i = 1; library && result && !write && i < library->interface->outputs.size(); ++i) {
      std::string why;
      if (auto other = interfaceOutputGraph(*library, &why, i))
        if (!compileGraphWithCross(*other, defaultRegistry(), options, targets.cross, diags)) result.reset();
    }
    if (result && targets.queryC) {
      if (auto h = queryCHeader(outcome.name, result->program, diags)) result->files.push_back({outcome.name + ".query.h", *h});
      else result.reset();
    }
    if (result && targets.queryJs) {
      if (auto m = queryJsModule(outcome.name, result->program, diags)) result->files.push_back({outcome.name + ".query.js", *m});
      else result.reset();
    }
    outcome.total = result ? result->nodesTotal : static_cast<int>(graph->nodes.size());
  }
  if (result && targets.wgsl && !write && !checkWgslExternally(*result, outcome.name, outcome, diags)) result.reset();
  if (result && args.textures) {
    auto pngs = textureFiles(*result, diags, &*graph);
    if (diags.hasErrors()) result.reset();
    else result->files.insert(result->files.end(), pngs.begin(), pngs.end());
  }
  if (result) {
    outcome.kept = result->nodesKept;
    if (args.explainFrequency) outcome.frequency = formatFrequencyReport(result->program, frequencyReport(result->program));
    outcome.files = result->files.size();
    if (write) {
      std::string dir = args.subdirs ? args.outDir + "/" + outcome.name : args.outDir;
      outcome.ok = writeOutputFiles(dir, result->files, diags);
      if (outcome.ok) outcome.dependencies = dependenciesOf(*graph, *result, dir);
    } else {
      outcome.ok = true;
    }
  }
  outcome.errors = diags.errorCount();
  outcome.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

std::string outcomeLine(const std::string& path, const GraphOutcome& o, const CompileArgs& args, bool write) {
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.0f ms", o.ms);
  if (!o.ok)
    return escapedForTerminal(path) + ": FAILED (" + std::to_string(o.errors) + " error" + (o.errors == 1 ? "" : "s") + ", " + ms + ")";
  std::string dir = args.subdirs ? args.outDir + "/" + o.name : args.outDir;
  std::string s = escapedForTerminal(path) + ": ok, " + std::to_string(o.kept) + "/" + std::to_string(o.total) + " nodes kept";
  if (write) s += ", " + std::to_string(o.files) + " files in " + escapedForTerminal(dir);
  return s + " (" + ms + ")";
}

// The depfile of every graph's last successful compile (--depfile), written atomically.
bool writeDepfile(const CompileArgs& args, const std::vector<GraphOutcome>& outcomes, Diagnostics& diags) {
  std::vector<DepfileRule> rules;
  for (const auto& o : outcomes)
    if (!o.dependencies.outputs.empty()) rules.push_back(o.dependencies);  // not yet compiled in --watch: no rule
  auto text = depfileText(rules, args.depfile, diags);
  return text && writeFileAtomically(args.depfile, *text, diags);
}

std::atomic<bool> gStop{false};
extern "C" void onStopSignal(int) { gStop = true; }

// Polls the modification times and sizes of the graph files, of every graph they import
// and of what their last good compile read besides (the depfile's inputs: PNG textures and
// the .glsl files of function nodes); recompiles a graph when any of its files changes.
int watchLoop(const CompileArgs& args, const TargetSet& targets, const GlobalOptions& global,
              std::vector<GraphOutcome> outcomes) {
  namespace fs = std::filesystem;
  struct Stamp {
    fs::file_time_type time{};
    uintmax_t size = 0;
    bool exists = false;
    bool operator!=(const Stamp& o) const { return time != o.time || size != o.size || exists != o.exists; }
  };
  auto stampOf = [](const std::string& p) {
    Stamp s;
    std::error_code ec;
    s.time = fs::last_write_time(p, ec);
    if (ec) return s;
    s.size = fs::file_size(p, ec);
    s.exists = !ec;
    return s;
  };
  // Per graph: each file it is made of, with its stamp (re-listed after each change: an
  // edit may add or drop an import, a texture or a function file).
  using Watched = std::vector<std::pair<std::string, Stamp>>;
  auto watchMore = [&](Watched& files, const std::vector<std::string>& paths) {
    for (const auto& f : paths)
      if (std::none_of(files.begin(), files.end(), [&](const auto& w) { return w.first == f; })) files.emplace_back(f, stampOf(f));
  };
  auto watchedOf = [&](const std::string& graph, const DepfileRule& lastGood) {
    Watched files;
    watchMore(files, graphFilesToWatch(graph));
    watchMore(files, lastGood.inputs);
    return files;
  };
  std::vector<Watched> watched;
  for (size_t i = 0; i < args.graphs.size(); ++i) watched.push_back(watchedOf(args.graphs[i], outcomes[i].dependencies));
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  std::cout << "watching " << args.graphs.size() << " graph" << (args.graphs.size() == 1 ? "" : "s")
            << " for changes (every " << args.watchIntervalMs << " ms; Ctrl-C to stop)" << std::endl;
  while (!gStop) {
    std::this_thread::sleep_for(std::chrono::milliseconds(args.watchIntervalMs));
    for (size_t i = 0; i < args.graphs.size() && !gStop; ++i) {
      bool changed = false;
      for (auto& [file, stamp] : watched[i]) {
        Stamp now = stampOf(file);
        changed |= now != stamp;
        stamp = now;
      }
      if (!changed) continue;
      if (!stampOf(args.graphs[i]).exists) continue;  // mid-save by an editor; the next change brings it back
      watched[i] = watchedOf(args.graphs[i], outcomes[i].dependencies);
      Diagnostics diags;
      GraphOutcome o = compileOne(args.graphs[i], args, targets, true, diags);
      // An edit may add or drop an import, a texture or a function file: the depfile and the
      // watch follow (a failed compile keeps the last good one's dependencies, as it keeps
      // its files).
      if (o.ok) outcomes[i] = o, watchMore(watched[i], o.dependencies.inputs);
      if (!args.depfile.empty() && o.ok) writeDepfile(args, outcomes, diags);
      printDiagnostics(diags, global);
      std::cout << "[" << nowHms() << "] recompiled " << outcomeLine(args.graphs[i], o, args, true) << std::endl;
    }
  }
  std::cout << "watch stopped" << std::endl;
  return kExitOk;
}

int runCompile(const CompileArgs& args, const GlobalOptions& global, bool write) {
  TargetSet targets;
  if (!parseTargets(args.targets, targets)) return kExitUsageOrIo;
  if (args.quiet && args.verbose) {
    std::cerr << "watergraph: --quiet and --verbose exclude each other\n";
    return kExitUsageOrIo;
  }
  // Two graphs whose files share a name would write the same output files (with
  // --subdirs, into the same folder), the second silently replacing the first: refused
  // before anything is written.
  if (write) {
    std::map<std::string, std::string> byName;
    for (const auto& path : args.graphs) {
      auto [it, fresh] = byName.emplace(graphBaseName(path), path);
      std::error_code ec1, ec2;
      if (fresh || it->second == path ||
          std::filesystem::weakly_canonical(it->second, ec1) == std::filesystem::weakly_canonical(path, ec2))
        continue;  // the same file, however spelled: compiled again into the same files
      std::cerr << "watergraph: '" << it->second << "' and '" << path << "' would both write " << args.outDir << "/"
                << it->first << (args.subdirs ? "/" : ".*") << "; compile them into different output folders\n";
      return kExitUsageOrIo;
    }
  }
  // Paths known now that a depfile could not hold are refused before anything is compiled
  // (those of imports and textures are known only once the graphs are read).
  if (write && !args.depfile.empty()) {
    Diagnostics depfile;
    std::vector<std::string> known = args.graphs;
    known.push_back(args.outDir);
    for (const auto& path : known)
      if (std::string why = depfilePathProblem(path); !why.empty())
        depfile.error(DiagCode::FileWrite, SourceRef{args.depfile, 0, 0}, "cannot write '" + path + "' into the depfile: " + why);
    if (depfile.hasErrors()) {
      printDiagnostics(depfile, global);
      return kExitUsageOrIo;
    }
  }
  // The depfile is written after every graph's files: one that cannot be written was found
  // before any of them (cli/option_values.h, checkOutputPaths), so a failing --depfile
  // leaves no compiled files behind.
  const bool textFormat = global.diagnosticsFormat == "text";
  // SARIF owns stdout: human-readable lines go to stderr instead.
  std::FILE* info = global.diagnosticsFormat == "sarif" ? stderr : stdout;
  ProgressBar progress(!args.noProgress && !args.quiet && textFormat && isatty(STDOUT_FILENO), args.graphs.size());
  Diagnostics all;
  std::vector<GraphOutcome> outcomes;
  std::vector<std::string> verboseLines;
  for (size_t i = 0; i < args.graphs.size(); ++i) {
    const auto& path = args.graphs[i];
    progress.show(i, path);
    Diagnostics diags;
    GraphOutcome outcome = compileOne(path, args, targets, write, diags);
    if (args.verbose) {
      progress.clear();
      std::fprintf(info, "%s\n", outcomeLine(path, outcome, args, write).c_str());
      std::fflush(info);
    }
    all.append(diags);
    outcomes.push_back(outcome);
  }
  progress.show(args.graphs.size(), "done");
  progress.clear();
  if (write && !args.depfile.empty() && !all.hasErrors()) writeDepfile(args, outcomes, all);
  printDiagnostics(all, global);
  for (const auto& o : outcomes) std::fputs(escapedKeepingLines(o.frequency).c_str(), info);
  if (args.summary) printSummary(info, outcomes, targets);
  int code = kExitOk;
  if (!all.hasErrors()) {
    // A check that could not run is said, every time, and never counted as passed.
    std::set<std::string> notRun;
    for (const auto& o : outcomes) notRun.insert(o.notRun.begin(), o.notRun.end());
    for (const auto& why : notRun) std::fprintf(info, "wgsl: not validated by %s\n", escapedForTerminal(why).c_str());
    if (!write && !args.summary && !args.quiet)
      std::fprintf(info, "validated %zu graph%s for %zu target%s: %s\n", args.graphs.size(),
                   args.graphs.size() == 1 ? "" : "s", targets.size(), targets.size() == 1 ? "" : "s",
                   notRun.empty() ? "ok" : "ok where checked; wgsl NOT fully validated (see above)");
    if (write && args.verbose)
      std::fprintf(info, "compiled %zu graph%s for %s\n", args.graphs.size(), args.graphs.size() == 1 ? "" : "s",
                   targets.list().c_str());
  } else {
    code = exitCodeFor(all);
  }
  std::fflush(info);
  if (write && args.watch) return watchLoop(args, targets, global, std::move(outcomes));
  return code;
}

void addCommonOptions(CLI::App* cmd, CompileArgs& args) {
  cmd->add_option("--target", args.targets,
                  "targets, comma separated: glsl330, es300, vk450 (default: these three), msl, hlsl (from the vk450 "
                  "SPIR-V through SPIRV-Cross), wgsl (<graph>.wgsl for WebGPU: both entry points in one module; alone it "
                  "compiles glsl330 too; validate runs naga and Tint on it where Node.js and Chromium are installed), query-c and query-js "
                  "(<graph>.query.h, <graph>.query.js: where the water surface is, its height, normal and velocity, "
                  "from the vertex stage's displacement, for game code; docs/queries.md)");
  auto* quiet = cmd->add_flag("-q,--quiet", args.quiet, "print only errors");
  cmd->add_flag("-v,--verbose", args.verbose, "print one line per graph: nodes kept, files, time")->excludes(quiet);
  cmd->add_flag("--no-progress", args.noProgress, "no progress bar (it is drawn only when stdout is a terminal)");
  cmd->add_option("--preset", args.preset,
                  "a preset from the graph's \"presets\" table (e.g. calm, moderate, choppy): its values become the "
                  "parameter defaults; static parameters fold into the shader");
  cmd->add_flag("--explain-frequency", args.explainFrequency,
                "print, per graph, how many ops are constant, per-draw, per-vertex and per-fragment, and the per-draw "
                "values the fragment stage computes for every pixel, each with its estimated operations per pixel "
                "(operators, built-in calls and the operations inside library functions, counted 1 each; constructors, "
                "swizzles and signs free; vector width ignored)");
}

}  // namespace

Runner addCompileCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compile",
      "Compile graphs to GLSL (and SPIR-V for vk450) plus a manifest; every shader is validated by glslang first "
      "and nothing is written for a graph that fails. With --target msl or hlsl, SPIRV-Cross translates the vk450 "
      "SPIR-V into <graph>.msl.{vert,frag} or <graph>.hlsl.{vert,frag}.\n\nExamples:\n"
      "  watergraph compile graphs/lake.json -o out\n"
      "  watergraph compile graphs/*.json -o out --subdirs --summary\n"
      "  watergraph compile graphs/lake.json -o out --target es300\n"
      "  watergraph compile graphs/lake.json -o out --target msl,hlsl\n"
      "  watergraph compile graphs/ocean.json -o out --target glsl330,query-c   # shaders + ocean.query.h\n"
      "  watergraph compile graphs/lake.json -o out --target es300 --textures   # for the three.js client\n"
      "  watergraph compile graphs/*.json -o out --verbose\n"
      "  watergraph compile graphs/lake.json -o out --watch        # recompile on every save\n"
      "  watergraph compile graphs/*.json -o out --diagnostics-format sarif > watergraph.sarif");
  cmd->add_option("graphs", args->graphs, "graph files (.json)")->required();
  addOutputFolderOption(cmd, "-o,--output", args->outDir, "output folder")->required();
  addCommonOptions(cmd, *args);
  cmd->add_flag("--subdirs", args->subdirs, "write each graph into OUTPUT/<graph>/");
  cmd->add_flag("--summary", args->summary, "print a table: graph, nodes kept/total, targets, status");
  cmd->add_flag("--textures", args->textures,
                "also write every node texture the manifest lists (built-in ones generated, PNG sources re-encoded) as "
                "<graph>.<sampler>.png, for clients such as clients/three/");
  cmd->add_flag("-w,--watch", args->watch,
                "after compiling, keep running and recompile a graph whenever its file changes (polls modification "
                "times); stop with Ctrl-C");
  addOutputOption(cmd, "--depfile", args->depfile,
                  "also write a Make/Ninja depfile: the files written for each graph depend on its file, every graph "
                  "it imports, every PNG texture it samples and every .glsl file its function nodes call (for build systems: "
                  "CMake's DEPFILE, Ninja's depfile)");
  cmd->add_option("--watch-interval", args->watchIntervalMs, "milliseconds between polls in --watch")
      ->check(CLI::Range(10, 60000))
      ->capture_default_str();
  return [args, &global] { return runCompile(*args, global, true); };
}

Runner addValidateCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate",
      "Compile graphs for every target and validate them with glslang without writing anything: exit 0 when all "
      "pass, 1 with one line per failure.\n\nExamples:\n  watergraph validate graphs/*.json\n"
      "  watergraph validate graphs/lake.json --diagnostics-format json\n"
      "  watergraph validate graphs/*.json --diagnostics-format sarif > watergraph.sarif   # for code scanning\n"
      "  watergraph validate graphs/*.json --target glsl330,hlsl --quiet\n"
      "  watergraph validate graphs/*.json --explain-frequency   # what is the same for every pixel of a draw");
  cmd->add_option("graphs", args->graphs, "graph files (.json)")->required();
  addCommonOptions(cmd, *args);
  return [args, &global] { return runCompile(*args, global, false); };
}

}  // namespace wg::cli
