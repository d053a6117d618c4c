// What the colour pipeline costs (issue 38): each example graph rendered side by side in
// one process on one EGL context in three configurations of the runtime:
//   rgba8        frame and scene targets RGBA8, no output transform (the runtime before
//                the colour pipeline: display values written as they are)
//   rgba16f      frame and scene targets RGBA16F, no output transform
//   rgba16f+ot   RGBA16F and the output transform into the RGBA8 display image (what
//                `watergraph render` does)
// After a warm-up frame of each, `rounds` rounds render `frames` frames of every
// configuration in an order that rotates per round, so drift in the shared machine's load
// hits all alike. Reported per graph: the median frame time of each (CPU wall time around
// the frame and its glFinish, llvmpipe) and the median over rounds of each round's ratio to
// rgba8 (paired).
//
//   build/bin/wg_bench_color [--rounds N] [--frames N] [--size WxH] [--tonemap NAME] [graph ...]
//
// Defaults: 9 rounds of 2 frames, 1280x720, agx, every graph in graphs/.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime/median.h"

namespace {

using wg::rt::median;

struct Configuration {
  const char* name;
  wg::rt::ColorFormat format;
  bool outputTransform;
};
constexpr Configuration kConfigurations[] = {{"rgba8", wg::rt::ColorFormat::Rgba8, false},
                                             {"rgba16f", wg::rt::ColorFormat::Rgba16f, false},
                                             {"rgba16f+ot", wg::rt::ColorFormat::Rgba16f, true}};
constexpr size_t kCount = std::size(kConfigurations);

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr, "wg_bench_color: %s\nusage: wg_bench_color [--rounds N] [--frames N] [--size WxH] [--tonemap NAME] [graph ...]\n",
               why);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace wg;
  int rounds = 9, frames = 2, width = 1280, height = 720;
  ToneMapper toneMapper = ToneMapper::Agx;
  std::vector<std::string> graphs;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage(("missing value after " + a).c_str());
      return argv[++i];
    };
    if (a == "--rounds") rounds = std::max(1, std::atoi(next().c_str()));
    else if (a == "--frames") frames = std::max(1, std::atoi(next().c_str()));
    else if (a == "--size") {
      if (std::sscanf(next().c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1) usage("--size is WxH");
    } else if (a == "--tonemap") {
      auto t = parseToneMapper(next());
      if (!t) usage(("--tonemap is " + toneMapperList()).c_str());
      toneMapper = *t;
    } else if (!a.empty() && a[0] == '-') usage(("unknown option " + a).c_str());
    else graphs.push_back(a);
  }
  if (graphs.empty())
    for (const auto& e : std::filesystem::directory_iterator(std::string(WG_SOURCE_DIR) + "/graphs"))
      if (e.path().extension() == ".json") graphs.push_back(e.path().string());
  std::sort(graphs.begin(), graphs.end());

  try {
    auto context = rt::EglContext::create(rt::GlApi::DesktopGl45);
    std::printf("%dx%d, camera above, %d rounds of %d frames, tone mapper %s, glsl330 on %s\n\n", width, height, rounds,
                frames, std::string(toneMapperName(toneMapper)).c_str(), context->renderer().c_str());
    std::printf("| graph | rgba8 ms | rgba16f ms | rgba16f+ot ms | rgba16f / rgba8 | rgba16f+ot / rgba8 | target MiB rgba8 / rgba16f+ot |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const auto& path : graphs) {
      Diagnostics diags;
      auto graph = loadGraphFile(path, diags);
      CompileOptions options;
      options.targets = {Target::Glsl330};
      std::optional<CompileResult> result;
      if (graph) result = compileGraph(*graph, defaultRegistry(), options, diags);
      if (!result) {
        std::fprintf(stderr, "%s: does not compile\n", path.c_str());
        return 1;
      }
      std::vector<std::unique_ptr<rt::Renderer>> renderers;
      for (const Configuration& c : kConfigurations) {
        rt::RenderSettings s;
        s.width = width, s.height = height;
        s.pictureFormat = c.format;
        s.outputTransform = c.outputTransform;
        s.view = {toneMapper, 0.0};
        renderers.push_back(std::make_unique<rt::Renderer>(result->manifest, rt::waterShaderSources(*result, Target::Glsl330),
                                                           s, false, rt::textureOrigins(*result)));
        renderers.back()->renderFrame();  // warm-up: llvmpipe compiles at the first draw
      }
      std::vector<double> ms[kCount], ratio[kCount];
      for (int r = 0; r < rounds; ++r) {
        double roundMs[kCount] = {};
        for (size_t k = 0; k < kCount; ++k) {
          const size_t c = (k + static_cast<size_t>(r)) % kCount;
          for (int f = 0; f < frames; ++f) roundMs[c] += renderers[c]->renderFrame();
          ms[c].push_back(roundMs[c] / frames);
        }
        for (size_t c = 0; c < kCount; ++c) ratio[c].push_back(roundMs[c] / roundMs[0]);
      }
      auto mib = [](size_t b) { return static_cast<double>(b) / (1024.0 * 1024.0); };
      std::printf("| %s | %.1f | %.1f | %.1f | %.3f | %.3f | %.1f / %.1f |\n",
                  std::filesystem::path(path).stem().string().c_str(), median(ms[0]), median(ms[1]), median(ms[2]),
                  median(ratio[1]), median(ratio[2]), mib(renderers[0]->createdTargetBytes()),
                  mib(renderers[2]->createdTargetBytes()));
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wg_bench_color: %s\n", e.what());
    return 1;
  }
  return 0;
}
