// watergraph: water shader graphs (JSON) compiled to validated GLSL.
#include <iostream>
#include <new>

#include "cli/commands.h"
#include "cli/option_values.h"
#include "cli/terminal_output.h"

int main(int argc, char** argv) {
  using namespace wg::cli;
  TerminalSafeOutput safeOutput;  // what reaches the terminal is escaped (cli/terminal_output.h)
  CLI::App app{"watergraph: compiles water shader graphs (JSON) into GLSL for glsl330, es300 and vk450, "
               "validated by glslang.\n\nExamples:\n  watergraph compile graphs/lake.json -o out\n"
               "  watergraph validate graphs/*.json\n  watergraph nodes\n  watergraph fmt --check graphs/*.json"};
  app.require_subcommand(1);
  app.fallthrough();  // global options may follow the subcommand
  GlobalOptions global;
  app.add_option("--diagnostics-format", global.diagnosticsFormat, "how errors are printed: text (stderr), json or sarif (SARIF 2.1.0 for code scanning; stdout)")
      ->check(CLI::IsMember({"text", "json", "sarif"}));
  app.set_version_flag("--version", "watergraph 0.1.0");

  Runner compile = addCompileCommand(app, global);
  Runner validate = addValidateCommand(app, global);
  Runner nodes = addNodesCommand(app, global);
  Runner fmt = addFmtCommand(app, global);
  Runner render = addRenderCommand(app, global);
  Runner schema = addSchemaCommand(app, global);
  Runner probe = addProbeCommand(app, global);
  Runner check = addCheckCommand(app, global);
  Runner bench = addBenchCommand(app, global);
  Runner scene = addSceneCommand(app, global);
  Runner tune = addTuneCommand(app, global);
  Runner codes = addCodesCommand(app, global);
  refuseEmptyValues(app);

  // A usage error is one line naming the option, as the commands' own usage errors are
  // (CLI11's default adds "Run with --help for more information.").
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return "watergraph: " + std::string(e.what()) + "\n"; });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsageOrIo;
  }
  // Every file a command would write is checked before it does any work.
  if (!checkOutputPaths(global)) return kExitUsageOrIo;
  try {
    if (app.got_subcommand("compile")) return compile();
    if (app.got_subcommand("validate")) return validate();
    if (app.got_subcommand("nodes")) return nodes();
    if (app.got_subcommand("fmt")) return fmt();
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("schema")) return schema();
    if (app.got_subcommand("probe")) return probe();
    if (app.got_subcommand("check")) return check();
    if (app.got_subcommand("bench")) return bench();
    if (app.got_subcommand("scene")) return scene();
    if (app.got_subcommand("tune")) return tune();
    if (app.got_subcommand("codes")) return codes();
  } catch (const std::bad_alloc&) {
    // Not a bug: the machine (or a limit on the process) has less memory than the work
    // needs. The sizes that can get here are refused up front (docs/robustness.md), so this
    // is a process capped below them.
    std::cerr << "watergraph: out of memory: the work needs more memory than this process can get "
                 "(ulimit -v, a container's limit, or a smaller --size or graph)\n";
    return kExitUsageOrIo;
  } catch (const std::exception& e) {
    // A bug, not a graph problem: say so plainly rather than crash.
    std::cerr << "watergraph: internal error: " << e.what() << "\n";
    return kExitUsageOrIo;
  }
  return kExitUsageOrIo;
}
