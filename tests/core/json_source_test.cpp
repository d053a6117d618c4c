#include <gtest/gtest.h>

#include <string>

#include "core/json_source.h"
#include "diagnostic_text.h"

namespace wg {
namespace {

using core_test::lc;

TEST(JsonSource, ParsesValuesAndRecordsPositions) {
  const std::string text =
      "{\n"
      "  \"a\": 1,\n"
      "  \"b\": [true, null, -2.5e3],\n"
      "  \"c\" : {\"d\":\"x\\\"y\"},\n"
      "  \"e\": 42\n"
      "}";
  Diagnostics d;
  auto js = parseJsonWithPositions(text, "t.json", d);
  ASSERT_TRUE(js) << (d.empty() ? "" : d.all()[0].message);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(js->root["a"], 1);
  EXPECT_TRUE(js->root["a"].is_number_integer());
  EXPECT_DOUBLE_EQ(js->root["b"][2].get<double>(), -2500.0);
  EXPECT_EQ(js->root["c"]["d"], "x\"y");

  EXPECT_EQ(lc(js->value("")), "1:1");
  EXPECT_EQ(js->value("").file, "t.json");
  EXPECT_EQ(lc(js->key("/a")), "2:3");
  EXPECT_EQ(lc(js->value("/a")), "2:8");
  EXPECT_EQ(lc(js->value("/b")), "3:8");
  EXPECT_EQ(lc(js->value("/b/0")), "3:9");
  EXPECT_EQ(lc(js->value("/b/1")), "3:15");
  EXPECT_EQ(lc(js->value("/b/2")), "3:21");
  EXPECT_EQ(lc(js->key("/c")), "4:3");
  EXPECT_EQ(lc(js->value("/c")), "4:9");
  EXPECT_EQ(lc(js->key("/c/d")), "4:10");
  EXPECT_EQ(lc(js->value("/c/d")), "4:14");
  EXPECT_EQ(lc(js->key("/e")), "5:3");
  EXPECT_EQ(lc(js->value("/e")), "5:8");
  EXPECT_EQ(js->value("/nope").line, 0);
}

TEST(JsonSource, KeepsMemberOrder) {
  Diagnostics d;
  auto js = parseJsonWithPositions(R"({"z": 1, "a": {"y": 2, "b": 3}, "m": 4})", "t.json", d);
  ASSERT_TRUE(js);
  EXPECT_EQ(js->keysInOrder(""), (std::vector<std::string>{"z", "a", "m"}));
  EXPECT_EQ(js->keysInOrder("/a"), (std::vector<std::string>{"y", "b"}));
}

TEST(JsonSource, NumbersAtEndOfInputAndBeforeSeparators) {
  Diagnostics d;
  auto js = parseJsonWithPositions("[1,22 ,333]", "t.json", d);
  ASSERT_TRUE(js);
  EXPECT_EQ(lc(js->value("/0")), "1:2");
  EXPECT_EQ(lc(js->value("/1")), "1:4");
  EXPECT_EQ(lc(js->value("/2")), "1:8");
  auto top = parseJsonWithPositions("  17", "t.json", d);
  ASSERT_TRUE(top);
  EXPECT_EQ(lc(top->value("")), "1:3");
}

TEST(JsonSource, EscapedKeysInPointers) {
  Diagnostics d;
  auto js = parseJsonWithPositions(R"({"a/b": {"c~d": 1}})", "t.json", d);
  ASSERT_TRUE(js);
  EXPECT_EQ(jsonPointerEscape("a/b~c"), "a~1b~0c");
  EXPECT_EQ(lc(js->value("/a~1b/c~0d")), "1:17");
  EXPECT_EQ(lc(js->key("/a~1b/c~0d")), "1:10");
}

TEST(JsonSource, CrlfLineEndings) {
  Diagnostics d;
  auto js = parseJsonWithPositions("{\r\n  \"a\": 1,\r\n  \"b\": \"x\"\r\n}\r\n", "t.json", d);
  ASSERT_TRUE(js);
  EXPECT_EQ(lc(js->key("/a")), "2:3");
  EXPECT_EQ(lc(js->value("/b")), "3:8");
}

TEST(JsonSource, SyntaxErrorHasPositionAndCleanMessage) {
  Diagnostics d;
  auto js = parseJsonWithPositions("{\n  \"a\": 1\n", "t.json", d);
  EXPECT_FALSE(js);
  ASSERT_EQ(d.all().size(), 1u);
  const auto& e = d.all()[0];
  EXPECT_EQ(e.code, DiagCode::JsonSyntax);
  EXPECT_EQ(e.where.file, "t.json");
  EXPECT_EQ(lc(e.where), "3:1");
  EXPECT_EQ(e.message.find("[json.exception"), std::string::npos) << e.message;
  EXPECT_EQ(e.message.rfind("syntax error: ", 0), 0u) << e.message;
  EXPECT_NE(e.message.find("unexpected end of input"), std::string::npos) << e.message;
}

TEST(JsonSource, SyntaxErrorInTheMiddle) {
  Diagnostics d;
  auto js = parseJsonWithPositions("{\n  \"a\": 1,\n  \"b\" 2\n}", "t.json", d);
  EXPECT_FALSE(js);
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::JsonSyntax);
  EXPECT_EQ(lc(d.all()[0].where), "3:7");
  auto trailing = parseJsonWithPositions("{} x", "t.json", d);
  EXPECT_FALSE(trailing);
  EXPECT_EQ(lc(d.all().back().where), "1:4");
}

TEST(JsonSource, ByteOrderMark) {
  Diagnostics d;
  auto js = parseJsonWithPositions("\xEF\xBB\xBF{}", "t.json", d);
  EXPECT_FALSE(js);
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::JsonEncoding);
  EXPECT_EQ(lc(d.all()[0].where), "1:1");
  EXPECT_EQ(d.all()[0].message, "the file starts with a UTF-8 byte-order mark; save it without one");
}

TEST(JsonSource, InvalidUtf8InString) {
  Diagnostics d;
  auto js = parseJsonWithPositions("{\"a\": \"x\xFFy\"}", "t.json", d);
  EXPECT_FALSE(js);
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::JsonEncoding);
  EXPECT_EQ(d.all()[0].where.line, 1);
  EXPECT_EQ(d.all()[0].where.col, 9);
}

TEST(JsonSource, ValidUtf8AndEscapes) {
  Diagnostics d;
  auto js = parseJsonWithPositions("{\"a\": \"h\xC3\xA9\\u00e9\\ud83c\\udf0a\"}", "t.json", d);
  ASSERT_TRUE(js);
  EXPECT_EQ(js->root["a"], "h\xC3\xA9\xC3\xA9\xF0\x9F\x8C\x8A");
}

TEST(JsonSource, EveryDuplicateKeyReported) {
  const std::string text =
      "{\n"
      "  \"a\": 1,\n"
      "  \"b\": {\"x\": 1, \"x\": 2},\n"
      "  \"a\": 3,\n"
      "  \"a\": 4\n"
      "}";
  Diagnostics d;
  auto js = parseJsonWithPositions(text, "t.json", d);
  EXPECT_FALSE(js);
  ASSERT_EQ(d.all().size(), 3u);
  for (const auto& e : d.all()) EXPECT_EQ(e.code, DiagCode::DuplicateKey);
  EXPECT_EQ(d.all()[0].message, "duplicate key 'x'");
  EXPECT_EQ(lc(d.all()[0].where), "3:17");
  ASSERT_EQ(d.all()[0].notes.size(), 1u);
  EXPECT_EQ(d.all()[0].notes[0], "first defined at 3:9");
  EXPECT_EQ(d.all()[1].message, "duplicate key 'a'");
  EXPECT_EQ(lc(d.all()[1].where), "4:3");
  EXPECT_EQ(d.all()[1].notes[0], "first defined at 2:3");
  EXPECT_EQ(lc(d.all()[2].where), "5:3");
}

TEST(JsonSource, SameKeyInDifferentObjectsIsFine) {
  Diagnostics d;
  auto js = parseJsonWithPositions(R"([{"a": 1}, {"a": 2}])", "t.json", d);
  ASSERT_TRUE(js);
  EXPECT_TRUE(d.empty());
}

TEST(JsonSource, NestingDepthIsLimited) {
  Diagnostics d;
  std::string ok(64, '[');
  ok += std::string(64, ']');
  EXPECT_TRUE(parseJsonWithPositions(ok, "t.json", d));
  EXPECT_TRUE(d.empty());

  std::string deep(100000, '[');
  deep += std::string(100000, ']');
  EXPECT_FALSE(parseJsonWithPositions(deep, "t.json", d));
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::LimitExceeded);
  EXPECT_EQ(lc(d.all()[0].where), "1:65");
}

TEST(JsonSource, OverflowingNumber) {
  Diagnostics d;
  EXPECT_FALSE(parseJsonWithPositions("[1, 1e999]", "t.json", d));
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::NonFiniteLiteral);
  EXPECT_EQ(d.all()[0].message, "number 1e999 is outside float32 range");
  EXPECT_EQ(lc(d.all()[0].where), "1:5");
}

TEST(JsonSource, EmptyInput) {
  Diagnostics d;
  EXPECT_FALSE(parseJsonWithPositions("", "t.json", d));
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::JsonSyntax);
  EXPECT_EQ(lc(d.all()[0].where), "1:1");
}

}  // namespace
}  // namespace wg
