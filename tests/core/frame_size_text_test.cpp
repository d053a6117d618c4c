#include "core/frame_size_text.h"

#include <gtest/gtest.h>

namespace wg {
namespace {

TEST(FrameSizeText, ReadsWidthAndHeight) {
  auto size = parseFrameSizeText("1280x720", 8, 9999);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 1280);
  EXPECT_EQ(size->height, 720);
  size = parseFrameSizeText("00008x9", 1, 8192);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 8);
  EXPECT_EQ(size->height, 9);
}

TEST(FrameSizeText, RefusesEverythingElse) {
  for (const char* text : {"", "x", "1280", "1280x", "x720", "1280X720", " 1280x720", "1280x720 ", "+1280x720",
                           "-8x8", "12 80x720", "1280x720x2", "1280x7e2", "0x0.5", "1280\0x720"}) {
    EXPECT_FALSE(parseFrameSizeText(text, 1, 9999).has_value()) << '"' << text << '"';
  }
}

// Each side within [min, max], the bounds themselves included; digits past the maximum are
// refused before they could overflow.
TEST(FrameSizeText, EachSideWithinItsRange) {
  EXPECT_TRUE(parseFrameSizeText("8x4096", 8, 4096).has_value());
  EXPECT_FALSE(parseFrameSizeText("7x100", 8, 4096).has_value());
  EXPECT_FALSE(parseFrameSizeText("100x7", 8, 4096).has_value());
  EXPECT_FALSE(parseFrameSizeText("4097x100", 8, 4096).has_value());
  EXPECT_FALSE(parseFrameSizeText("100x4097", 8, 4096).has_value());
  EXPECT_FALSE(parseFrameSizeText("0x0", 1, 8192).has_value());
  EXPECT_FALSE(parseFrameSizeText("99999999999999999999x720", 1, 8192).has_value());
  EXPECT_FALSE(parseFrameSizeText("1280x99999999999999999999", 1, 8192).has_value());
}

}  // namespace
}  // namespace wg
