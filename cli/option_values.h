#pragma once
// What every command's options share, so that each is checked the same way:
// - no option takes an empty value: '' would otherwise read as "not given" (`--preset ''`
//   compiled with no preset), so it is a usage error for every option that takes one;
// - a comma-separated list has no empty entry ("above," is not "above");
// - a file a command writes is named through addOutputOption, and every one given is
//   checked before the command does any work: a path that cannot be written fails at once
//   (WG051, exit 2), not after minutes of rendering.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"

namespace wg::cli {

// Adds the no-empty-value check to every option that takes a value, of `app` and of each
// of its subcommands (call once, after every command has registered its options).
void refuseEmptyValues(CLI::App& app);

// The entries of a comma-separated list; nullopt and *why ("--cameras 'above,' has an empty
// entry (a comma too many)") when the value or an entry is empty.
std::optional<std::vector<std::string>> splitList(const std::string& option, const std::string& value, std::string* why);

// Registers `--name` as naming a file the command writes (into `path`).
CLI::Option* addOutputOption(CLI::App* cmd, const std::string& name, std::string& path, const std::string& help);

// Registers an option naming a folder the command writes files into (compile -o).
CLI::Option* addOutputFolderOption(CLI::App* cmd, const std::string& name, std::string& path, const std::string& help);

// Checks every output option given on the command line (codegen/output_files.h,
// checkWritable); prints why not and returns false when one cannot be written.
bool checkOutputPaths(const GlobalOptions& global);

}  // namespace wg::cli
