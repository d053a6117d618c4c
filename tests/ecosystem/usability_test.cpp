// The command line as a person uses it: a progress bar on batch runs only on a terminal,
// --quiet / --verbose, --watch recompiling on change, and examples in every --help.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "eco_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

std::string examplesArgs() {
  std::string all;
  for (const auto& p : test::exampleGraphs()) all += " " + shellQuote(p);
  return all;
}

TEST(Usability, EveryHelpHasExamples) {
  for (const char* sub : {"", "compile", "validate", "nodes", "fmt", "render", "schema"}) {
    auto r = eco::wgRun(std::string(sub) + " --help");
    EXPECT_EQ(r.exit, 0) << sub;
    EXPECT_NE(r.out.find("Examples:"), std::string::npos) << "watergraph " << sub << " --help:\n" << r.out;
    EXPECT_NE(r.out.find(std::string("watergraph ") + sub), std::string::npos) << r.out;
  }
  auto r = eco::wgRun("compile --help");
  for (const char* opt : {"--quiet", "--verbose", "--watch", "--no-progress", "msl", "hlsl"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST(Usability, NoProgressBarWhenStdoutIsNotATerminal) {
  eco::TempDir tmp;
  auto r = eco::wgRun("compile" + examplesArgs() + " -o " + shellQuote(tmp / "out") + " --subdirs");
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\033["), std::string::npos) << r.out;
}

TEST(Usability, ProgressBarOnATerminal) {
  if (!eco::haveTool("script")) GTEST_FAIL() << "script (util-linux) is missing";
  eco::TempDir tmp;
  std::string cmd = shellQuote(test::watergraphBinary()) + " compile" + examplesArgs() + " -o " +
                    shellQuote(tmp / "out") + " --subdirs";
  // script runs the command on a pseudo-terminal and copies what it printed to our stdout.
  auto r = eco::sh("script -qfec " + shellQuote(cmd) + " /dev/null");
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  size_t n = test::exampleGraphs().size();
  EXPECT_NE(r.out.find("\r\033[K["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("] 1/" + std::to_string(n)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("] " + std::to_string(n) + "/" + std::to_string(n)), std::string::npos) << r.out;
  // --no-progress turns it off even there.
  r = eco::sh("script -qfec " + shellQuote(cmd + " --no-progress") + " /dev/null");
  EXPECT_EQ(r.out.find("\033[K["), std::string::npos) << r.out;
}

TEST(Usability, QuietPrintsOnlyErrors) {
  auto ok = eco::wgRun("validate" + examplesArgs() + " --quiet");
  EXPECT_EQ(ok.exit, 0);
  EXPECT_EQ(ok.out, "");
  EXPECT_EQ(ok.err, "");
  auto bad = eco::wgRun("validate --quiet " + shellQuote(test::sourcePath("tests/ecosystem/schema_bad/unknown_option_value.json")));
  EXPECT_EQ(bad.exit, 1);
  EXPECT_EQ(bad.out, "");
  EXPECT_NE(bad.err.find("[WG030]"), std::string::npos) << bad.err;
  auto both = eco::wgRun("validate --quiet --verbose" + examplesArgs());
  EXPECT_EQ(both.exit, 2);
}

TEST(Usability, VerboseSaysWhatEachGraphDid) {
  eco::TempDir tmp;
  auto r = eco::wgRun("compile" + examplesArgs() + " -o " + shellQuote(tmp / "out") + " --verbose");
  EXPECT_EQ(r.exit, 0) << r.err;
  for (const auto& g : test::exampleGraphs())
    EXPECT_NE(r.out.find(g + ": ok, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" nodes kept, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" files in " + tmp / "out"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("compiled " + std::to_string(test::exampleGraphs().size()) + " graphs for glsl330,es300,vk450"),
            std::string::npos)
      << r.out;
}

// Waits until `path` contains `needle` (or the time runs out); returns the contents.
std::string waitFor(const std::string& path, const std::string& needle, int ms = 15000) {
  std::string text;
  for (int waited = 0; waited < ms; waited += 50) {
    std::error_code ec;
    if (fs::exists(path, ec)) {
      text = test::readFile(path);
      if (text.find(needle) != std::string::npos) return text;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return text;
}

// `watergraph compile GRAPH -o OUT --watch` in the background, printing into LOG; killed
// when the returned value goes out of scope (kill(1) on a finished process does nothing).
struct WatchProcess {
  int pid = 0;
  WatchProcess(const WatchProcess&) = delete;
  WatchProcess& operator=(const WatchProcess&) = delete;
  WatchProcess(const std::string& graph, const std::string& out, const std::string& log, const std::string& more = "") {
    auto start = eco::sh(shellQuote(test::watergraphBinary()) + " compile " + shellQuote(graph) + " -o " +
                         shellQuote(out) + " --watch --watch-interval 50" + more + " > " + shellQuote(log) + " 2>&1 & echo $!");
    if (start.exit == 0) pid = std::stoi(start.out);
  }
  ~WatchProcess() {
    if (pid > 0) eco::sh("kill " + std::to_string(pid) + " 2>/dev/null");
  }
};

TEST(Usability, WatchRecompilesOnChange) {
  eco::TempDir tmp;
  std::string graph = tmp / "lake.json";
  fs::copy_file(test::sourcePath("graphs/lake.json"), graph);
  std::string log = tmp / "watch.log";
  std::string out = tmp / "out";
  WatchProcess watch(graph, out, log);
  ASSERT_GT(watch.pid, 0);

  std::string text = waitFor(log, "watching 1 graph");
  ASSERT_NE(text.find("watching 1 graph"), std::string::npos) << text;
  ASSERT_TRUE(fs::exists(out + "/lake.glsl330.frag"));

  // A change: the graph is compiled again.
  std::string json = test::readFile(graph);
  size_t at = json.find("\"f0\": 0.02");
  ASSERT_NE(at, std::string::npos);
  test::writeFile(graph, json.substr(0, at) + "\"f0\": 0.03" + json.substr(at + 10));
  text = waitFor(log, "recompiled ");
  EXPECT_NE(text.find("] recompiled " + graph + ": ok"), std::string::npos) << text;
  EXPECT_NE(test::readFile(out + "/lake.glsl330.frag").find("0.03"), std::string::npos);

  // A broken save is reported, the watch goes on, and the fix compiles again.
  test::writeFile(graph, "{\"version\": 1,");
  text = waitFor(log, "FAILED");
  EXPECT_NE(text.find("error: [WG001]"), std::string::npos) << text;
  test::writeFile(graph, json);
  for (int i = 0; i < 300; ++i) {
    text = test::readFile(log);
    size_t failed = text.find("FAILED");
    if (failed != std::string::npos && text.find(": ok", failed) != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  size_t failed = text.find("FAILED");
  ASSERT_NE(failed, std::string::npos);
  EXPECT_NE(text.find("recompiled " + graph + ": ok", failed), std::string::npos) << text;

  // SIGTERM stops it cleanly.
  eco::sh("kill " + std::to_string(watch.pid));
  text = waitFor(log, "watch stopped");
  EXPECT_NE(text.find("watch stopped"), std::string::npos) << text;
}

// --watch follows the graphs a graph imports: saving a subgraph recompiles its user.
TEST(Usability, WatchRecompilesWhenAnImportedSubgraphChanges) {
  eco::TempDir tmp;
  fs::create_directories(tmp / "lib");
  fs::copy_file(test::sourcePath("graphs/pool.json"), tmp / "pool.json");
  for (const char* lib : {"floor_caustics.json", "fresnel_sky.json"})
    fs::copy_file(test::sourcePath(std::string("graphs/lib/") + lib), tmp / (std::string("lib/") + lib));
  std::string log = tmp / "watch.log";
  std::string out = tmp / "out";
  WatchProcess watch(tmp / "pool.json", out, log);
  ASSERT_GT(watch.pid, 0);
  std::string text = waitFor(log, "watching 1 graph");
  ASSERT_NE(text.find("watching 1 graph"), std::string::npos) << text;

  std::string sky = tmp / "lib/fresnel_sky.json";
  std::string json = test::readFile(sky);
  size_t at = json.find("\"default\": 0.02");
  ASSERT_NE(at, std::string::npos);
  test::writeFile(sky, json.substr(0, at) + "\"default\": 0.0371" + json.substr(at + 15));
  text = waitFor(log, "recompiled ");
  EXPECT_NE(text.find("recompiled " + std::string(tmp / "pool.json") + ": ok"), std::string::npos) << text;
  EXPECT_NE(test::readFile(out + "/pool.glsl330.frag").find("0.0371"), std::string::npos);
}

// --watch follows the .glsl files of function nodes (the depfile's inputs), here one that a
// subgraph's glsl_function node calls: saving it recompiles the graph.
TEST(Usability, WatchRecompilesWhenAFunctionFileChanges) {
  eco::TempDir tmp;
  fs::create_directories(tmp / "lib");
  fs::copy_file(test::sourcePath("graphs/caustic_pool.json"), tmp / "caustic_pool.json");
  for (const char* lib : {"caustic_light.json", "caustic.glsl"})
    fs::copy_file(test::sourcePath(std::string("graphs/lib/") + lib), tmp / (std::string("lib/") + lib));
  // The texture its `broad` instance takes (an instance option).
  fs::copy_file(test::sourcePath("graphs/lagoon_ripples.png"), tmp / "lagoon_ripples.png");
  std::string log = tmp / "watch.log";
  std::string out = tmp / "out";
  WatchProcess watch(tmp / "caustic_pool.json", out, log);
  ASSERT_GT(watch.pid, 0);
  std::string text = waitFor(log, "watching 1 graph");
  ASSERT_NE(text.find("watching 1 graph"), std::string::npos) << text;

  std::string glsl = tmp / "lib/caustic.glsl";
  std::string code = test::readFile(glsl);
  size_t at = code.find("0.3 * sin(p.y");
  ASSERT_NE(at, std::string::npos);
  test::writeFile(glsl, code.substr(0, at) + "0.4375 * sin(p.y" + code.substr(at + 13));
  text = waitFor(log, "recompiled ");
  EXPECT_NE(text.find("recompiled " + std::string(tmp / "caustic_pool.json") + ": ok"), std::string::npos) << text;
  EXPECT_NE(test::readFile(out + "/caustic_pool.glsl330.frag").find("0.4375"), std::string::npos);
}

// --watch --depfile: an edit that adds imports rewrites the depfile (it stayed as the first
// compile wrote it, so a build system missed changes to the new imports).
TEST(Usability, WatchRewritesTheDepfileWhenTheImportsChange) {
  eco::TempDir tmp;
  fs::create_directories(tmp / "lib");
  for (const char* lib : {"floor_caustics.json", "fresnel_sky.json"})
    fs::copy_file(test::sourcePath(std::string("graphs/lib/") + lib), tmp / (std::string("lib/") + lib));
  std::string graph = tmp / "pool.json";
  fs::copy_file(test::sourcePath("graphs/lake.json"), graph);  // no imports yet
  std::string log = tmp / "watch.log", depfile = tmp / "pool.d";
  WatchProcess watch(graph, tmp / "out", log, " --depfile " + shellQuote(depfile));
  ASSERT_GT(watch.pid, 0);
  std::string text = waitFor(log, "watching 1 graph");
  ASSERT_NE(text.find("watching 1 graph"), std::string::npos) << text;
  EXPECT_EQ(test::readFile(depfile).find("fresnel_sky.json"), std::string::npos);
  test::writeFile(graph, test::readFile(test::sourcePath("graphs/pool.json")));
  std::string d;
  for (int i = 0; i < 300 && d.find("fresnel_sky.json") == std::string::npos; ++i) {  // a save may be seen half-written first
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    d = test::readFile(depfile);
  }
  EXPECT_NE(test::readFile(log).find("recompiled " + graph + ": ok"), std::string::npos) << test::readFile(log);
  EXPECT_NE(d.find(std::string(tmp / "lib/fresnel_sky.json")), std::string::npos) << d;
  EXPECT_NE(d.find(std::string(tmp / "lib/floor_caustics.json")), std::string::npos) << d;
}

TEST(Usability, DepfileListsEveryGraphFileAndTextureAGraphIsMadeOf) {
  eco::TempDir tmp;
  std::string river = test::sourcePath("graphs/river.json");
  std::string lagoon = test::sourcePath("graphs/lagoon.json");
  auto r = eco::wgRun("compile " + shellQuote(river) + " " + shellQuote(lagoon) + " -o " + shellQuote(tmp / "out") +
                      " --target glsl330 --depfile " + shellQuote(tmp / "shaders.d"));
  ASSERT_EQ(r.exit, 0) << r.err;
  std::string d = test::readFile(tmp / "shaders.d");
  std::string outDir = tmp / "out";
  // One rule per graph: its files written, then the files read.
  EXPECT_NE(d.find(outDir + "/river.manifest.json " + outDir + "/river.glsl330.vert " + outDir + "/river.glsl330.frag:"),
            std::string::npos)
      << d;
  for (const char* lib : {"depth_colour.json", "fresnel_sky.json", "shore_foam.json"})
    EXPECT_NE(d.find(test::sourcePath(std::string("graphs/lib/") + lib)), std::string::npos) << lib << "\n" << d;
  EXPECT_NE(d.find(" \\\n  " + river), std::string::npos) << d;
  EXPECT_NE(d.find(test::sourcePath("graphs/lagoon_ripples.png")), std::string::npos) << d;
  // validate writes nothing and takes no depfile.
  EXPECT_EQ(eco::wgRun("validate " + shellQuote(river) + " --depfile x.d").exit, 2);
}

// Ninja refuses a depfile naming an output its rule did not declare, and a build system
// declares outputs before the graph is read: the node textures `--textures` writes are not
// the depfile's targets (cmake/WatergraphShaders.cmake's TEXTURES relies on it).
TEST(Usability, ADepfileDoesNotNameTheNodeTexturesAsTargets) {
  eco::TempDir tmp;
  std::string river = test::sourcePath("graphs/river.json");
  auto r = eco::wgRun("compile " + shellQuote(river) + " -o " + shellQuote(tmp / "out") +
                      " --target glsl330 --textures --depfile " + shellQuote(tmp / "river.d"));
  ASSERT_EQ(r.exit, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(tmp / "out/river.t0_water_normal.png")) << "no node texture written";
  std::string d = test::readFile(tmp / "river.d");
  const std::string targets = d.substr(0, d.find(':'));
  EXPECT_NE(targets.find("river.manifest.json"), std::string::npos) << d;
  EXPECT_EQ(targets.find(".png"), std::string::npos) << d;
}

// The same for a spectral ocean's web module: watergraph_add_shaders cannot know whether a
// graph has an ocean, so <graph>.ocean.js (written for es300 and wgsl) is not a target either.
TEST(Usability, ADepfileDoesNotNameAnOceansWebModuleAsATarget) {
  eco::TempDir tmp;
  std::string ocean = test::sourcePath("graphs/open_ocean.json");
  auto r = eco::wgRun("compile " + shellQuote(ocean) + " -o " + shellQuote(tmp / "out") +
                      " --target es300 --depfile " + shellQuote(tmp / "open_ocean.d"));
  ASSERT_EQ(r.exit, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(tmp / "out/open_ocean.ocean.js")) << "no ocean module written";
  std::string d = test::readFile(tmp / "open_ocean.d");
  const std::string targets = d.substr(0, d.find(':'));
  EXPECT_NE(targets.find("open_ocean.es300.frag"), std::string::npos) << d;
  EXPECT_EQ(targets.find("ocean.js"), std::string::npos) << d;
}

// Found in review: a --depfile that cannot be written (a folder in its place, a file where
// its folder would be made) failed after every graph's files were written: found first now,
// nothing written.
TEST(Usability, ADepfileThatCannotBeWrittenLeavesNoCompiledFiles) {
  eco::TempDir tmp;
  std::string lake = test::sourcePath("graphs/lake.json");
  std::filesystem::create_directories(tmp / "folder.d");
  test::writeFile(tmp / "afile", "x");
  for (const std::string& depfile : {tmp / "afile/sub/x.d", tmp / "folder.d"}) {
    SCOPED_TRACE(depfile);
    auto r = eco::wgRun("compile " + shellQuote(lake) + " -o " + shellQuote(tmp / "out") + " --depfile " + shellQuote(depfile));
    EXPECT_EQ(r.exit, 2) << r.err;
    EXPECT_NE(r.err.find(depfile + ": error: [WG051] cannot"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp / "out")) << "compiled files were written";
  }
}

// The README's own line on a clean tree: the depfile's folder is the one -o makes (with
// CMake's Unix Makefiles generator nothing makes it before the command runs).
TEST(Usability, ADepfileInTheFolderOfTheOutputsIsWrittenThere) {
  eco::TempDir tmp;
  std::string river = test::sourcePath("graphs/river.json");
  auto r = eco::wgRun("compile " + shellQuote(river) + " -o " + shellQuote(tmp / "out") + " --depfile " +
                      shellQuote(tmp / "out/deps/river.d") + " --target glsl330");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(tmp / "out/river.glsl330.frag"));
  EXPECT_NE(test::readFile(tmp / "out/deps/river.d").find("river.json"), std::string::npos);
}

TEST(Usability, NodesPrintsAFunctionGraphsInterface) {
  auto text = eco::wgRun("nodes --graph " + shellQuote(test::sourcePath("graphs/lib/fresnel_sky.json")));
  ASSERT_EQ(text.exit, 0) << text.err;
  EXPECT_NE(text.out.find("fresnel_sky  (subgraph, "), std::string::npos) << text.out;
  // A graph that offers none says so (it printed nothing).
  auto none = eco::wgRun("nodes --graph " + shellQuote(test::sourcePath("graphs/lake.json")));
  EXPECT_EQ(none.exit, 0) << none.err;
  EXPECT_NE(none.out.find("lake.json: no subgraph node types"), std::string::npos) << none.out;
  EXPECT_NE(text.out.find("    f0: float, default 0.02 in [0, 1]"), std::string::npos) << text.out;
  // A user graph lists what it imports, under the names it imports them as.
  auto json = eco::wgRun("nodes --json --graph " + shellQuote(test::sourcePath("graphs/pool.json")));
  ASSERT_EQ(json.exit, 0) << json.err;
  auto list = nlohmann::json::parse(json.out);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["type"], "floor_caustics");
  EXPECT_EQ(list[1]["type"], "fresnel_sky");
  EXPECT_EQ(list[1]["outputs"][0]["name"], "color");
  EXPECT_EQ(list[1]["inputs"][2]["name"], "f0");
  EXPECT_EQ(list[1]["inputs"][2]["max"], 1);
}

}  // namespace
}  // namespace wg
