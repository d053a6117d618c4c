// The lagoon example's texture is made by a script in the repository: running
// scripts/make_lagoon_texture.py again gives the same pixels as graphs/lagoon_ripples.png
// (pixels, not bytes: another zlib may compress the same image differently), and the
// texture tiles (its first and last rows and columns continue into each other).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "runtime/image.h"
#include "test_support.h"

namespace wg {
namespace {

TEST(LagoonTexture, TheScriptMakesTheShippedPixels) {
  std::string dir = test::makeTempDir("wg_lagoon_texture");
  std::string made = dir + "/lagoon_ripples.png";
  std::string out, err;
  int status = test::runCommandSplit("python3 " + test::shellQuote(test::sourcePath("scripts/make_lagoon_texture.py")) + " " +
                                         test::shellQuote(made),
                                     &out, &err);
  ASSERT_EQ(status, 0) << err;
  rt::Image shipped = rt::readPng(test::sourcePath("graphs/lagoon_ripples.png"));
  rt::Image again = rt::readPng(made);
  EXPECT_EQ(shipped.width, 256);
  EXPECT_EQ(shipped.height, 256);
  EXPECT_EQ(again.width, shipped.width);
  EXPECT_EQ(again.height, shipped.height);
  EXPECT_TRUE(again.rgba8 == shipped.rgba8) << "run scripts/make_lagoon_texture.py and commit the PNG";
  std::filesystem::remove_all(dir);
}

TEST(LagoonTexture, TilesWithoutASeam) {
  rt::Image t = rt::readPng(test::sourcePath("graphs/lagoon_ripples.png"));
  ASSERT_EQ(t.width, 256);
  // Across the wrap, neighbouring texels differ no more than neighbours inside do.
  auto at = [&](int x, int y, int c) { return static_cast<int>(t.rgba8[(static_cast<size_t>(y) * 256 + static_cast<size_t>(x)) * 4 + static_cast<size_t>(c)]); };
  int inside = 0, across = 0;
  for (int y = 0; y < 256; ++y)
    for (int c = 0; c < 4; ++c) {
      for (int x = 0; x + 1 < 256; ++x) inside = std::max(inside, std::abs(at(x, y, c) - at(x + 1, y, c)));
      across = std::max(across, std::abs(at(255, y, c) - at(0, y, c)));
    }
  EXPECT_GT(inside, 0);
  EXPECT_LE(across, inside);
}

}  // namespace
}  // namespace wg
