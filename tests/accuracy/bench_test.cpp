// The bench's mechanics on one small family (not its timings, which are benchmarks): every
// level measured, the reference has zero error, the others' error is what the images say,
// the Pareto front is marked and the table lists every level. `bench GRAPH` makes its
// families from the graph's quality knobs.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "accuracy/bench.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

TEST(Bench, MeasuresEveryLevelAgainstItsReference) {
  BenchSettings s;
  s.configFile = test::sourcePath("bench/variants.json");
  s.root = test::sourcePath("");
  s.width = s.height = 48;
  s.runs = 1;
  s.families = {"normal blend"};
  BenchResult r = runBench(s);
  ASSERT_EQ(r.levels.size(), 3u);
  int references = 0, pareto = 0;
  for (const auto& l : r.levels) {
    EXPECT_GT(l.msPerMegapixel, 0) << l.level;
    EXPECT_GT(l.ratio, 0) << l.level;
    EXPECT_GT(l.spirvInstructions, 10) << l.level;
    if (l.reference) {
      ++references;
      EXPECT_EQ(l.maxError, 0);
      EXPECT_TRUE(std::isinf(l.psnr));
    } else {
      EXPECT_GT(l.maxError, 0) << l.level << ": another blend gives the same image?";
      EXPECT_LE(l.meanError, l.maxError);
    }
    pareto += l.pareto;
  }
  EXPECT_EQ(references, 1);
  EXPECT_GE(pareto, 1);
  std::string table = benchMarkdown(r);
  for (const char* level : {"| rnm (reference) |", "| whiteout |", "| add |"})
    EXPECT_NE(table.find(level), std::string::npos) << table;
}

// A graph with one knob, written at its middle level: the knob's family has the node's
// three levels against the exact one, and "as written" is the middle level again.
TEST(Bench, AGraphsOwnKnobsAreItsFamilies) {
  std::string dir = test::makeTempDir("wg_bench_graph");
  test::writeFile(dir + "/g.json", R"({"version": 1, "name": "g", "nodes": [
    {"id": "f", "type": "fresnel", "options": {"model": "schlick"}},
    {"id": "tint", "type": "mix", "inputs": {"a": [0, 0.15, 0.25], "b": [0.6, 0.75, 0.9], "t": "f.reflectance"}}],
    "outputs": {"fragment": {"color": "tint.out"}}})");
  BenchSettings s;
  s.graphFile = dir + "/g.json";
  s.camera = "grazing";
  s.width = s.height = 48;
  s.runs = 1;
  BenchResult r = runBench(s);
  std::vector<std::string> names;
  for (const auto& l : r.levels) names.push_back(l.family + "/" + l.level + (l.reference ? " (ref)" : ""));
  EXPECT_EQ(names, (std::vector<std::string>{"f.model/power", "f.model/schlick", "f.model/exact (ref)",
                                             "as written/reference (ref)", "as written/as written"}));
  ASSERT_EQ(r.levels.size(), 5u);
  EXPECT_EQ(r.levels[2].maxError, 0);
  EXPECT_GT(r.levels[0].maxError, 0);
  EXPECT_GT(r.levels[1].maxError, 0);
  EXPECT_EQ(r.levels[4].maxError, r.levels[1].maxError);  // as written = schlick
  EXPECT_EQ(r.levels[4].spirvInstructions, r.levels[1].spirvInstructions);
  s.families = {"nope"};
  EXPECT_THROW(runBench(s), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(Bench, AGraphWithoutKnobsIsAClearError) {
  std::string dir = test::makeTempDir("wg_bench_graph");
  test::writeFile(dir + "/g.json", R"({"version": 1, "name": "g", "nodes": [{"id": "n", "type": "normal"}],
    "outputs": {"fragment": {"color": "n.out"}}})");
  BenchSettings s;
  s.graphFile = dir + "/g.json";
  try {
    runBench(s);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("g.json: error: the graph has no node with a quality knob"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// A --family that does not exist is an error naming the ones that do, for a graph's knobs
// and for a configuration file alike (it used to be skipped without a word).
TEST(Bench, AnUnknownFamilyIsNamedWithTheOnesThatExist) {
  std::string dir = test::makeTempDir("wg_bench_family");
  test::writeFile(dir + "/g.json", R"({"version": 1, "name": "g",
    "nodes": [{"id": "f", "type": "fresnel"}, {"id": "c", "type": "combine", "inputs": {"x": "f.reflectance"}}],
    "outputs": {"fragment": {"color": "c.out"}}})");
  test::writeFile(dir + "/v.json", R"({"families": [{"name": "x", "graph_file": "g.json", "levels": {"a": {}}, "reference": "a"}]})");
  BenchSettings fromGraph;
  fromGraph.graphFile = dir + "/g.json";
  fromGraph.families = {"f.model", "f.modle"};
  BenchSettings fromConfig;
  fromConfig.configFile = dir + "/v.json";
  fromConfig.root = dir;
  fromConfig.families = {"y"};
  for (const auto& [s, expected] : {std::pair{fromGraph, "g.json: error: no family 'f.modle'; the graph's knobs give: f.model, as written"},
                                    std::pair{fromConfig, "v.json: error: no family 'y'; the configuration has: x"}}) {
    try {
      runBench(s);
      ADD_FAILURE() << "no error for " << expected;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(Bench, ABadConfigIsOneLineNamingTheFile) {
  std::string dir = test::makeTempDir("wg_bench");
  test::writeFile(dir + "/v.json", R"({"families": [{"name": "x", "graph_file": "nope.json", "levels": {"a": {}}, "reference": "a"}]})");
  BenchSettings s;
  s.configFile = dir + "/v.json";
  s.root = dir;
  try {
    runBench(s);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("v.json: error: family 'x': the graph does not load"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// Configurations of the wrong shape: each a one-line error naming the file and a code, not
// a library exception; a syntax error at its line and column; a folder is not a file.
TEST(Bench, AConfigOfTheWrongShapeIsAnErrorWithACode) {
  std::string dir = test::makeTempDir("wg_bench_shape");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"families": [{"name": 1}]})", "[WG004] family 1: \"name\" must be a string (got 1)"},
      {R"({"families": [null]})", "[WG004] family 1 must be an object (got null)"},
      {R"({"families": [{"name": "x", "camera": 5, "levels": {}}]})", "[WG004] family 1: \"camera\" must be a string"},
      {R"({"families": [{"name": "x", "graph_file": 5}]})", "[WG004] family 1: \"graph_file\" must be a string"},
      {R"({"families": [{"name": "x", "node": []}]})", "[WG004] family 1: \"node\" must be a string"},
      {R"([1, 2])", "[WG004] needs \"families\""},
      {"{\n  \"families\": [\n  {", "v.json:3:4: error: [WG001] the bench configuration is not valid JSON"},
  };
  for (const auto& [text, expected] : cases) {
    test::writeFile(dir + "/v.json", text);
    BenchSettings s;
    s.configFile = dir + "/v.json";
    s.root = dir;
    try {
      runBench(s);
      ADD_FAILURE() << "no error for " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << text << "\n" << e.what();
    }
  }
  std::filesystem::create_directories(dir + "/folder.json");
  BenchSettings s;
  s.configFile = dir + "/folder.json";
  try {
    runBench(s);
    ADD_FAILURE() << "no error for a folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("[WG050] cannot read the bench configuration"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg::accuracy

namespace wg::accuracy {
namespace {

// --plot: gnuplot draws in a private folder (it wrote /tmp/wg_bench_PID.* and opened the
// output itself, following a link planted there), a quote in a family name or the output
// path cannot end a string in its script, and the picture replaces a link at the output.
TEST(BenchPlot, DrawsInAPrivateFolderAndReplacesALinkAtTheOutput) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  std::string dir = test::makeTempDir("wg_bench_plot_");
  test::writeFile(dir + "/victim", "precious");
  const std::string png = dir + "/it's plot.png";
  std::filesystem::create_symlink(dir + "/victim", png);
  BenchResult r;
  r.settings.width = r.settings.height = 8;
  for (const char* family : {"a'b", "system 'touch x'"}) {
    BenchLevel ref{family, "ref", "n", "above", true, 1, 1, 1};
    BenchLevel fast{family, "fast\"one", "n", "above", false, 0.5, 0.5, 0.5};
    fast.meanError = 1e-3;
    fast.pareto = ref.pareto = true;
    r.levels.push_back(ref);
    r.levels.push_back(fast);
  }
  EXPECT_EQ(writeBenchPlot(r, png), "");
  EXPECT_EQ(test::readFile(dir + "/victim"), "precious");
  EXPECT_FALSE(std::filesystem::is_symlink(png));
  EXPECT_EQ(test::readFile(png).substr(1, 3), "PNG");
  EXPECT_FALSE(std::filesystem::exists("x"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg::accuracy
