#include "core/frame_size_text.h"

#include <gtest/gtest.h>

namespace wg {
namespace {

TEST(FrameSizeText, ReadsWidthAndHeight) {
  auto size = parseFrameSizeText("1280x720", 4);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 1280);
  EXPECT_EQ(size->height, 720);
  size = parseFrameSizeText("00008x9", 5);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 8);
  EXPECT_EQ(size->height, 9);
}

TEST(FrameSizeText, RefusesEverythingElse) {
  for (const char* text : {"", "x", "1280", "1280x", "x720", "1280X720", " 1280x720", "1280x720 ", "+1280x720",
                           "-8x8", "12 80x720", "1280x720x2", "1280x7e2", "0x0.5", "1280\0x720"}) {
    EXPECT_FALSE(parseFrameSizeText(text, 4).has_value()) << '"' << text << '"';
  }
  // The digit limit holds on each side: five digits are refused at four and taken at five.
  EXPECT_FALSE(parseFrameSizeText("12800x720", 4).has_value());
  EXPECT_FALSE(parseFrameSizeText("1280x72000", 4).has_value());
  EXPECT_TRUE(parseFrameSizeText("12800x72000", 5).has_value());
}

}  // namespace
}  // namespace wg
