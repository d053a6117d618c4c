// `watergraph validate|compile --explain-frequency`: the frequency report per graph, as a
// user reads it (codegen/frequency_report.h builds it; tests/codegen/frequency_test.cpp
// checks the classification itself).
#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

TEST(CliFrequency, ValidatePrintsEachGraphsReportWithItsPerDrawRoots) {
  std::string dir = test::makeTempDir("wg_freq_");
  std::string graph = dir + "/chain.json";
  // tint = colour * k * 0.5 depends only on parameters; the uv makes the rest per-pixel.
  test::writeFile(graph, test::graphJson(
                             R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
                                {"id": "half", "type": "mul", "inputs": {"a": "$k", "b": 0.5}},
                                {"id": "tint", "type": "mul", "inputs": {"a": "$colour", "b": "half.out"}},
                                {"id": "shade", "type": "mul", "inputs": {"a": "tint.out", "b": "l.out"}})",
                             R"("fragment": {"color": "shade.out"})",
                             R"("k": {"type": "float", "default": 0.5}, "colour": {"type": "vec3", "default": [0, 0.3, 0.5]})"));
  test::CmdResult r = test::runWatergraph("validate " + shellQuote(graph) + " " +
                                          shellQuote(test::sourcePath("graphs/classic_webgl.json")) + " --explain-frequency");
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("t: 5 ops after the passes: 0 constant, 2 per-draw, 0 per-vertex, 3 per-fragment\n"
                       "  per-draw ops computed per pixel: 2, about 2 of the fragment stage's 4 operations per pixel\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("    node 'tint' (mul) output out (vec3): 2 operations from 2 ops of nodes [half, tint]\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("classic_webgl: "), std::string::npos) << "one report per graph\n" << r.out;
  EXPECT_NE(r.out.find("validated 2 graphs for 3 targets: ok"), std::string::npos) << r.out;

  // Without the flag: no report.
  test::CmdResult plain = test::runWatergraph("validate " + shellQuote(graph));
  EXPECT_EQ(plain.out.find("after the passes"), std::string::npos) << plain.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wg
