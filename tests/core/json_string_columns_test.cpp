// File columns of bytes inside a JSON string (core/json_string_columns.h), escapes counted.
#include <gtest/gtest.h>

#include <string>

#include "core/json_string_columns.h"

namespace wg {
namespace {

TEST(JsonStringColumns, PlainBytesAreOneColumnEach) {
  const std::string line = R"x(  "f": "a + mixx(b)",)x";
  int quote = 8;  // the value's opening quote
  EXPECT_EQ(line[static_cast<std::size_t>(quote - 1)], '"');
  EXPECT_EQ(jsonStringByteColumn(line, quote, 0), 9);   // 'a'
  EXPECT_EQ(jsonStringByteColumn(line, quote, 4), 13);  // 'm' of mixx
  EXPECT_EQ(jsonStringByteColumn(line, quote, 10), 19);  // ')'
  EXPECT_EQ(jsonStringByteColumn(line, quote, 11), 20);  // past the end: the closing quote
  EXPECT_EQ(jsonStringByteColumn(line, quote, 99), 20);
}

TEST(JsonStringColumns, EscapesTakeTheirWrittenWidth) {
  // decoded: a " b \ c <newline> d é e 😀 f
  const std::string line = R"("a\"b\\c\nd\u00e9e\ud83d\ude00f")";
  auto col = [&](std::size_t decoded) { return jsonStringByteColumn(line, 1, decoded); };
  EXPECT_EQ(col(0), 2);   // a
  EXPECT_EQ(col(1), 3);   // \" starts at column 3
  EXPECT_EQ(col(2), 5);   // b
  EXPECT_EQ(col(3), 6);   // "\\"
  EXPECT_EQ(col(4), 8);   // c
  EXPECT_EQ(col(5), 9);   // \n
  EXPECT_EQ(col(6), 11);  // d
  EXPECT_EQ(col(7), 12);  // é: two decoded bytes, both at its escape
  EXPECT_EQ(col(8), 12);
  EXPECT_EQ(col(9), 18);  // e
  EXPECT_EQ(col(10), 19);  // the surrogate pair: four bytes, one escape of twelve characters
  EXPECT_EQ(col(13), 19);
  EXPECT_EQ(col(14), 31);  // f
  EXPECT_EQ(col(15), 32);  // the closing quote
}

TEST(JsonStringColumns, RawUtf8AndAQuoteOutsideTheLine) {
  const std::string line = "\"\xc3\xa9x\"";  // é written as UTF-8: two bytes, two columns
  EXPECT_EQ(jsonStringByteColumn(line, 1, 2), 4);
  EXPECT_EQ(jsonStringByteColumn(line, 40, 0), static_cast<int>(line.size()) + 1);
  EXPECT_EQ(jsonStringByteColumn("\"ab", 1, 5), 4);  // no closing quote: the line's end
}

}  // namespace
}  // namespace wg
