// scene: the built-in scene `render` draws, as JSON for other renderers (clients/three
// builds it in three.js from this file): mesh, cameras, sun, environment views, water grid
// and the ES 3.00 shaders of the runtime's own passes.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/option_values.h"
#include "cli/finite_number.h"

#ifdef WG_HAVE_RUNTIME
#include "codegen/output_files.h"
#include "runtime/scene_description.h"
#endif

namespace wg::cli {

Runner addSceneCommand(CLI::App& app, const GlobalOptions& global) {
  struct Args {
    std::string output;
    float sunAzimuth = 110.0f;  // = rt::SceneOptions defaults, as `render`
    float sunElevation = 30.0f;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "scene",
      "Print the built-in scene that `render` draws (sky, pool floor, shore, pillars, rocks) as JSON: the opaque "
      "mesh, the camera presets, the sun direction, the environment cube's views, the water grid and the GLSL ES "
      "3.00 shaders of the runtime's own passes, so another renderer draws the same scene (clients/three/ does).\n\n"
      "Examples:\n"
      "  watergraph scene -o public/scene.json\n"
      "  watergraph scene --sun-elevation 10 > low_sun.json");
  addOutputOption(cmd, "-o,--output", args->output, "write the JSON to this file (atomically) instead of stdout");
  cmd->add_option("--sun-azimuth", args->sunAzimuth, "sun direction: degrees from +x towards +z")
      ->check(finiteFloat())
      ->capture_default_str();
  cmd->add_option("--sun-elevation", args->sunElevation, "sun height above the horizon in degrees")
      ->check(finiteFloat() & CLI::Range(-90.0f, 90.0f))
      ->capture_default_str();
#ifdef WG_HAVE_RUNTIME
  return [args, &global] {
    rt::SceneOptions options;
    options.sunAzimuthDegrees = args->sunAzimuth;
    options.sunElevationDegrees = args->sunElevation;
    std::string text = rt::sceneDescriptionJson(options);
    if (args->output.empty()) {
      std::cout << text;
      return kExitOk;
    }
    Diagnostics diags;
    if (!writeFileAtomically(args->output, text, diags)) {
      printDiagnostics(diags, global);
      return exitCodeFor(diags);
    }
    return kExitOk;
  };
#else
  (void)global;
  return [] {
    std::cerr << "watergraph: scene: this build has no GL runtime (configure with -DWG_BUILD_RUNTIME=ON)\n";
    return kExitUsageOrIo;
  };
#endif
}

}  // namespace wg::cli
