// Faults (docs/robustness.md): every bad graph through the CLI, unwritable output folders,
// read-only and special graph files on fmt, and what the runtime does with a shader that
// glslang accepts but the GL driver rejects. Each is one clear error line, the documented
// exit status, no partial output and no lost input.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "codegen/glslang_validate.h"
#include "test_support.h"

#ifdef WG_HAVE_RUNTIME
#include "runtime/egl_context.h"
#include "runtime/gl_resources.h"
#include "runtime/runtime_error.h"
#endif

namespace wg {
namespace {

namespace fs = std::filesystem;

std::string wg() { return test::watergraphBinary(); }

int run(const std::string& args, std::string* out, std::string* err) {
  return test::runCommandSplit(wg() + " " + args, out, err);
}

// A graph that loads but is not in the canonical form (fmt would rewrite it).
std::string unformattedGraph() {
  return "{\"version\":1,\"name\":\"g\",\"nodes\":[{\"id\":\"t\",\"type\":\"time\"}],"
         "\"outputs\":{\"fragment\":{\"alpha\":\"t.out\"}}}";
}

mode_t modeOf(const std::string& path) {
  struct stat st {};
  ::stat(path.c_str(), &st);
  return st.st_mode & 07777;
}

// Every file of tests/bad, compiled by one CLI run: exit 1, every error one line in the
// `file:line:col: error: [WGnnn]` form, the expected first diagnostic of each file printed,
// and nothing written.
TEST(Faults, EveryBadGraphIsOneLinePerErrorAndNothingIsWritten) {
  std::string bad = test::sourcePath("tests/bad");
  std::map<std::string, std::string> firstExpected;  // path -> "path:line:col: error: [code]"
  std::ifstream in(bad + "/expected.txt");
  std::string line;
  std::string files;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::string file, code, pos, in;
    ss >> file >> code >> pos >> in;
    // `@imports/x.json`: the first diagnostic lies in a graph the bad graph imports.
    std::string at = bad + "/" + (in.size() > 1 ? in.substr(1) : file);
    firstExpected[at] = at + ":" + pos + ": error: [" + code + "]";
    files += " " + test::shellQuote(bad + "/" + file);
  }
  ASSERT_GE(firstExpected.size(), 100u);
  std::string dir = test::makeTempDir("wg_badcli_");
  std::string out, err;
  int code = run("compile" + files + " -o " + dir + "/out", &out, &err);
  EXPECT_EQ(code, 1) << err;
  EXPECT_TRUE(test::listFilesRecursive(dir).empty()) << "something was written";
  std::map<std::string, std::string> firstSeen;
  for (const auto& l : test::splitLines(err)) {
    if (l.rfind("  note: ", 0) == 0) continue;
    // A located note (an import or a subgraph instance): `file:line:col: note: ...`.
    if (l.find(": note: ") != std::string::npos && l.find(": error: ") == std::string::npos) continue;
    // Every other line is a diagnostic of one of the files (a graph, or the GLSL function
    // file a bad graph's glsl_function node names), with a position.
    auto colon = l.find(".json:");
    if (colon == std::string::npos) colon = l.find(".glsl:");  // as long as ".json"
    ASSERT_NE(colon, std::string::npos) << "not a diagnostic line: " << l;
    std::string path = l.substr(0, colon + 5);
    ASSERT_TRUE(firstExpected.count(path)) << l;
    EXPECT_NE(l.find(": error: [WG0"), std::string::npos) << l;
    if (!firstSeen.count(path)) firstSeen[path] = l;
  }
  for (const auto& [path, want] : firstExpected) {
    ASSERT_TRUE(firstSeen.count(path)) << path << " printed no error";
    EXPECT_EQ(firstSeen[path].substr(0, want.size()), want);
  }
  fs::remove_all(dir);
}

TEST(Faults, OutputFolderUnderARegularFileIsExit2) {
  std::string dir = test::makeTempDir("wg_unwritable_");
  test::writeFile(dir + "/file", "x");
  std::string out, err;
  int code = run("compile " + test::sourcePath("graphs/lake.json") + " -o " + dir + "/file/out", &out, &err);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("error: [WG051]"), std::string::npos) << err;
  EXPECT_EQ(test::splitLines(err).size(), 1u) << err;
  EXPECT_EQ(test::readFile(dir + "/file"), "x");
  EXPECT_EQ(test::listFilesRecursive(dir), std::vector<std::string>{"file"});
  fs::remove_all(dir);
}

// Permissions do not stop root, so as root the command runs as 'nobody' (setpriv).
std::string asUnprivileged() {
  if (::geteuid() != 0) return "";
  if (std::system("command -v setpriv >/dev/null 2>&1") != 0) return "-";
  std::string prefix = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  // 'nobody' must be able to run the binary (a checkout under a private home cannot).
  if (std::system((prefix + test::watergraphBinary() + " --version >/dev/null 2>&1").c_str()) != 0) return "-";
  return prefix;
}

TEST(Faults, ReadOnlyOutputFolderIsExit2AndLeavesItAsItWas) {
  std::string prefix = asUnprivileged();
  if (prefix == "-") GTEST_SKIP() << "running as root, and cannot run watergraph as nobody: permissions cannot be tested";
  std::string dir = test::makeTempDir("wg_readonly_");
  fs::permissions(dir, fs::perms::all);
  std::string graph = dir + "/lake.json";
  fs::copy_file(test::sourcePath("graphs/lake.json"), graph);
  fs::permissions(graph, fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
  fs::create_directory(dir + "/out");
  test::writeFile(dir + "/out/lake.glsl330.frag", "old");
  fs::permissions(dir + "/out", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                    fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  std::string out, err;
  int code = test::runCommandSplit(prefix + wg() + " compile " + graph + " -o " + dir + "/out", &out, &err);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("error: [WG051]"), std::string::npos) << err;
  EXPECT_EQ(test::listFilesRecursive(dir + "/out"), std::vector<std::string>{"lake.glsl330.frag"});
  EXPECT_EQ(test::readFile(dir + "/out/lake.glsl330.frag"), "old");
  fs::permissions(dir + "/out", fs::perms::owner_all);
  fs::remove_all(dir);
}

// A folder where the last file (the manifest) goes: found before any file is renamed, so
// the earlier shaders of the set are not left behind either.
TEST(Faults, AFolderInTheWayLeavesNoPartialSet) {
  std::string dir = test::makeTempDir("wg_inway_");
  fs::create_directories(dir + "/out/lake.manifest.json");
  std::string out, err;
  int code = run("compile " + test::sourcePath("graphs/lake.json") + " -o " + dir + "/out", &out, &err);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("error: [WG051]"), std::string::npos) << err;
  EXPECT_TRUE(test::listFilesRecursive(dir + "/out").empty()) << "partial output or temporary files left";
  fs::remove_all(dir);
}

TEST(Faults, FmtOnAReadOnlyGraphIsAnErrorAndTheFileIsUnchanged) {
  std::string dir = test::makeTempDir("wg_fmt_ro_");
  std::string graph = dir + "/g.json";
  test::writeFile(graph, unformattedGraph());
  fs::permissions(graph, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  std::string out, err;
  int code = run("fmt " + graph, &out, &err);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find(graph + ": error: [WG051]"), std::string::npos) << err;
  EXPECT_NE(err.find("read-only"), std::string::npos) << err;
  EXPECT_EQ(test::readFile(graph), unformattedGraph());
  EXPECT_EQ(modeOf(graph), 0444u);
  EXPECT_EQ(test::listFiles(dir), std::vector<std::string>{"g.json"});  // no temporary left
  // --check only reads: it works on a read-only file.
  code = run("fmt --check " + graph, &out, &err);
  EXPECT_EQ(code, 1) << err;
  fs::remove_all(dir);
}

TEST(Faults, FmtKeepsTheModeAndFollowsSymlinks) {
  std::string dir = test::makeTempDir("wg_fmt_mode_");
  std::string graph = dir + "/g.json";
  test::writeFile(graph, unformattedGraph());
  fs::permissions(graph, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink("g.json", dir + "/link.json");
  std::string out, err;
  int code = run("fmt " + dir + "/link.json", &out, &err);
  EXPECT_EQ(code, 0) << err;
  EXPECT_TRUE(fs::is_symlink(dir + "/link.json"));
  EXPECT_NE(test::readFile(graph), unformattedGraph());  // the target was formatted
  EXPECT_EQ(modeOf(graph), 0640u);
  code = run("fmt --check " + graph, &out, &err);
  EXPECT_EQ(code, 0) << out << err;
  fs::remove_all(dir);
}

// fmt reads a graph exactly once and works on that snapshot: a FIFO (which can only be
// read once) is checked, and is refused for rewriting, without ever blocking.
TEST(Faults, FmtReadsTheFileOnceAndNeverReplacesAFifo) {
  std::string dir = test::makeTempDir("wg_fifo_");
  std::string fifo = dir + "/g.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  test::writeFile(dir + "/src.json", unformattedGraph());
  std::string writer = "(timeout 60 cat " + dir + "/src.json > " + fifo + " &) ; ";
  std::string out, err;
  int code = test::runCommandSplit(writer + "timeout 60 " + wg() + " fmt --check " + fifo, &out, &err);
  EXPECT_EQ(code, 1) << out << err;  // read once, not canonical; a second read would block
  EXPECT_NE(out.find("not in canonical form"), std::string::npos) << out;
  code = test::runCommandSplit(writer + "timeout 60 " + wg() + " fmt " + fifo, &out, &err);
  EXPECT_EQ(code, 2) << out << err;
  EXPECT_NE(err.find("not a regular file"), std::string::npos) << err;
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  fs::remove_all(dir);
}

TEST(Faults, UnreadableInputsAreExit2) {
  std::string dir = test::makeTempDir("wg_unreadable_");
  std::string out, err;
  EXPECT_EQ(run("validate " + dir, &out, &err), 2) << err;  // a folder
  EXPECT_NE(err.find("error: [WG050]"), std::string::npos) << err;
  EXPECT_EQ(run("validate " + dir + "/missing.json", &out, &err), 2) << err;
  EXPECT_NE(err.find("No such file"), std::string::npos) << err;
  fs::remove_all(dir);
}

#ifdef WG_HAVE_RUNTIME
// glslang checks the language, not an implementation's limits: a 65,536-element uniform
// array is valid GLSL 3.30, and Mesa refuses to link it (too many uniform components).
// The runtime turns that into a RuntimeError of kind Driver (exit 1) naming the file and
// carrying the driver's log. (The CLI path is tests/runtime's DriverErrors and render tests.)
TEST(Faults, AShaderTheDriverRejectsButGlslangAcceptsIsADriverError) {
  using namespace wg::rt;
  const std::string vert =
      "#version 330 core\nlayout(location = 0) in vec3 a_position;\n"
      "void main() { gl_Position = vec4(a_position, 1.0); }\n";
  const std::string frag =
      "#version 330 core\nuniform vec4 u_big[65536];\nout vec4 o_color;\n"
      "void main() { o_color = u_big[int(gl_FragCoord.x)]; }\n";
  ValidationResult vr = validateShaders(Target::Glsl330, {{ShaderStage::Vertex, "big.glsl330.vert", vert},
                                                          {ShaderStage::Fragment, "big.glsl330.frag", frag}});
  ASSERT_TRUE(vr.ok) << "glslang was expected to accept the shader";
  std::unique_ptr<EglContext> ctx;
  try {
    ctx = EglContext::create(GlApi::DesktopGl45);
  } catch (const RuntimeError& e) {
    GTEST_SKIP() << "no GL context: " << e.what();
  }
  try {
    linkProgram({{GL_VERTEX_SHADER, "big.glsl330.vert", vert}, {GL_FRAGMENT_SHADER, "big.glsl330.frag", frag}},
                "fault test");
    GTEST_SKIP() << "this GL driver accepts 65,536 uniform vec4s";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Driver);
    EXPECT_EQ(e.exitCode(), 1);
    std::string m = e.what();
    EXPECT_NE(m.find("big.glsl330"), std::string::npos) << m;
    EXPECT_TRUE(m.find("rejected") != std::string::npos || m.find("could not link") != std::string::npos) << m;
  }
}
#endif

}  // namespace
}  // namespace wg
