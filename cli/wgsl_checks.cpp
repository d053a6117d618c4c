// naga and Tint on a WGSL module, through Node.js (cli/wgsl_checks.h), each run to its end
// as a core/json_line_process.h helper.
#include "cli/wgsl_checks.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include "core/json_line_process.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

// `program` found in a folder of $PATH, or "".
std::string onSearchPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    fs::path candidate = fs::path(dirs.substr(start, end - start).empty() ? "." : dirs.substr(start, end - start)) / program;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
    start = end + 1;
  }
  return "";
}

// How long a checker may take: Tint's starts Chromium, naga's loads its WebAssembly.
constexpr int kWgslCheckerSeconds = 300;

// Writes `wgsl` to a fresh temporary file and runs `script` on it; parses its JSON lines.
WgslCheckOutcome runCheckScript(const std::string& checker, const std::string& script, const std::string& needs,
                                const std::string& wgsl) {
  WgslCheckOutcome o;
  o.checker = checker;
  o.notRunBecause = webgpuClientMissing(needs);
  if (!o.notRunBecause.empty()) return o;
  const std::string node = nodeExecutable();
  const std::string dir = webgpuClientDir();
  std::error_code ec;
  fs::path tmp = fs::temp_directory_path(ec) / ("watergraph-" + checker + "-" + std::to_string(::getpid()) + ".wgsl");
  {
    std::ofstream f(tmp, std::ios::binary);
    f << wgsl;
    if (!f) {
      o.notRunBecause = "cannot write a temporary file for it";
      return o;
    }
  }
  int status = -1;
  std::vector<nlohmann::json> lines;
  std::string failed;
  try {
    JsonLineProcess helper({node, dir + "/" + script, tmp.string()});
    lines = helper.receiveToEnd(kWgslCheckerSeconds, &status);
    if (lines.empty()) failed = helper.stderrTail();
  } catch (const std::runtime_error& e) {
    failed = e.what();
  }
  fs::remove(tmp, ec);
  // One JSON line for the file; anything else (status 2, or no line) says why it did not run.
  for (const nlohmann::json& line : lines) {
    if (!line.contains("ok")) continue;
    if (line.contains("skipped")) {
      o.notRunBecause = line["skipped"].is_string() ? line["skipped"].get<std::string>() : line["skipped"].dump();
      return o;
    }
    o.ran = true;
    if (line.contains("errors"))
      for (const auto& e : line["errors"])
        o.errors.push_back({e.value("line", 0), e.value("column", 0), e.value("message", std::string("(no message)"))});
    if (!(line["ok"].is_boolean() && line["ok"].get<bool>()) && o.errors.empty()) o.errors.push_back({0, 0, "rejected without a message"});
    return o;
  }
  std::string first = failed.substr(0, failed.find('\n'));
  o.notRunBecause = script + " gave no result (exit status " + std::to_string(status) + ")" + (first.empty() ? "" : ": " + first);
  return o;
}

}  // namespace

std::string webgpuClientDir() {
  if (const char* env = std::getenv("WATERGRAPH_WEBGPU_CLIENT"); env && *env) return env;
  return WG_WEBGPU_CLIENT_DIR;
}

std::string nodeExecutable() { return onSearchPath("node"); }

std::string webgpuClientMissing(const std::string& package) {
  if (nodeExecutable().empty()) return "Node.js (node) is not on PATH";
  const std::string dir = webgpuClientDir();
  if (!fs::exists(fs::path(dir) / "node_modules" / package))
    return "the npm package " + package + " is not installed in " + dir + " (run `npm ci` there)";
  return "";
}

WgslCheckOutcome runNagaCheck(const std::string& wgsl) { return runCheckScript("naga", "naga_check.mjs", "naga-wasm", wgsl); }

WgslCheckOutcome runTintCheck(const std::string& wgsl) {
  return runCheckScript("Tint", "tint_check.mjs", "playwright-core", wgsl);
}

}  // namespace wg
