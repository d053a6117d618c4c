#include "cli/option_values.h"

#include "codegen/output_files.h"

namespace wg::cli {
namespace {

struct OutputOption {
  CLI::Option* option;
  std::string* path;
  bool folder;
};

std::vector<OutputOption>& outputOptions() {
  static std::vector<OutputOption> all;
  return all;
}

void refuseEmptyIn(CLI::App& app) {
  static const CLI::Validator nonEmpty(
      [](std::string& value) { return value.empty() ? std::string("the value is empty (leave the option out instead)") : std::string(); },
      "", "non-empty");
  for (CLI::Option* option : app.get_options())
    if (option->get_type_size_max() > 0) option->check(nonEmpty);
}

}  // namespace

void refuseEmptyValues(CLI::App& app) {
  refuseEmptyIn(app);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) refuseEmptyValues(*sub);
}

std::optional<std::vector<std::string>> splitList(const std::string& option, const std::string& value, std::string* why) {
  if (value.empty()) {
    *why = option + " is empty";
    return std::nullopt;
  }
  std::vector<std::string> entries;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = value.find(',', start);
    std::string entry = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (entry.empty()) {
      *why = option + " '" + value + "' has an empty entry (a comma too many)";
      return std::nullopt;
    }
    entries.push_back(entry);
    if (comma == std::string::npos) return entries;
    start = comma + 1;
  }
}

CLI::Option* addOutputOption(CLI::App* cmd, const std::string& name, std::string& path, const std::string& help) {
  CLI::Option* option = cmd->add_option(name, path, help);
  outputOptions().push_back({option, &path, false});
  return option;
}

CLI::Option* addOutputFolderOption(CLI::App* cmd, const std::string& name, std::string& path, const std::string& help) {
  CLI::Option* option = cmd->add_option(name, path, help);
  outputOptions().push_back({option, &path, true});
  return option;
}

bool checkOutputPaths(const GlobalOptions& global) {
  Diagnostics diags;
  for (const auto& [option, path, folder] : outputOptions())
    if (option->count() > 0) folder ? checkFolderWritable(*path, diags) : checkWritable(*path, diags);
  if (!diags.hasErrors()) return true;
  printDiagnostics(diags, global);
  return false;
}

}  // namespace wg::cli
