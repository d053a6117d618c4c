// Memory at the largest sizes (docs/robustness.md, issue 40 class 7): what a size costs is
// estimated before anything is allocated and refused past the budget with one line, exit 2
// (bench --size 9999x9999 took 7.3 GB and failed "render target incomplete"; tune --size
// 8193x8193 6.3 GB; check --size 4096x4096 2.86 GB); an allocation that fails anyway is one
// line, never "internal error". The sizes just over and under the budget are found with a
// budget lowered through WATERGRAPH_MEMORY_BUDGET_MIB, so no test allocates gigabytes.
#ifdef WG_HAVE_RUNTIME
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/memory_budget.h"
#include "runtime/renderer.h"
#include "runtime/runtime_error.h"
#include "test_support.h"

namespace wg {
namespace {

using test::CmdResult;

Manifest manifestOf(const std::string& graph) {
  Diagnostics diags;
  auto g = loadGraphFile(test::sourcePath(graph), diags);
  EXPECT_TRUE(g) << graph;
  CompileOptions options;
  options.targets = {Target::Glsl330};
  auto r = compileGraph(*g, defaultRegistry(), options, diags);
  EXPECT_TRUE(r) << graph;
  return r->manifest;
}

rt::RenderSettings square(int side, bool floatColor = false) {
  rt::RenderSettings s;
  s.width = s.height = side;
  s.floatColor = floatColor;
  return s;
}

// The largest square side whose renderer of `manifest` keeps `budget`.
int largestSide(const Manifest& manifest, size_t budget, bool floatColor = false) {
  int lo = 1, hi = 65536;
  while (lo < hi) {
    int mid = lo + (hi - lo + 1) / 2;
    if (rt::rendererBytes(manifest, square(mid, floatColor)) <= budget) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

TEST(MemoryBudget, ARenderersShareIsItsTargetsAndItsReadBack) {
  // lake: the frame (RGBA16F colour, 32-bit float depth), the display image (RGBA8) and the
  // picture read back (RGBA8): 8 + 4 + 4 + 4 bytes a pixel.
  Manifest lake = manifestOf("graphs/lake.json");
  EXPECT_EQ(rt::rendererBytes(lake, square(100)), 100u * 100u * 20u);
  // Accuracy renders: RGBA32F frame and depth, no display image, the float frame read back.
  EXPECT_EQ(rt::rendererBytes(lake, square(100, true)), 100u * 100u * (16u + 4u + 16u));
  // Scene targets count at their size: tutorial_pbr's reflection, refraction, depth,
  // scene colour and a 128-texel environment cube.
  Manifest pbr = manifestOf("graphs/tutorial_pbr.json");
  EXPECT_GT(rt::rendererBytes(pbr, square(100)), rt::rendererBytes(lake, square(100)) + 100u * 100u * 24u);
}

TEST(MemoryBudget, SizesJustUnderTheBudgetAreKeptAndJustOverRefused) {
  const size_t budget = rt::memoryBudget();
  ASSERT_EQ(budget, rt::kDefaultMemoryBudget) << "WATERGRAPH_MEMORY_BUDGET_MIB is set for the test binary";
  for (const char* graph : {"graphs/lake.json", "graphs/tutorial_pbr.json"}) {
    Manifest m = manifestOf(graph);
    int side = largestSide(m, budget);
    SCOPED_TRACE(std::string(graph) + " at " + std::to_string(side));
    EXPECT_NO_THROW(rt::checkMemoryBudget(rt::rendererBytes(m, square(side)), "a render"));
    try {
      rt::checkMemoryBudget(rt::rendererBytes(m, square(side + 1)), "render targets at the next size");
      ADD_FAILURE() << "one pixel more a side is not refused";
    } catch (const rt::RuntimeError& e) {
      EXPECT_EQ(e.kind(), rt::RuntimeError::Kind::Budget);
      EXPECT_EQ(e.exitCode(), 2);
      EXPECT_NE(std::string(e.what()).find("over the memory budget of 2.00 GiB"), std::string::npos) << e.what();
    }
  }
  // lake's 20 bytes a pixel: the largest square is 10,362 (2 GiB / 20 = 107,374,182 pixels).
  EXPECT_EQ(largestSide(manifestOf("graphs/lake.json"), budget), 10362);
}

TEST(MemoryBudget, ReservationsAddUpAndAreGivenBack) {
  const size_t budget = rt::memoryBudget();
  {
    rt::MemoryReservation half(budget / 2, "half");
    EXPECT_EQ(rt::memoryReserved(), budget / 2);
    EXPECT_NO_THROW(rt::MemoryReservation other(budget - budget / 2, "the rest"));
    EXPECT_THROW(rt::MemoryReservation more(budget - budget / 2 + 1, "a byte too many"), rt::RuntimeError);
    EXPECT_EQ(rt::memoryReserved(), budget / 2);  // a refused reservation holds nothing
  }
  EXPECT_EQ(rt::memoryReserved(), 0u);
  // Sizes from the command line cannot wrap the estimate round.
  EXPECT_EQ(rt::saturatedProduct(SIZE_MAX / 2, 3), SIZE_MAX);
  EXPECT_EQ(rt::saturatedSum(SIZE_MAX - 1, 2), SIZE_MAX);
  EXPECT_THROW(rt::checkMemoryBudget(SIZE_MAX, "everything"), rt::RuntimeError);
}

// The review's sizes through the CLI: refused by the estimate, before a target is made
// (so in far less than the minutes and gigabytes they took), one line, exit 2.
void expectRefused(const CmdResult& r, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("over the memory budget of 2.00 GiB"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("incomplete"), std::string::npos) << r.err;
}

TEST(MemoryBudget, TheReviewsSizesAreRefusedBeforeAllocating) {
  std::string dir = test::makeTempDir("wg_memory_");
  const std::string lake = test::shellQuote(test::sourcePath("graphs/lake.json"));
  expectRefused(test::runWatergraph("bench " + lake + " --size 9999x9999 --runs 1"), "bench 9999x9999");
  expectRefused(test::runWatergraph("tune " + lake + " --size 8193x8193 --min-psnr 40"), "tune 8193x8193");
  expectRefused(test::runWatergraph("check " + lake + " --size 4096x4096 --target glsl330"), "check 4096x4096");
  const std::string png = dir + "/big.png";
  expectRefused(test::runWatergraph("render " + test::shellQuote(test::sourcePath("graphs/tutorial_pbr.json")) +
                                    " --size 8192x8192 -o " + test::shellQuote(png)),
                "render 8192x8192");
  EXPECT_FALSE(std::filesystem::exists(png));
  std::filesystem::remove_all(dir);
}

// With the budget lowered to 64 MiB, lake renders at the largest square it allows and is
// refused one pixel a side above it: the estimate is what the renderer reserves.
TEST(MemoryBudget, ALoweredBudgetMovesTheLargestSize) {
  const size_t budget = size_t{64} << 20;
  int side = largestSide(manifestOf("graphs/lake.json"), budget);
  ASSERT_EQ(side, 1831);  // 64 MiB / 20 bytes a pixel = 3,355,443 pixels
  std::string dir = test::makeTempDir("wg_memory_");
  const std::string lake = test::shellQuote(test::sourcePath("graphs/lake.json"));
  auto render = [&](int s) {
    return test::runSplit("WATERGRAPH_MEMORY_BUDGET_MIB=64 " + test::shellQuote(test::watergraphBinary()) + " render " + lake +
                          " --size " + std::to_string(s) + "x" + std::to_string(s) + " -o " +
                          test::shellQuote(dir + "/lake" + std::to_string(s) + ".png"));
  };
  CmdResult under = render(side);
  EXPECT_EQ(under.exit, 0) << under.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/lake" + std::to_string(side) + ".png"));
  CmdResult over = render(side + 1);
  EXPECT_EQ(over.exit, 2) << over.err;
  EXPECT_NE(over.err.find("over the memory budget of 64.0 MiB"), std::string::npos) << over.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/lake" + std::to_string(side + 1) + ".png"));
  std::filesystem::remove_all(dir);
}

// An allocation that fails anyway (a process capped below what the work needs) is one line
// and exit 2, never "internal error: std::bad_alloc". A 1 GiB address-space cap leaves the
// program room to start; a 100,000-node chain cannot compile in it.
TEST(MemoryBudget, AnAllocationFailureIsOneClearLine) {
  std::string dir = test::makeTempDir("wg_memory_");
  std::string s = "{\"version\": 1, \"name\": \"chain\", \"nodes\": [\n{\"id\": \"a0\", \"type\": \"time\"}";
  for (int i = 1; i < 100000; ++i)
    s += ",\n{\"id\": \"a" + std::to_string(i) + "\", \"type\": \"sin\", \"inputs\": {\"x\": \"a" + std::to_string(i - 1) + ".out\"}}";
  s += "\n], \"outputs\": {\"fragment\": {\"alpha\": \"a99999.out\"}}}\n";
  test::writeFile(dir + "/chain.json", s);
  CmdResult r = test::runSplit("ulimit -v 262144; " + test::shellQuote(test::watergraphBinary()) + " validate " +
                               test::shellQuote(dir + "/chain.json") + " --target glsl330");
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("watergraph: out of memory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(test::splitLines(r.err).size(), 1u) << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
#endif
