// Edit-to-pixels: an editor changes one parameter default of a graph and waits for the
// first frame drawn with the new shader. Each iteration: the edited file text is loaded,
// compiled for the preview target (glslang validation included, as `watergraph compile`
// does), the Renderer is rebuilt (targets created, programs linked or taken from the
// editor's GpuCache) and one frame is rendered and finished on llvmpipe. The EGL context
// lives across iterations, as in an editor. Wall time: llvmpipe renders on several threads.
// Two variants per graph and size: `cached` rebuilds the way the editor does (one GpuCache
// across edits), `relink` links every program again (the editor before the cache).
//
//   build/bin/wg_bench_edit [graph.json ...] --benchmark_repetitions=9 --benchmark_enable_random_interleaving=true
//
// With no graph named, graphs/ocean.json when it exists, else graphs/lake.json.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/gpu_cache.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime/runtime_error.h"

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct EditCase {
  std::string path;
  wg::Graph graph;  // as loaded; each iteration edits a copy
  int parameter = -1;
  // A graph without parameters gets its first number literal edited (node, input) instead.
  int node = -1, input = -1;
  std::string edited() const {
    if (parameter >= 0) return "$" + graph.parameters[static_cast<size_t>(parameter)].name;
    const wg::Node& n = graph.nodes[static_cast<size_t>(node)];
    return n.id + "." + n.inputs[static_cast<size_t>(input)].port;
  }
};

// The graph text with the edited number's first component nudged (alternately up and
// down, inside a parameter's range), in the canonical form an editor saves.
std::string editedText(const EditCase& c, int iteration) {
  wg::Graph g = c.graph;
  double step = iteration % 2 == 0 ? 0.01 : -0.01;
  if (c.parameter >= 0) {
    wg::Parameter& p = g.parameters[static_cast<size_t>(c.parameter)];
    double& x = p.defaultValue[0];
    if ((p.max && x + step > *p.max) || (p.min && x + step < *p.min)) step = -step;
    x += step;
  } else {
    g.nodes[static_cast<size_t>(c.node)].inputs[static_cast<size_t>(c.input)].source.literal[0] += step;
  }
  return wg::saveGraph(g);
}

void editToPixels(benchmark::State& state, EditCase* c, wg::rt::EglContext* context, int width, int height,
                  bool cached) {
  wg::rt::GpuCache cache;
  wg::rt::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  double loadMs = 0, compileMs = 0, rebuildMs = 0, frameMs = 0, steadyMs = 0;
  int iteration = 0;
  {
    // Untimed: the graph as it was before the edit, on screen, as in the editor.
    wg::Diagnostics diags;
    wg::CompileOptions options;
    options.targets = {wg::Target::Glsl330};
    auto before = wg::compileGraph(c->graph, wg::defaultRegistry(), options, diags);
    if (!before) {
      state.SkipWithError("the graph does not compile");
      return;
    }
    wg::rt::Renderer shown(before->manifest, wg::rt::waterShaderSources(*before, wg::Target::Glsl330), settings,
                           context->isEs(), wg::rt::textureOrigins(*before), cached ? &cache : nullptr);
    shown.renderFrame();
  }
  const size_t linksBefore = cache.stats().programLinks;
  for (auto _ : state) {
    state.PauseTiming();
    std::string text = editedText(*c, iteration++);
    state.ResumeTiming();

    auto t0 = Clock::now();
    wg::Diagnostics diags;
    auto g = wg::parseGraph(text, c->path, diags);
    if (!g) {
      state.SkipWithError("the edited graph does not load");
      break;
    }
    loadMs += msSince(t0);
    auto t1 = Clock::now();
    wg::CompileOptions options;
    options.targets = {wg::Target::Glsl330};
    auto result = wg::compileGraph(*g, wg::defaultRegistry(), options, diags);
    if (!result) {
      state.SkipWithError("the edited graph does not compile");
      break;
    }
    compileMs += msSince(t1);
    auto t2 = Clock::now();
    wg::rt::Renderer renderer(result->manifest, wg::rt::waterShaderSources(*result, wg::Target::Glsl330), settings,
                              context->isEs(), wg::rt::textureOrigins(*result), cached ? &cache : nullptr);
    rebuildMs += msSince(t2);
    auto t3 = Clock::now();
    renderer.renderFrame();  // ends with glFinish: the pixels exist
    frameMs += msSince(t3);
    // Not timed: a second frame, whose cost is drawing alone (llvmpipe compiles the
    // programs at their first draw), to split the first frame into compile and draw.
    state.PauseTiming();
    steadyMs += renderer.renderFrame();
    state.ResumeTiming();
  }
  using benchmark::Counter;
  state.counters["load_ms"] = Counter(loadMs, Counter::kAvgIterations);
  state.counters["compile_ms"] = Counter(compileMs, Counter::kAvgIterations);
  state.counters["rebuild_ms"] = Counter(rebuildMs, Counter::kAvgIterations);
  state.counters["frame_ms"] = Counter(frameMs, Counter::kAvgIterations);
  state.counters["next_frame_ms"] = Counter(steadyMs, Counter::kAvgIterations);
  // Programs linked per edit with the cache (0: every shader text was seen before).
  if (cached)
    state.counters["links"] = Counter(static_cast<double>(cache.stats().programLinks - linksBefore), Counter::kAvgIterations);
  state.SetLabel(c->edited() + " edited");
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);  // removes the --benchmark_* flags; graphs remain
  std::vector<std::string> paths(argv + 1, argv + argc);
  if (paths.empty()) {
    std::string graphs = std::string(WG_SOURCE_DIR) + "/graphs/";
    paths.push_back(std::filesystem::exists(graphs + "ocean.json") ? graphs + "ocean.json" : graphs + "lake.json");
  }
  std::unique_ptr<wg::rt::EglContext> context;
  try {
    context = wg::rt::EglContext::create(wg::rt::GlApi::DesktopGl45);
  } catch (const wg::rt::RuntimeError& e) {
    std::fprintf(stderr, "wg_bench_edit: %s\n", e.what());
    return 2;
  }
  std::vector<std::unique_ptr<EditCase>> cases;
  for (const auto& path : paths) {
    wg::Diagnostics diags;
    auto g = wg::loadGraphFile(path, diags);
    if (!g) {
      for (const auto& d : diags.sorted()) std::fprintf(stderr, "%s\n", wg::formatText(d).c_str());
      return 1;
    }
    auto c = std::make_unique<EditCase>();
    c->path = path;
    c->graph = std::move(*g);
    for (size_t i = 0; i < c->graph.parameters.size() && c->parameter < 0; ++i)
      if (!c->graph.parameters[i].isStatic) c->parameter = static_cast<int>(i);
    for (size_t n = 0; n < c->graph.nodes.size() && c->parameter < 0 && c->node < 0; ++n)
      for (size_t i = 0; i < c->graph.nodes[n].inputs.size() && c->node < 0; ++i)
        if (c->graph.nodes[n].inputs[i].source.kind == wg::InputSource::Kind::Literal)
          c->node = static_cast<int>(n), c->input = static_cast<int>(i);
    if (c->parameter < 0 && c->node < 0) {
      std::fprintf(stderr, "wg_bench_edit: %s has no parameter or number to edit\n", path.c_str());
      return 1;
    }
    std::string name = "edit_to_pixels/" + std::filesystem::path(path).stem().string();
    for (bool cached : {true, false})
      for (auto [w, h] : {std::pair{1280, 720}, std::pair{640, 360}})
        benchmark::RegisterBenchmark(
            (name + "/" + std::to_string(w) + "x" + std::to_string(h) + (cached ? "/cached" : "/relink")).c_str(),
            editToPixels, c.get(), context.get(), w, h, cached)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->MinTime(1.0);
    cases.push_back(std::move(c));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
