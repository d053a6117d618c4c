// The bench's mechanics on one small family (not its timings, which are benchmarks): every
// level measured, the reference has zero error, the others' error is what the images say,
// the Pareto front is marked and the table lists every level.
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

}  // namespace
}  // namespace wg::accuracy
