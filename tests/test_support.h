#pragma once
// Helpers shared by the test suites: paths into the source tree, reading files, running
// the watergraph binary.
#include <chrono>
#include <string>
#include <vector>

namespace wg::test {

// Wall-clock seconds since t0 (the robustness tests print how long the hard inputs take).
double secondsSince(std::chrono::steady_clock::time_point t0);

std::string sourceDir();                     // the repository root
std::string sourcePath(const std::string& rel);
std::string readFile(const std::string& path);
std::string watergraphBinary();  // $WG_BINARY, else the watergraph next to the test binary
// Runs a shell command; returns its exit status and fills `output` with stdout+stderr.
int runCommand(const std::string& command, std::string* output);
// A fresh empty directory under the system temp folder, removed by the caller.
std::string makeTempDir(const std::string& prefix);

// Writes `contents` to `path` (binary), creating or replacing it; throws on failure.
void writeFile(const std::string& path, const std::string& contents);

// A fresh folder of files a test writes (graphs, their subgraphs and function files),
// removed with everything in it when the tree goes.
class FileTree {
 public:
  explicit FileTree(const std::string& prefix) : dir_(makeTempDir(prefix)) {}
  ~FileTree();
  FileTree(const FileTree&) = delete;
  FileTree& operator=(const FileTree&) = delete;
  // Writes `text` to `rel` under the folder (making its folders); its path.
  std::string write(const std::string& rel, const std::string& text) const;
  std::string path(const std::string& rel) const { return dir_ + "/" + rel; }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
};
// The names (not paths) of the regular files in `dir` whose name ends with `suffix`
// ("" for all), sorted. A missing folder gives an empty list.
std::vector<std::string> listFiles(const std::string& dir, const std::string& suffix = "");
// Every regular file under `dir`, as paths relative to it, sorted.
std::vector<std::string> listFilesRecursive(const std::string& dir);
// The example graphs: paths of graphs/*.json in the source tree, sorted.
std::vector<std::string> exampleGraphs();
// Whether the graph at `graphPath`, or a function graph it imports (at any depth), holds a
// glsl_function node: its code is GLSL only, so it has no WGSL form.
bool holdsGlslFunction(const std::string& graphPath);
// Node.js (`node`) found on $PATH, or "": the WebGPU executor's tests run it.
std::string nodeOnPath();
// `s` quoted for /bin/sh.
std::string shellQuote(const std::string& s);
// Runs a shell command with stdout and stderr captured separately; returns its exit status.
int runCommandSplit(const std::string& command, std::string* out, std::string* err);
// A command's exit status and its stdout and stderr apart.
struct CmdResult {
  int exit = -1;
  std::string out, err;
};
CmdResult runSplit(const std::string& command);
// `watergraph <args>` (args already shell-quoted where needed), the build's own binary.
CmdResult runWatergraph(const std::string& args);
// The lines of `text`, without their '\n'; a final empty line is dropped.
std::vector<std::string> splitLines(const std::string& text);

// Calls of the GLSL library function `fn` in shader `text`, not counting its definition
// (the line "type fn(...").
size_t glslCalls(const std::string& text, const std::string& fn);
// WG_UPDATE_GOLDEN=1 in the environment: tests with golden files (GLSL, manifests, images)
// rewrite them instead of comparing (tests/golden/README.md).
bool updatingGoldens();
// A graph file (version 1, named "t") around the given nodes, outputs and parameters: the
// insides of its "nodes" array, "outputs" object and "parameters" object.
std::string graphJson(const std::string& nodes, const std::string& outputs, const std::string& parameters = "");

}  // namespace wg::test
