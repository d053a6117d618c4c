// What the spectral ocean's simulation costs inside a frame (issue 41): a graph with an
// ocean (default graphs/open_ocean.json) rendered by the GL runtime, and beside it, on the
// same EGL context, the same oceans' simulation alone (runtime/ocean_simulation.h: the
// evolution, the inverse FFT passes and the packing of every cascade, then glFinish), once
// per fft_size level. After a warm-up of each, `rounds` rounds alternate whole frames and
// simulation updates (at advancing times, as frames have), in an order that rotates per
// round. Reported per level: the median frame time (CPU wall time around the frame and its
// glFinish, llvmpipe), the median simulation time, and the median over rounds of each
// round's simulation / frame ratio (paired: the frame includes one simulation update).
// With --target vk450 the same on Vulkan (lavapipe): the VkRenderer's frames, and the
// Vulkan simulation (runtime/vk_ocean_simulation.h) recorded into a command buffer of its
// own, submitted and waited for.
//
//   build/bin/wg_bench_ocean [--rounds N] [--size WxH] [--fft-sizes 64,128,256] [--target glsl330|vk450] [graph]
//
// Defaults: 9 rounds, 1280x720, fft_size 64, 128 and 256, graphs/open_ocean.json.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "core/ocean_foam.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/median.h"
#include "runtime/ocean_simulation.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime/vk_context.h"
#include "runtime/vk_ocean_simulation.h"
#include "runtime/vk_preview.h"
#include "runtime/vk_renderer.h"

namespace {

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "wg_bench_ocean: %s\nusage: wg_bench_ocean [--rounds N] [--size WxH] [--fft-sizes 64,128,256] "
               "[--target glsl330|vk450] [graph]\n",
               why);
  std::exit(2);
}

// The graph with every ocean_spectrum node's fft_size set to `n`.
wg::Graph withFftSize(wg::Graph graph, int n) {
  for (auto& node : graph.nodes) {
    if (node.type != "ocean_spectrum") continue;
    auto it = std::find_if(node.options.begin(), node.options.end(), [](const auto& o) { return o.name == "fft_size"; });
    if (it != node.options.end())
      it->value = n;
    else
      node.options.push_back({"fft_size", n, {}, {}});
  }
  return graph;
}

using FrameFunction = std::function<double()>;            // renders a frame, returns its ms
using UpdateFunction = std::function<void(double)>;        // a simulation update to t, waited for
using StepsFunction = std::function<int()>;                // the foam steps the last update ran

// The rounds, the table's row and the foam's line for one fft_size (file comment).
void measure(int rounds, int n, size_t cascades, const nlohmann::json& oceanOptions, const FrameFunction& frame,
             const UpdateFunction& update, const StepsFunction& lastFoamSteps) {
  frame();  // warm-up: llvmpipe and lavapipe compile at the first draw
  double time = 3.5;
  update(time);
  std::vector<double> frameMs, simulationMs, ratio;
  for (int r = 0; r < rounds; ++r) {
    double frameTime = 0, updateTime = 0;
    for (int k = 0; k < 2; ++k) {
      if ((k + r) % 2 == 0) {
        frameTime = frame();
      } else {
        time += 1.0 / 60.0;
        auto start = std::chrono::steady_clock::now();
        update(time);
        updateTime = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      }
    }
    frameMs.push_back(frameTime);
    simulationMs.push_back(updateTime);
    ratio.push_back(updateTime / frameTime);
  }
  std::printf("| %d | %zu | %.1f | %.1f | %.3f |\n", n, cascades, wg::rt::median(frameMs), wg::rt::median(simulationMs),
              wg::rt::median(ratio));
  // The persistent foam: the rounds above step it at most once (a step every foam_step
  // seconds of 1/60 s frames), so its cost is measured apart: a still frame's replay (the
  // first frame, or one after a jump in time), and from it one step's cost.
  time += 1000;
  auto start = std::chrono::steady_clock::now();
  update(time);
  const double replayMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const int steps = lastFoamSteps();
  if (steps > 0) {
    const double stepMs = (replayMs - wg::rt::median(simulationMs)) / steps;
    // Per 60 fps frame each foam cascade steps (1/60) / foam_step times on average.
    wg::ocean::FoamSettings foam;
    foam.step = oceanOptions.value("foam_step", foam.step);
    foam.decay = oceanOptions.value("foam_decay", foam.decay);
    const int foamCascades = steps / (wg::ocean::historySteps(foam) + 1);
    std::printf("|   | foam: a still frame's replay %d steps %.1f ms; a step %.2f ms; an animation at 60 fps %.2f ms a frame |\n",
                steps, replayMs, stepMs, stepMs * foamCascades * (1.0 / 60.0) / foam.step);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace wg;
  int rounds = 9, width = 1280, height = 720;
  std::vector<int> sizes = {64, 128, 256};
  std::string path = std::string(WG_SOURCE_DIR) + "/graphs/open_ocean.json";
  bool vulkan = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage(("missing value after " + a).c_str());
      return argv[++i];
    };
    if (a == "--rounds") {
      rounds = std::max(1, std::atoi(next().c_str()));
    } else if (a == "--size") {
      if (std::sscanf(next().c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1) usage("--size is WxH");
    } else if (a == "--fft-sizes") {
      sizes.clear();
      std::stringstream list(next());
      for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::atoi(item.c_str()));
    } else if (a == "--target") {
      const std::string t = next();
      if (t != "glsl330" && t != "vk450") usage("--target is glsl330 or vk450");
      vulkan = t == "vk450";
    } else if (!a.empty() && a[0] == '-') {
      usage(("unknown option " + a).c_str());
    } else {
      path = a;
    }
  }

  try {
    // One context for every level: EGL for glsl330, a Vulkan device (no validation) for vk450.
    std::unique_ptr<rt::EglContext> context;
    std::unique_ptr<rt::VkContext> vkContext;
    if (vulkan)
      vkContext = rt::VkContext::create({});
    else
      context = rt::EglContext::create(rt::GlApi::DesktopGl45);
    std::printf("%s, %dx%d, camera above, %d rounds, %s on %s\n\n", path.c_str(), width, height, rounds,
                vulkan ? "vk450" : "glsl330", vulkan ? vkContext->deviceName().c_str() : context->renderer().c_str());
    std::printf("| fft_size | cascades | frame ms | simulation ms | simulation / frame |\n|---|---|---|---|---|\n");
    Diagnostics loadDiags;
    auto original = loadGraphFile(path, loadDiags);
    if (!original) {
      std::fprintf(stderr, "%s: does not load\n", path.c_str());
      return 1;
    }
    for (int n : sizes) {
      Diagnostics diags;
      std::optional<Graph> graph = withFftSize(*original, n);
      CompileOptions options;
      options.targets = {vulkan ? Target::Vk450 : Target::Glsl330};
      std::optional<CompileResult> result;
      if (graph) result = compileGraph(*graph, defaultRegistry(), options, diags);
      if (!result || result->manifest.oceans.empty()) {
        std::fprintf(stderr, "%s (fft_size %d): does not compile, or has no ocean\n", path.c_str(), n);
        return 1;
      }
      rt::RenderSettings s;
      s.width = width, s.height = height;
      size_t cascades = 0;
      for (const auto& o : result->manifest.oceans) cascades += o.options.value("tile_lengths", nlohmann::json::array()).size();
      const nlohmann::json& oceanOptions = result->manifest.oceans.front().options;
      if (vulkan) {
        rt::VkRenderer renderer(*vkContext, result->manifest, rt::waterSpirv(*result), s, rt::textureOrigins(*result));
        rt::VkOceanSimulation simulation(*vkContext, result->manifest.oceans, result->manifest.textures);
        simulation.setFoamHistory(rt::FoamHistory::Continue);  // frames follow one another, as in an animation
        measure(
            rounds, n, cascades, oceanOptions, [&] { return renderer.renderFrame(); },
            [&](double t) { vkContext->submit([&](VkCommandBuffer cmd) { simulation.record(cmd, t); }); },
            [&] { return simulation.lastFoamSteps(); });
        continue;
      }
      rt::Renderer renderer(result->manifest, rt::waterShaderSources(*result, Target::Glsl330), s, false,
                            rt::textureOrigins(*result));
      rt::OceanSimulation simulation(result->manifest.oceans, result->manifest.textures, rt::SceneShaderApi::Gl330);
      simulation.setFoamHistory(rt::FoamHistory::Continue);  // frames follow one another, as in an animation
      measure(
          rounds, n, cascades, oceanOptions, [&] { return renderer.renderFrame(); },
          [&](double t) {
            simulation.update(t);
            glFinish();
          },
          [&] { return simulation.lastFoamSteps(); });
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wg_bench_ocean: %s\n", e.what());
    return 1;
  }
  return 0;
}
