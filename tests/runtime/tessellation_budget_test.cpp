// The tessellation budget per draw (runtime/tessellation_budget.h): legal options (factor
// 64 at every distance) made a render that did not finish in 600 s on llvmpipe; the
// runtime now draws fewer, larger patches so a draw generates at most
// kMaxTessellatedTrianglesPerDraw triangles.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "runtime/tessellation_budget.h"
#include "test_support.h"

namespace wg {
namespace {

TEST(TessellationBudget, TheGridShrinksOnlyPastTheBudget) {
  using namespace rt;
  EXPECT_EQ(tessellatedGridQuads(128, 4), 128);  // graphs/stylized.json: well inside
  EXPECT_EQ(tessellatedGridQuads(64, 8), 64);  // tests/runtime/tessellation_test.cpp at its grid
  int q = tessellatedGridQuads(128, 64);
  EXPECT_LT(q, 128);
  EXPECT_LE(tessellatedTriangles(q, 64), kMaxTessellatedTrianglesPerDraw);
  EXPECT_GT(tessellatedTriangles(q + 1, 64), kMaxTessellatedTrianglesPerDraw);  // the largest grid that fits
  EXPECT_EQ(tessellatedGridQuads(0, 64), 1);
  EXPECT_EQ(tessellatedGridQuads(100000, 1e300), tessellatedGridQuads(100000, 64));  // levels stop at GL's 64
}

TEST(TessellationBudget, FactorSixtyFourEverywhereRendersInBoundedTime) {
  std::string dir = test::makeTempDir("wg_tess_budget_");
  test::writeFile(dir + "/tess64.json", R"({
  "version": 1,
  "name": "tess64",
  "nodes": [
    {"id": "waves", "type": "gerstner_waves",
     "options": {"waves": [{"direction": [1, 0.2], "steepness": 0.5, "wavelength": 6}]}},
    {"id": "surface", "type": "vertex_output",
     "options": {"tessellation": "distance", "factor": 64, "min_distance": 1000000, "max_distance": 1000000},
     "inputs": {"position": "waves.position", "normal": "waves.normal"}}
  ],
  "outputs": {"vertex": {"position": "surface.position", "normal": "surface.normal"},
              "fragment": {"color": [0.1, 0.3, 0.5]}}
})");
  auto t0 = std::chrono::steady_clock::now();
  std::string out;
  int code = test::runCommand("timeout 300 " + test::shellQuote(test::watergraphBinary()) + " render " + dir +
                                  "/tess64.json -o " + dir + "/tess64.png --size 64x64",
                              &out);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(code, 0) << out;  // 124: still drawing after five minutes
  EXPECT_LT(seconds, 120) << out;
  std::printf("factor-64 render at 64x64: %.1f s\n", seconds);
}

}  // namespace
}  // namespace wg
