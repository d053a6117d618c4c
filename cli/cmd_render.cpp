// render: compile one graph for glsl330, es300 (EGL, Mesa llvmpipe) or vk450 (Vulkan, Mesa
// lavapipe) and run it headless in the built-in scene; write the frame as a PNG, optionally with pass and timing stats.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/frame_size_text.h"
#include "cli/commands.h"
#include "cli/option_values.h"
#include "cli/finite_number.h"
#include "cli/view_flags.h"

#ifdef WG_HAVE_RUNTIME
#include "codegen/compile.h"
#include "codegen/output_files.h"
#include "codegen/texture_files.h"
#include "core/graph_io.h"
#include "core/node_preview_graph.h"
#include "nodes/registry.h"
#include "runtime/floating_buoys.h"
#include "runtime/image.h"
#include "runtime/ocean_simulation.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"
#include "runtime/vk_preview.h"
#endif

namespace wg::cli {
namespace {

struct RenderArgs {
  std::string graph;
  std::string output;
  std::string size = "1280x720";
  double time = 3.5;
  std::string camera = "above";
  std::string target = "glsl330";
  int frames = 1;
  bool stats = false;
  float sunAzimuth = 110.0f;    // = rt::SceneOptions defaults
  float sunElevation = 30.0f;
  int grid = 128;  // = rt::RenderSettings default
  std::string preset;
  bool obliqueReflection = false;
  std::string scene = "builtin";
  bool buoys = false;
  bool vulkanValidation = false;
  ViewFlags view;
};

#ifdef WG_HAVE_RUNTIME
std::string formatBytes(size_t b) {
  char buf[64];
  if (b >= 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(b) / (1024.0 * 1024.0));
  else std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(b) / 1024.0);
  return buf;
}

const char* colorName(rt::ColorFormat f) {
  switch (f) {
    case rt::ColorFormat::None: return "";
    case rt::ColorFormat::Rgba8: return "RGBA8";
    case rt::ColorFormat::Rgba16f: return "RGBA16F";
    case rt::ColorFormat::Rgba32f: return "RGBA32F";
  }
  return "";
}

void printStats(const RenderArgs& args, const std::string& name, const rt::Preview& p, const ViewTransform& view,
                const Manifest& manifest) {
  std::printf("render %s: %s on %s (%s), %dx%d, camera %s, time %g s, view %s at %g EV\n", name.c_str(),
              args.target.c_str(), p.renderer.c_str(), p.version.c_str(), p.image.width, p.image.height,
              args.camera.c_str(), args.time, std::string(toneMapperName(view.toneMapper)).c_str(), view.exposureEv);
  std::string passes;
  for (auto k : p.plan.passes) passes += (passes.empty() ? "" : ", ") + std::string(rt::passName(k));
  std::printf("passes: %s\n", passes.c_str());
  std::printf("render targets: %d, %zu bytes (%s)\n", p.targetCount, p.targetBytes, formatBytes(p.targetBytes).c_str());
  for (const auto& t : p.plan.targets) {
    std::string fmt = colorName(t.color);
    if (t.depth != rt::DepthFormat::None) fmt += std::string(fmt.empty() ? "" : " + ") + "DEPTH32F";
    std::string dims = std::to_string(t.width) + "x" + std::to_string(t.height) + (t.cube ? "x6" : "");
    std::printf("  %-12s %-12s %-18s %10zu bytes  %s\n", t.name.c_str(), dims.c_str(), fmt.c_str(), t.bytes(),
                t.name == rt::kDisplayTarget ? "(the PNG: the frame through the output transform)"
                : t.sampler.empty()          ? "(the frame: linear radiance)"
                                             : t.sampler.c_str());
  }
  // The spectral ocean's own float textures (runtime/ocean_simulation.h), beside the targets.
  if (!manifest.oceans.empty()) {
    size_t bytes = rt::OceanSimulation::textureBytes(manifest.oceans, manifest.textures);
    std::printf("ocean simulation: %zu bytes (%s) of float textures (amplitudes, spectra, maps)\n", bytes,
                formatBytes(bytes).c_str());
  }
  double lo = p.frameMs.front(), hi = p.frameMs.front();
  for (double v : p.frameMs) lo = std::min(lo, v), hi = std::max(hi, v);
  std::printf("frame time: median %.2f ms over %zu frame%s (min %.2f, max %.2f; CPU clock around glFinish; "
              "first frame %.0f ms, untimed)\n",
              p.medianMs(), p.frameMs.size(), p.frameMs.size() == 1 ? "" : "s", lo, hi, p.warmupMs);
}

int runRender(const RenderArgs& args, const GlobalOptions& global) {
  const auto size = parseFrameSizeText(args.size, 1, 8192);
  if (!size) {
    std::cerr << "watergraph: --size must be WIDTHxHEIGHT with each side 1..8192, e.g. 1280x720 (got '" << args.size
              << "')\n";
    return kExitUsageOrIo;
  }
  Target target = *parseTarget(args.target);
  if (args.vulkanValidation && target != Target::Vk450) {
    std::cerr << "watergraph: --vk-validation needs --target vk450 (the layer checks Vulkan calls)\n";
    return kExitUsageOrIo;
  }
  if (args.buoys && (args.scene != "builtin" || target == Target::Vk450)) {
    std::cerr << "watergraph: --buoys floats the built-in scene's buoys: it needs --scene builtin and a GL target "
                 "(glsl330, es300)\n";
    return kExitUsageOrIo;
  }
  // -o was checked before the command ran (cli/option_values.h, checkOutputPaths).
  Diagnostics diags;
  auto graph = loadGraphFile(args.graph, diags);
  // A function graph with no output slots shows its first interface output, as in the editor.
  if (std::string why; graph && graph->interface && graph->outputs.empty())
    if (auto shown = interfaceOutputGraph(*graph, &why)) graph = std::move(shown);
  std::optional<CompileResult> result;
  if (graph) {
    CompileOptions options;
    options.targets = {target};
    options.preset = args.preset;
    result = compileGraph(*graph, defaultRegistry(), options, diags);
  }
  printDiagnostics(diags, global);
  if (!result) return exitCodeFor(diags);

  rt::RenderSettings settings;
  settings.width = size->width;
  settings.height = size->height;
  settings.camera = args.camera;
  settings.scene.time = args.time;
  settings.waterGridQuads = args.grid;
  settings.obliqueReflection = args.obliqueReflection;
  settings.scene.sunAzimuthDegrees = args.sunAzimuth;
  settings.scene.sunElevationDegrees = args.sunElevation;
  settings.scene.drawScene = args.scene == "builtin";
  if (args.buoys) {
    std::vector<Value> parameters;
    for (const auto& p : result->program.parameters) parameters.push_back(p.defaultValue);
    settings.scene.buoys = rt::floatingBuoys(result->program, parameters, args.time);
  }
  settings.view = args.view.over(result->program.view);
  try {
    rt::Preview p = target == Target::Vk450
                        ? rt::renderVulkanPreview(*result, settings, args.frames, /*warmup=*/args.stats, args.vulkanValidation)
                        : rt::renderPreview(*result, target, settings, args.frames, /*warmup=*/args.stats);
    rt::writePng(args.output, p.image);
    if (args.stats) printStats(args, graphBaseName(args.graph), p, settings.view, result->manifest);
  } catch (const rt::TextureLoadError& e) {
    Diagnostics textureDiags;
    reportUnusableTexture(result->program, &*graph, e.source(), e.why(), textureDiags);
    printDiagnostics(textureDiags, global);
    return kExitGraphError;
  } catch (const rt::RuntimeError& e) {
    std::cerr << args.graph << ": error: " << e.what() << "\n";
    return e.exitCode();
  }
  return kExitOk;
}
#endif

}  // namespace

Runner addRenderCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Compile a graph and run it headless (EGL or Vulkan; Mesa llvmpipe and lavapipe work everywhere) in the built-in scene: a sky with a "
      "sun, a tiled pool sloping up to a sandy shore towards -x, pillars and rocks crossing the water. Only the passes "
      "the manifest lists run. Writes the frame as a PNG.\n\nExamples:\n"
      "  watergraph render graphs/lake.json -o lake.png\n"
      "  watergraph render graphs/lake.json -o lake.png --size 640x360 --camera grazing --time 2\n"
      "  watergraph render graphs/lake.json -o lake.png --target es300 --frames 20 --stats\n"
      "  watergraph render graphs/topdown.json -o choppy.png --preset choppy --camera topdown\n"
      "  watergraph render graphs/lake.json -o water.png --target es300 --scene none   # the water alone, on black\n"
      "  watergraph render graphs/lake.json -o lake_vk.png --target vk450 --vk-validation\n"
      "  watergraph render graphs/ocean.json -o ocean.png --tonemap agx --exposure 0.5\n\n"
      "Exit codes: 0 ok; 1 graph errors, a shader the driver rejects or a validation message; 2 usage, I/O, or no "
      "EGL/GL context or Vulkan device.\n\n"
      "The frame is linear, scene-referred radiance in RGBA16F targets; the PNG is that through the output "
      "transform: exposure (--exposure EV), a tone mapper (--tonemap none|aces|agx|neutral) and the sRGB encoding. "
      "Both default to the graph's \"view\".");
  cmd->add_option("graph", args->graph, "graph file (.json)")->required();
  addOutputOption(cmd, "-o,--output", args->output, "PNG file to write (written atomically)")->required();
  cmd->add_option("--size", args->size, "WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->add_option("--time", args->time, "scene time in seconds (u_time)")->check(finiteFloat())->capture_default_str();
  cmd->add_option("--camera", args->camera, "camera preset: above, grazing, underwater, topdown")
      ->check(CLI::IsMember({"above", "grazing", "underwater", "topdown"}))
      ->capture_default_str();
  cmd->add_option("--target", args->target,
                  "shaders to run: glsl330 (OpenGL 4.5 core), es300 (OpenGL ES 3.2) or vk450 (the SPIR-V on Vulkan 1.3)")
      ->check(CLI::IsMember({"glsl330", "es300", "vk450"}))
      ->capture_default_str();
  cmd->add_flag("--vk-validation", args->vulkanValidation,
                "vk450: run under the Khronos validation layer; any message it reports fails the render (exit 1)");
  cmd->add_option("--frames", args->frames, "frames to time; --stats renders one untimed warm-up frame first and reports the median")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  cmd->add_flag("--stats", args->stats, "print the passes that ran, render targets (count, bytes) and ms per frame");
  cmd->add_option("--sun-azimuth", args->sunAzimuth, "sun direction: degrees from +x towards +z")
      ->check(finiteFloat())
      ->capture_default_str();
  cmd->add_option("--sun-elevation", args->sunElevation, "sun height above the horizon in degrees")
      ->check(finiteFloat() & CLI::Range(-90.0f, 90.0f))
      ->capture_default_str();
  cmd->add_option("--scene", args->scene,
                  "builtin: the sky, pool, shore, pillars and rocks; none: only the water, over opaque black (nothing "
                  "else in any pass), e.g. to compare with another renderer such as clients/three/")
      ->check(CLI::IsMember({"builtin", "none"}))
      ->capture_default_str();
  cmd->add_flag("--buoys", args->buoys,
                "float the built-in scene's three buoys on the water: each where the graph's vertex stage moves its "
                "rest point at --time, tilted to the surface (GL targets; docs/queries.md)");
  cmd->add_option("--grid", args->grid, "quads per side of the 40 x 40 m water grid (finer for short waves; costs time on llvmpipe)")
      ->check(CLI::Range(1, 2048))
      ->capture_default_str();
  addViewFlags(cmd, args->view);
  cmd->add_option("--preset", args->preset, "a preset from the graph's \"presets\" table (e.g. calm, moderate, choppy)");
  cmd->add_flag("--oblique-reflection", args->obliqueReflection,
                "clip the planar reflection pass with an oblique near plane on the water (the stylized water shader's) instead of a clip "
                "plane (the classic WebGL water renderer's)");
#ifdef WG_HAVE_RUNTIME
  return [args, &global] { return runRender(*args, global); };
#else
  return [] {
    std::cerr << "watergraph: render: this build has no GL runtime (configure with -DWG_BUILD_RUNTIME=ON)\n";
    return kExitUsageOrIo;
  };
#endif
}

}  // namespace wg::cli
