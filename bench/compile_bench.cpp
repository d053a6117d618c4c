// Compile speed: load, resolve, each pass, emit per target, manifest, and glslang per
// target, measured separately on synthetic graphs of 10 to 100,000 nodes and on every
// graph in graphs/. `before_glslang` is the whole compile a user waits for except glslang
// (load + compileGraph without validation: resolve, passes, three emits, manifest).
//
//   build/bin/wg_bench_compile --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
//
// After the runs it prints a markdown summary (medians when repeated) with the ratios the
// targets are about: t(10k)/t(1k) and our time against glslang's on the same output.
#include <benchmark/benchmark.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/alloc_counter.h"
#include "bench/synthetic_graph.h"
#include "codegen/compile.h"
#include "codegen/glslang_validate.h"
#include "codegen/manifest_build.h"
#include "codegen/passes.h"
#include "core/graph_load.h"
#include "core/graph_parse.h"
#include "core/resolve.h"
#include "nodes/registry.h"

namespace wg::bench {
namespace {

// The calling thread's CPU time: what a pass costs, whatever else the machine runs.
struct ThreadCpuClock {
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<ThreadCpuClock, duration>;
  static time_point now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return time_point(duration(static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec));
  }
};
using Clock = ThreadCpuClock;

const char* const kPasses[] = {"bypass", "specialise", "prune", "fold", "simplify", "cse", "prune_final", "stages"};

// One graph to measure, and the values each phase starts from (made once, on first use,
// so filtered-out cases cost nothing).
struct Case {
  std::string name;  // "synthetic_1000", "lake"
  std::string file;  // the name diagnostics and texture paths use
  std::string text;
  // The text as the CLI holds it once read (core/graph_io.h): loads share it with their
  // diagnostics rather than copy it. Made on first use, before any heap window opens.
  std::shared_ptr<const std::string> sharedText() const {
    if (!shared_) shared_ = std::make_shared<const std::string>(text);
    return shared_;
  }
  mutable std::shared_ptr<const std::string> shared_;

  struct Prepared {
    Graph graph;
    Program resolved;  // before the passes
    Program program;   // after them
    TargetPlans plans;  // what the manifest is built from
    std::map<Target, std::vector<ShaderSource>> sources;
  };
  const Prepared& prepared() {
    if (!prep_) prep_ = prepare();
    return *prep_;
  }

 private:
  std::unique_ptr<Prepared> prepare() const {
    auto p = std::make_unique<Prepared>();
    Diagnostics diags;
    auto g = loadGraphText(sharedText(), file, diags);
    if (!g) throw std::runtime_error(name + ": does not load");
    p->graph = std::move(*g);
    auto r = resolveGraph(p->graph, defaultRegistry(), diags);
    if (!r) throw std::runtime_error(name + ": does not resolve");
    p->resolved = *r;
    PassContext ctx{diags};
    p->program = std::move(*r);
    if (!runPassRecipe(p->program, ctx)) throw std::runtime_error(name + ": a pass failed");
    std::string base = graphBaseName(file);
    p->plans = planTargets(p->program, allTargets(), file);
    for (size_t i = 0; i < allTargets().size(); ++i) {
      Target t = allTargets()[i];
      EmitResult er = emitGlsl(p->plans.of(i), t);
      auto& src = p->sources[t];
      for (const auto& sh : er.shaders)
        src.push_back({sh.stage, base + "." + std::string(targetName(t)) + "." + std::string(stageExtension(sh.stage)), sh.text});
    }
    return p;
  }
  std::unique_ptr<Prepared> prep_;
};

// instances_N.json for each N, importing lib/unit.json, into `dir`.
void writeInstanceGraphs(const std::filesystem::path& dir, const std::vector<int>& counts) {
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "lib/unit.json") << R"({"version": 1, "name": "unit",
  "interface": {"outputs": {"color": {"type": "vec3", "source": "lit.out"}}},
  "parameters": {"seed": {"type": "float", "default": 1}, "f0": {"type": "float", "default": 0.02, "min": 0, "max": 1}},
  "nodes": [
    {"id": "p", "type": "world_position"},
    {"id": "s", "type": "mul", "inputs": {"a": "p.out", "b": "$seed"}},
    {"id": "l", "type": "length", "inputs": {"x": "s.out"}},
    {"id": "w", "type": "sin", "inputs": {"x": "l.out"}},
    {"id": "f", "type": "fresnel", "inputs": {"f0": "$f0"}},
    {"id": "m", "type": "mix", "inputs": {"a": [0, 0.2, 0.3], "b": [0.5, 0.7, 0.9], "t": "f.reflectance"}},
    {"id": "k", "type": "mul", "inputs": {"a": "w.out", "b": 0.1}},
    {"id": "lit", "type": "add", "inputs": {"a": "m.out", "b": "k.out"}}
  ]})";
  for (int n : counts) {
    std::string nodes;
    for (int i = 0; i < n; ++i) {
      std::string id = "u" + std::to_string(i);
      nodes += R"(    {"id": ")" + id + R"(", "type": "unit", "inputs": {"seed": )" + std::to_string(i + 1) + "}},\n";
      if (i == 0) continue;
      std::string sumSoFar = i == 1 ? "u0.color" : "sum" + std::to_string(i - 1) + ".out";
      nodes += R"(    {"id": "sum)" + std::to_string(i) + R"(", "type": "add", "inputs": {"a": ")" + sumSoFar +
               R"(", "b": ")" + id + R"(.color"}},)" + "\n";
    }
    std::string last = n == 1 ? "u0.color" : "sum" + std::to_string(n - 1) + ".out";
    nodes.resize(nodes.size() - 2);  // the last ",\n"
    std::ofstream(dir / ("instances_" + std::to_string(n) + ".json"))
        << R"({"version": 1, "name": "instances", "imports": {"unit": "lib/unit.json"}, "nodes": [)" << "\n"
        << nodes << "\n  ],\n" << R"(  "outputs": {"fragment": {"color": ")" << last << R"("}}})" << "\n";
  }
}

std::vector<std::unique_ptr<Case>>& cases() {
  static std::vector<std::unique_ptr<Case>> all;
  return all;
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// The file and the subgraphs it imports (each read and parsed once).
void load(benchmark::State& state, Case* c) {
  for (auto _ : state) {
    Diagnostics diags;
    auto g = loadGraphText(c->sharedText(), c->file, diags);
    if (!g) state.SkipWithError("load failed");
    benchmark::DoNotOptimize(g);
  }
  state.counters["bytes"] = static_cast<double>(c->text.size());
  // The peak heap of one more load, the Graph included.
  startHeapWindow();
  {
    Diagnostics diags;
    auto g = loadGraphText(c->sharedText(), c->file, diags);
  }
  state.counters["peak_MiB"] = static_cast<double>(stopHeapWindow()) / (1024.0 * 1024.0);
}

// The floor under `load`: nlohmann's SAX parse of the same text into handlers that keep
// nothing (the lexer still makes every string and number), so the two together say how
// much of a load is the loader's own.
struct NullSax {
  using json = nlohmann::json;
  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t) { return true; }
  bool number_float(json::number_float_t, const json::string_t&) { return true; }
  bool string(json::string_t&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool start_object(std::size_t) { return true; }
  bool end_object() { return true; }
  bool start_array(std::size_t) { return true; }
  bool end_array() { return true; }
  bool key(json::string_t&) { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }
};

void jsonSaxFloor(benchmark::State& state, Case* c) {
  for (auto _ : state) {
    NullSax sax;
    if (!nlohmann::json::sax_parse(c->text, &sax)) state.SkipWithError("not JSON");
  }
  state.counters["bytes"] = static_cast<double>(c->text.size());
}

void resolve(benchmark::State& state, Case* c) {
  const Graph& g = c->prepared().graph;
  for (auto _ : state) {
    Diagnostics diags;
    auto p = resolveGraph(g, defaultRegistry(), diags);
    if (!p) state.SkipWithError("resolve failed");
    benchmark::DoNotOptimize(p);
  }
  state.counters["nodes"] = static_cast<double>(g.nodes.size());
}

// One pass, timed inside the real recipe (its rounds summed, thread CPU time) on a fresh
// copy of the resolved program each iteration; the copy is not timed.
void pass(benchmark::State& state, Case* c, std::string passName) {
  const Program& resolved = c->prepared().resolved;
  int calls = 0;
  for (auto _ : state) {
    Program p = resolved;
    Diagnostics diags;
    PassContext ctx{diags};
    Clock::time_point start;
    Clock::duration spent{};
    PassHooks hooks;
    hooks.before = [&](std::string_view n) {
      if (n == passName) start = Clock::now();
    };
    hooks.after = [&](std::string_view n) {
      if (n == passName) spent += Clock::now() - start, ++calls;
    };
    if (!runPassRecipe(p, ctx, &hooks)) state.SkipWithError("recipe failed");
    state.SetIterationTime(seconds(spent));
  }
  state.counters["runs"] = benchmark::Counter(calls, benchmark::Counter::kAvgIterations);
}

void emit(benchmark::State& state, Case* c, Target target) {
  const Program& p = c->prepared().program;
  size_t lines = 0;
  for (auto _ : state) {
    EmitResult er = emitProgram(p, target, c->file);
    lines = 0;
    for (const auto& sh : er.shaders) lines += sh.lineOp.size();
    benchmark::DoNotOptimize(er);
  }
  state.counters["lines"] = static_cast<double>(lines);
}

void manifest(benchmark::State& state, Case* c) {
  const auto& prep = c->prepared();
  std::string base = graphBaseName(c->file);
  for (auto _ : state) {
    std::string text = buildManifest(prep.program, prep.plans, base).fileText();
    benchmark::DoNotOptimize(text);
  }
}

// Everything a compile does before glslang, as `watergraph compile` runs it: for every
// target, or (`only`) for one, as `--target es300` (what a WebGL2 page uses, and what
// three.js TSL's build() makes: bench/tsl/).
CompileResult compileWithoutGlslang(const Case& c, std::optional<Target> only = std::nullopt) {
  Diagnostics diags;
  auto g = loadGraphText(c.sharedText(), c.file, diags);
  if (!g) throw std::runtime_error(c.name + ": does not load");
  CompileOptions options;
  options.validate = false;
  if (only) options.targets = {*only};
  auto r = compileGraph(*g, defaultRegistry(), options, diags);
  if (!r) throw std::runtime_error(c.name + ": does not compile");
  return std::move(*r);
}

void beforeGlslang(benchmark::State& state, Case* c, std::optional<Target> only) {
  int kept = 0;
  for (auto _ : state) {
    CompileResult r = compileWithoutGlslang(*c, only);
    kept = r.nodesKept;
    benchmark::DoNotOptimize(r);
  }
  // The peak heap of one more compile, above what was live before it.
  startHeapWindow();
  { CompileResult r = compileWithoutGlslang(*c, only); }
  state.counters["peak_MiB"] = static_cast<double>(stopHeapWindow()) / (1024.0 * 1024.0);
  state.counters["kept"] = kept;
}

void glslang(benchmark::State& state, Case* c, Target target) {
  const auto& sources = c->prepared().sources.at(target);
  validateShaders(target, sources);  // glslang's one-time process set-up stays out of the loop
  for (auto _ : state) {
    ValidationResult vr = validateShaders(target, sources);
    if (!vr.ok) state.SkipWithError("glslang rejected the shaders");
    benchmark::DoNotOptimize(vr);
  }
  startHeapWindow();
  { ValidationResult vr = validateShaders(target, sources); }
  state.counters["peak_MiB"] = static_cast<double>(stopHeapWindow()) / (1024.0 * 1024.0);
}

// Registers every phase of one case. Large cases run fewer, longer iterations.
void registerCase(Case* c, int nodes) {
  auto tune = [nodes](benchmark::internal::Benchmark* b) {
    b->Unit(benchmark::kMillisecond);
    if (nodes >= 100000) b->Iterations(3);
    return b;
  };
  std::string n = "/" + c->name;
  tune(benchmark::RegisterBenchmark(("json_sax_floor" + n).c_str(), jsonSaxFloor, c));
  tune(benchmark::RegisterBenchmark(("load" + n).c_str(), load, c));
  tune(benchmark::RegisterBenchmark(("resolve" + n).c_str(), resolve, c));
  for (const char* p : kPasses)
    tune(benchmark::RegisterBenchmark(("pass_" + std::string(p) + n).c_str(), pass, c, std::string(p)))->UseManualTime();
  for (Target t : allTargets())
    tune(benchmark::RegisterBenchmark(("emit_" + std::string(targetName(t)) + n).c_str(), emit, c, t));
  tune(benchmark::RegisterBenchmark(("manifest" + n).c_str(), manifest, c));
  tune(benchmark::RegisterBenchmark(("before_glslang" + n).c_str(), beforeGlslang, c, std::nullopt));
  tune(benchmark::RegisterBenchmark(("before_glslang_es300" + n).c_str(), beforeGlslang, c, std::optional(Target::Es300)));
  for (Target t : allTargets()) {
    auto* b = tune(benchmark::RegisterBenchmark(("glslang_" + std::string(targetName(t)) + n).c_str(), glslang, c, t));
    if (nodes >= 100000) b->Iterations(1);  // ~10-30 s each: glslang on a 100,000-line shader
  }
}

// Collects the median (or the single run) of every benchmark for the summary.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.error_occurred) continue;
      std::string name = r.run_name.str();
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      if (r.run_type == Run::RT_Iteration && r.repetitions > 1) continue;  // the aggregate follows
      // CPU time: the machines are shared, and wall time counts the neighbours' work too.
      // Passes are timed by hand with the thread's CPU clock (their "real" time).
      bool manual = stripManual(name) != name;
      ms_[stripManual(name)] = toMs(manual ? r.GetAdjustedRealTime() : r.GetAdjustedCPUTime(), r.time_unit);
      for (const auto& [key, counter] : r.counters) counters_[stripManual(name)][key] = counter.value;
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n| graph | nodes (kept) | load | resolve | passes | emit x3 | manifest | before glslang | glslang x3 | ours / glslang | peak heap MiB (ours, glslang vk450) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& c : cases()) {
      std::string n = "/" + c->name;
      auto get = [&](const std::string& k) -> std::optional<double> {
        auto it = ms_.find(k + n);
        if (it == ms_.end()) return std::nullopt;
        return it->second;
      };
      auto total = get("before_glslang");
      if (!total) continue;
      double passes = 0, emits = 0, glsl = 0;
      bool haveGlslang = true;
      for (const char* p : kPasses) passes += get("pass_" + std::string(p)).value_or(0);
      for (Target t : allTargets()) {
        emits += get("emit_" + std::string(targetName(t))).value_or(0);
        auto g = get("glslang_" + std::string(targetName(t)));
        haveGlslang &= g.has_value();
        glsl += g.value_or(0);
      }
      const auto& bc = counters_["before_glslang" + n];
      const auto& gc = counters_["glslang_vk450" + n];
      auto rc = counters_.find("resolve" + n);
      double nodes = rc != counters_.end() ? rc->second["nodes"] : 0;
      std::printf("| %s | %.0f (%.0f) | %s | %s | %s | %s | %s | %s | %s | %s | %.2f, %s |\n", c->name.c_str(), nodes,
                  bc.count("kept") ? bc.at("kept") : 0.0, fmt(get("load")).c_str(), fmt(get("resolve")).c_str(),
                  fmt(passes).c_str(), fmt(emits).c_str(), fmt(get("manifest")).c_str(), fmt(total).c_str(),
                  haveGlslang ? fmt(glsl).c_str() : "-",
                  haveGlslang ? (std::to_string(static_cast<int>(100 * *total / glsl + 0.5)) + " %").c_str() : "-",
                  bc.count("peak_MiB") ? bc.at("peak_MiB") : 0.0,
                  gc.count("peak_MiB") ? fmtNumber(gc.at("peak_MiB")).c_str() : "-");
    }
    auto t1k = ms_.find("before_glslang/synthetic_1000"), t10k = ms_.find("before_glslang/synthetic_10000");
    if (t1k != ms_.end() && t10k != ms_.end())
      std::printf("\nt(10k)/t(1k) before glslang: %.2f (%.3f ms / %.3f ms)\n", t10k->second / t1k->second, t10k->second,
                  t1k->second);
    for (const char* size : {"1000", "10000"}) {
      auto load = ms_.find(std::string("load/synthetic_") + size);
      auto floor = ms_.find(std::string("json_sax_floor/synthetic_") + size);
      if (load != ms_.end() && floor != ms_.end())
        std::printf("load at %s nodes: %.3f ms against nlohmann's SAX parse alone %.3f ms (%.2fx)\n", size, load->second,
                    floor->second, load->second / floor->second);
    }
    std::printf("process peak RSS: %.1f MiB\n", static_cast<double>(maxResidentBytes()) / (1024.0 * 1024.0));
  }

 private:
  static std::string stripManual(std::string name) {
    const std::string suffix = "/manual_time";
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      name.resize(name.size() - suffix.size());
    auto it = name.find("/iterations:");
    if (it != std::string::npos) name.resize(it);
    return name;
  }
  static double toMs(double t, benchmark::TimeUnit u) {
    switch (u) {
      case benchmark::kNanosecond: return t / 1e6;
      case benchmark::kMicrosecond: return t / 1e3;
      case benchmark::kMillisecond: return t;
      case benchmark::kSecond: return t * 1e3;
    }
    return t;
  }
  static std::string fmtNumber(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", x);
    return buf;
  }
  static std::string fmt(std::optional<double> ms) {
    if (!ms) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, *ms < 1 ? "%.3f ms" : "%.1f ms", *ms);
    return buf;
  }
  std::map<std::string, double> ms_;
  std::map<std::string, std::map<std::string, double>> counters_;
};

}  // namespace
}  // namespace wg::bench

int main(int argc, char** argv) {
  using namespace wg::bench;
  for (int n : {10, 100, 1000, 10000, 100000}) {
    auto c = std::make_unique<Case>();
    c->name = "synthetic_" + std::to_string(n);
    c->file = c->name + ".json";
    c->text = syntheticGraphJson(n);
    registerCase(c.get(), n);
    cases().push_back(std::move(c));
  }
  // A graph of N instances of one function graph (graphs/lib-like, eight nodes), each fed
  // a different literal so that none merges: compile time against the inlined size.
  std::filesystem::path instancesDir = std::filesystem::temp_directory_path() / ("wg_bench_instances_" + std::to_string(::getpid()));
  writeInstanceGraphs(instancesDir, {1, 10, 100, 1000});
  for (int n : {1, 10, 100, 1000}) {
    auto c = std::make_unique<Case>();
    c->name = "instances_" + std::to_string(n);
    c->file = (instancesDir / (c->name + ".json")).string();
    wg::Diagnostics diags;
    c->text = *wg::readGraphFile(c->file, diags);
    registerCase(c.get(), n * 9);
    cases().push_back(std::move(c));
  }
  std::vector<std::filesystem::path> graphs;
  for (const auto& e : std::filesystem::directory_iterator(std::string(WG_SOURCE_DIR) + "/graphs"))
    if (e.path().extension() == ".json") graphs.push_back(e.path());
  std::sort(graphs.begin(), graphs.end());
  for (const auto& path : graphs) {
    wg::Diagnostics diags;
    auto text = wg::readGraphFile(path.string(), diags);
    if (!text) continue;
    auto c = std::make_unique<Case>();
    c->name = path.stem().string();
    c->file = path.string();
    c->text = std::move(*text);
    registerCase(c.get(), 0);
    cases().push_back(std::move(c));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  std::error_code ec;
  std::filesystem::remove_all(instancesDir, ec);
  return 0;
}
