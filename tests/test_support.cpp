#include "test_support.h"

#include "core/graph_io.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

namespace wg::test {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

namespace {
// Mesa's shader disk cache, set before main for the test process and every program it
// starts: never the user's (~/.cache), so no test depends on what ran outside this build,
// but the build tree's own, so the many tests that compile the same example graphs pay
// llvmpipe's LLVM compile once per shader instead of once per process (most of the GL
// tests' time). `make test` and scripts/sanitize.sh empty it first, so a run depends only
// on itself; an entry is keyed by the shader and the driver's build, so a hit runs the same
// code. A caller's own MESA_SHADER_CACHE_DIR or _DISABLE is kept.
const bool kMesaCacheInBuildTree = [] {
  if (std::getenv("MESA_SHADER_CACHE_DIR") || std::getenv("MESA_SHADER_CACHE_DISABLE")) return false;
  std::error_code ec;
  auto self = std::filesystem::read_symlink("/proc/self/exe", ec);  // build-dir/bin/wg_test_*
  if (ec) return setenv("MESA_SHADER_CACHE_DISABLE", "true", 1) == 0;
  auto dir = self.parent_path().parent_path() / "mesa-shader-cache";
  return setenv("MESA_SHADER_CACHE_DIR", dir.c_str(), 1) == 0;
}();
}  // namespace

std::string sourceDir() {
  if (const char* env = std::getenv("WG_SOURCE_DIR")) return env;
  return WG_SOURCE_DIR;
}

std::string sourcePath(const std::string& rel) { return sourceDir() + "/" + rel; }

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string watergraphBinary() {
  if (const char* env = std::getenv("WG_BINARY")) return env;
  // The build puts the test binaries next to watergraph (build-dir/bin/): prefer the one
  // of the same build over a possibly stale build/bin/watergraph in the source tree.
  std::error_code ec;
  auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    auto sibling = self.parent_path() / "watergraph";
    if (std::filesystem::exists(sibling, ec)) return sibling.string();
  }
  return sourceDir() + "/build/bin/watergraph";
}

int runCommand(const std::string& command, std::string* output) {
  std::string full = command + " 2>&1";
  FILE* pipe = popen(full.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buf;
  std::string out;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  int status = pclose(pipe);
  if (output) *output = out;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string makeTempDir(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

}  // namespace wg::test

namespace wg::test {

void writeFile(const std::string& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path);
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<std::string> listFiles(const std::string& dir, const std::string& suffix) {
  std::vector<std::string> names;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file()) continue;
    std::string name = it->path().filename().string();
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> listFilesRecursive(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (std::filesystem::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) names.push_back(std::filesystem::relative(it->path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> exampleGraphs() {
  std::vector<std::string> paths;
  for (const auto& name : listFiles(sourcePath("graphs"), ".json")) paths.push_back(sourcePath("graphs/" + name));
  return paths;
}

namespace {
bool graphHoldsNodeType(const Graph& g, std::string_view type) {
  for (const auto& n : g.nodes)
    if (n.type == type) return true;
  for (const auto& im : g.imports)
    if (im.graph && graphHoldsNodeType(*im.graph, type)) return true;
  return false;
}
}  // namespace

bool holdsGlslFunction(const std::string& graphPath) {
  Diagnostics diags;
  auto graph = loadGraphFile(graphPath, diags);
  if (!graph) throw std::runtime_error("holdsGlslFunction: " + graphPath + " does not load");
  return graphHoldsNodeType(*graph, "glsl_function");
}

std::string nodeOnPath() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (size_t start = 0; start <= dirs.size();) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    std::filesystem::path candidate = std::filesystem::path(dirs.substr(start, end - start)) / "node";
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate.string();
    start = end + 1;
  }
  return "";
}

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q += "'\\''";
    else
      q += c;
  }
  return q + "'";
}

int runCommandSplit(const std::string& command, std::string* out, std::string* err) {
  std::string dir = makeTempDir("wg_cmd_");
  std::string errPath = dir + "/stderr";
  std::string full = "{ " + command + " ; } 2>" + shellQuote(errPath);
  FILE* pipe = popen(full.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buf;
  std::string text;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) text.append(buf.data(), n);
  int status = pclose(pipe);
  if (out) *out = text;
  if (err) {
    std::ifstream in(errPath, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    *err = ss.str();
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

CmdResult runSplit(const std::string& command) {
  CmdResult r;
  r.exit = runCommandSplit(command, &r.out, &r.err);
  return r;
}

CmdResult runWatergraph(const std::string& args) { return runSplit(shellQuote(watergraphBinary()) + " " + args); }

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t eol = text.find('\n', start);
    if (eol == std::string::npos) eol = text.size();
    lines.push_back(text.substr(start, eol - start));
    start = eol + 1;
  }
  return lines;
}

std::string graphJson(const std::string& nodes, const std::string& outputs, const std::string& parameters) {
  std::string s = "{\"version\": 1, \"name\": \"t\",";
  if (!parameters.empty()) s += "\"parameters\": {" + parameters + "},";
  return s + "\"nodes\": [" + nodes + "], \"outputs\": {" + outputs + "}}";
}

bool updatingGoldens() {
  const char* env = std::getenv("WG_UPDATE_GOLDEN");
  return env && std::string(env) == "1";
}

size_t glslCalls(const std::string& text, const std::string& fn) {
  size_t n = 0;
  for (size_t at = text.find(fn + "("); at != std::string::npos; at = text.find(fn + "(", at + 1)) {
    size_t lineStart = text.rfind('\n', at);
    lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
    std::string before = text.substr(lineStart, at - lineStart);
    bool definition = !before.empty() && before.back() == ' ' && before.find_first_of(" =(,") == before.size() - 1;
    if (!definition) ++n;
  }
  return n;
}

FileTree::~FileTree() {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

std::string FileTree::write(const std::string& rel, const std::string& text) const {
  std::string p = path(rel);
  std::filesystem::create_directories(std::filesystem::path(p).parent_path());
  writeFile(p, text);
  return p;
}

}  // namespace wg::test
