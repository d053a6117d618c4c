// examples/floating-buoy: a host program that floats a buoy on graphs/ocean.json through the
// header `compile --target query-c` writes. Built as its comment says and run: after it
// settles (2 s), the buoy rides the water it queries (within 0.5 m of the height under it,
// while that height swings by more than 2 m) and is tilted by the normal (not upright at
// every second), and it stays within a metre of where it was dropped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "eco_support.h"

namespace wg {
namespace {

TEST(FloatingBuoy, RidesTheWaterItQueries) {
  eco::TempDir dir("wg_buoy_");
  auto compiled = eco::wgRun("compile " + test::shellQuote(test::sourcePath("graphs/ocean.json")) + " -o " +
                             test::shellQuote(dir.path()) + " --target glsl330,query-c -q");
  ASSERT_EQ(compiled.exit, 0) << compiled.err;
  auto built = eco::sh("cc -std=c99 -pedantic -Wall -Wextra -Werror -O2 -I " + test::shellQuote(dir.path()) +
                       " -DQUERY_HEADER='\"ocean.query.h\"' -D'QUERY(f)=wg_ocean_##f' " +
                       test::shellQuote(test::sourcePath("examples/floating-buoy/buoy.c")) + " -o " +
                       test::shellQuote(dir / "buoy") + " -lm");
  ASSERT_EQ(built.exit, 0) << built.err;
  auto run = eco::sh(test::shellQuote(dir / "buoy"));
  ASSERT_EQ(run.exit, 0) << run.err;
  std::vector<std::string> lines = test::splitLines(run.out);
  ASSERT_EQ(lines.size(), 21u) << run.out;
  double lowest = 1e9, highest = -1e9, maxTilt = 0;
  for (const std::string& line : lines) {
    double t, x, y, z, h, tilt;
    ASSERT_EQ(std::sscanf(line.c_str(), "t %lf s buoy (%lf, %lf, %lf) water %lf tilt %lf deg", &t, &x, &y, &z, &h, &tilt), 6)
        << line;
    EXPECT_NEAR(x, 3.0, 1.0) << line;
    EXPECT_NEAR(z, -2.0, 1.0) << line;
    if (t < 2) continue;
    EXPECT_NEAR(y, h, 0.5) << line;
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
    maxTilt = std::max(maxTilt, tilt);
  }
  EXPECT_GT(highest - lowest, 2.0);
  EXPECT_GT(maxTilt, 10.0);
}

}  // namespace
}  // namespace wg
