// Generated against hand-written (issue 10): the water of the classic WebGL water renderer (graphs/classic_webgl)
// and the stylized water shader (graphs/stylized) as watergraph generates it and as written by hand in
// bench/handwritten/, run side by side in one process on one EGL context, with the same
// manifest (uniforms, textures, passes, tessellation stages) and scene.
//
// Per graph and size: two Renderers; after warm-up frames, `rounds` rounds each render
// `frames` frames of one then of the other (the order alternates per round), so drift in
// the shared machine's load hits both alike. Reported: median frame time of each (CPU
// wall time around the frame and its glFinish, llvmpipe), their ratio generated /
// hand-written, the median over rounds of each round's ratio (paired: robust to load that
// changes between rounds), the PSNR between the two images, and the SPIR-V instruction count after
// spirv-opt -O (per program: all stages; and the fragment stage alone) of both, compiled
// the same way (glsl330 under glslang's relaxed Vulkan rules; see relaxedSpirv).
//
//   build/bin/wg_bench_handwritten [--rounds N] [--frames N] [--size WxH ...] [--water-only] [--dump-spirv DIR] [graph ...]
//
// Defaults: 15 rounds of 2 frames, sizes 640x360 and 1280x720, both graphs. --water-only
// draws none of the built-in scene (SceneOptions::drawScene = false): the frame is then
// mostly the water shader, whose cost the full frame dilutes with the scene passes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "accuracy/spirv_count.h"
#include "bench/handwritten/handwritten_water.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime/runtime_error.h"
#include "runtime/median.h"

namespace {

struct Size {
  int width, height;
};

using wg::rt::median;

// Instructions after spirv-opt -O: {all stages, fragment stage}; {-1, -1} on failure.
// With dumpPrefix set, each stage's module (before -O) is written to PREFIX.STAGE.spv, to
// read with spirv-opt -O and spirv-dis where the two sides differ.
std::pair<int, int> spirvCounts(const std::vector<wg::ShaderSource>& shaders, const std::string& dumpPrefix = {}) {
  std::vector<wg::ShaderMessage> errors;
  auto modules = wg::relaxedSpirv(shaders, &errors);
  if (!modules) {
    for (const auto& e : errors) std::fprintf(stderr, "%s:%d: %s\n", e.fileName.c_str(), e.line, e.text.c_str());
    return {-1, -1};
  }
  int total = 0, fragment = 0;
  for (size_t i = 0; i < shaders.size(); ++i) {
    int n = wg::accuracy::optimisedInstructionCount((*modules)[i]);
    if (n < 0) return {-1, -1};
    if (!dumpPrefix.empty()) {
      std::ofstream out(dumpPrefix + "." + std::string(wg::stageExtension(shaders[i].stage)) + ".spv", std::ios::binary);
      out.write(reinterpret_cast<const char*>((*modules)[i].data()), static_cast<std::streamsize>((*modules)[i].size() * 4));
    }
    total += n;
    if (shaders[i].stage == wg::ShaderStage::Fragment) fragment = n;
  }
  return {total, fragment};
}

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr, "wg_bench_handwritten: %s\nusage: wg_bench_handwritten [--rounds N] [--frames N] [--size WxH ...] [--water-only] [--dump-spirv DIR] [graph ...]\n", why);
  std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 15, frames = 2;
  bool waterOnly = false;
  std::string dumpDir;
  std::vector<Size> sizes;
  std::vector<std::string> graphs;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage(("missing value after " + a).c_str());
      return argv[++i];
    };
    if (a == "--rounds") rounds = std::atoi(next().c_str());
    else if (a == "--frames") frames = std::atoi(next().c_str());
    else if (a == "--water-only") waterOnly = true;
    else if (a == "--dump-spirv") dumpDir = next();
    else if (a == "--size") {
      Size s{};
      if (std::sscanf(next().c_str(), "%dx%d", &s.width, &s.height) != 2 || s.width <= 0 || s.height <= 0) usage("bad --size");
      sizes.push_back(s);
    } else if (!a.empty() && a[0] == '-') usage(("unknown option " + a).c_str());
    else graphs.push_back(a);
  }
  if (rounds < 1 || frames < 1) usage("--rounds and --frames must be at least 1");
  if (sizes.empty()) sizes = {{640, 360}, {1280, 720}};
  if (graphs.empty()) graphs = wg::handwritten::graphs();

  std::unique_ptr<wg::rt::EglContext> context;
  try {
    context = wg::rt::EglContext::create(wg::rt::GlApi::DesktopGl45);
  } catch (const wg::rt::RuntimeError& e) {
    std::fprintf(stderr, "wg_bench_handwritten: %s\n", e.what());
    return 2;
  }
  std::printf("GL_RENDERER: %s; %d rounds x %d frames per side, interleaved; %s\n\n", context->renderer().c_str(), rounds, frames,
              waterOnly ? "water only (no scene)" : "full scene");
  std::printf("| graph | size | generated ms | hand-written ms | ratio gen/hand | paired ratio | PSNR dB | SPIR-V -O gen (frag) | SPIR-V -O hand (frag) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");

  int status = 0;
  for (const std::string& name : graphs) {
    try {
      wg::Diagnostics diags;
      auto graph = wg::loadGraphFile(std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json", diags);
      wg::CompileOptions options;
      options.targets = {wg::Target::Glsl330};
      std::optional<wg::CompileResult> result;
      if (graph) result = wg::compileGraph(*graph, wg::defaultRegistry(), options, diags);
      if (!result) {
        std::fprintf(stderr, "wg_bench_handwritten: graphs/%s.json does not compile\n", name.c_str());
        status = 1;
        continue;
      }
      auto generated = wg::handwritten::generatedShaders(*result);
      auto hand = wg::handwritten::handwrittenShaders(WG_SOURCE_DIR, name, result->manifest);
      auto [genTotal, genFrag] = spirvCounts(generated, dumpDir.empty() ? "" : dumpDir + "/" + name + ".generated");
      auto [handTotal, handFrag] = spirvCounts(hand, dumpDir.empty() ? "" : dumpDir + "/" + name + ".handwritten");
      auto origins = wg::rt::textureOrigins(*result);

      for (Size size : sizes) {
        wg::rt::RenderSettings settings;
        settings.width = size.width;
        settings.height = size.height;
        settings.scene.drawScene = !waterOnly;
        wg::rt::Renderer gen(result->manifest, wg::handwritten::forRuntime(generated), settings, false, origins);
        wg::rt::Renderer hw(result->manifest, wg::handwritten::forRuntime(hand), settings, false, origins);
        for (int w = 0; w < 2; ++w) gen.renderFrame(), hw.renderFrame();  // llvmpipe compiles at the first draw
        double psnr = wg::rt::psnrRgb8(gen.readRgba8(), hw.readRgba8());
        std::vector<double> genMs, handMs, roundRatios;
        for (int r = 0; r < rounds; ++r) {
          wg::rt::Renderer* order[2] = {&gen, &hw};
          if (r % 2) std::swap(order[0], order[1]);
          std::vector<double> roundGen, roundHand;
          for (wg::rt::Renderer* which : order)
            for (int f = 0; f < frames; ++f) (which == &gen ? roundGen : roundHand).push_back(which->renderFrame());
          genMs.insert(genMs.end(), roundGen.begin(), roundGen.end());
          handMs.insert(handMs.end(), roundHand.begin(), roundHand.end());
          roundRatios.push_back(median(roundGen) / median(roundHand));
        }
        double g = median(genMs), h = median(handMs);
        std::printf("| %s | %dx%d | %.2f | %.2f | %.3f | %.3f | %.1f | %d (%d) | %d (%d) |\n", name.c_str(), size.width,
                    size.height, g, h, g / h, median(roundRatios), psnr, genTotal, genFrag, handTotal, handFrag);
        std::fflush(stdout);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "wg_bench_handwritten: %s: %s\n", name.c_str(), e.what());
      status = 1;
    }
  }
  return status;
}
