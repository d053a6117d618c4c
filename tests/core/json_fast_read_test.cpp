// The reader of well-formed JSON (core/json_fast_read.h) against nlohmann's parser, the one
// it stands in for: on every file of graphs/ and on thousands of mutations of them it must
// accept exactly what nlohmann accepts (less duplicate keys and nesting past the limit,
// which the format refuses), give the same values with the same number types, and put every
// event where its token starts; and parseJsonEvents must report every file it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/json_events.h"
#include "core/json_fast_read.h"
#include "test_support.h"

namespace wg {
namespace {

using nlohmann::json;
using test::readFile;
using test::sourcePath;

// Builds a DOM from the events and checks that each event's position is where its token
// starts in the text.
class DomRecorder : public JsonEventHandler {
 public:
  explicit DomRecorder(const std::string& text) {
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i)
      if (i == text.size() || text[i] == '\n') {
        lines_.push_back(text.substr(start, i - start));
        start = i + 1;
      }
  }

  json root;
  std::vector<std::string> misplaced;  // events whose position is not their token's start

  void scalar(JsonScalar& v, JsonPosition at) override {
    const char c = charAt(at);
    bool ok = false;
    switch (v.type) {
      case json::value_t::string: ok = c == '"'; break;
      case json::value_t::boolean: ok = c == (v.boolean ? 't' : 'f'); break;
      case json::value_t::null: ok = c == 'n'; break;
      default: ok = c == '-' || (c >= '0' && c <= '9'); break;
    }
    if (!ok) misplaced.push_back("scalar at " + where(at));
    place(v.toJson());
  }
  void startContainer(bool isArray, JsonPosition at) override {
    if (charAt(at) != (isArray ? '[' : '{')) misplaced.push_back("container at " + where(at));
    json* slot = place(isArray ? json::array() : json::object());
    stack_.push_back(slot);
  }
  void endContainer(bool) override { stack_.pop_back(); }
  void key(std::string& name, JsonPosition at, bool duplicate) override {
    if (charAt(at) != '"') misplaced.push_back("key at " + where(at));
    if (duplicate) misplaced.push_back("a duplicate delivered: " + name);
    key_ = std::move(name);
  }

 private:
  char charAt(JsonPosition at) const {
    if (at.line < 1 || static_cast<std::size_t>(at.line) > lines_.size()) return '\0';
    const std::string& line = lines_[static_cast<std::size_t>(at.line - 1)];
    if (at.col < 1 || static_cast<std::size_t>(at.col) > line.size()) return '\0';
    return line[static_cast<std::size_t>(at.col - 1)];
  }
  static std::string where(JsonPosition at) { return std::to_string(at.line) + ":" + std::to_string(at.col); }
  json* place(json&& v) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    return &(top[key_] = std::move(v));
  }

  std::vector<std::string> lines_;
  std::vector<json*> stack_;
  std::string key_;
};

// Equal values and equal JSON types all the way down (json's == calls 1 and 1.0 equal);
// doubles compared bit for bit.
bool identical(const json& a, const json& b) {
  if (a.type() != b.type()) return false;
  switch (a.type()) {
    case json::value_t::object: {
      if (a.size() != b.size()) return false;
      for (auto it = a.begin(); it != a.end(); ++it)
        if (!b.contains(it.key()) || !identical(it.value(), b.at(it.key()))) return false;
      return true;
    }
    case json::value_t::array: {
      if (a.size() != b.size()) return false;
      for (std::size_t i = 0; i < a.size(); ++i)
        if (!identical(a[i], b[i])) return false;
      return true;
    }
    case json::value_t::number_float: {
      double x = a.get<double>(), y = b.get<double>();
      return std::memcmp(&x, &y, sizeof x) == 0;
    }
    default: return a == b;
  }
}

// What the reader is held to for one text; returns a description of the first difference.
std::string disagreement(const std::string& text) {
  DomRecorder events(text);
  const bool fast = readWellFormedJsonEvents(text, events);
  const bool nlohmannAccepts = json::accept(text);
  if (fast && !nlohmannAccepts) return "accepted a text nlohmann refuses";
  if (fast) {
    if (!events.misplaced.empty()) return events.misplaced.front();
    if (!identical(events.root, json::parse(text))) return "values differ from nlohmann's";
    return {};
  }
  // Refused: parseJsonEvents must then say why (nlohmann's words, or WG003/WG035 for a
  // text nlohmann takes).
  Diagnostics diags;
  DomRecorder ignored(text);
  if (parseJsonEvents(text, "t.json", diags, ignored)) return "refused, yet parseJsonEvents succeeded";
  if (!diags.hasErrors()) return "refused without a diagnostic";
  if (nlohmannAccepts) {
    bool allowed = false;
    for (const auto& d : diags.all()) allowed |= d.code == DiagCode::DuplicateKey || d.code == DiagCode::LimitExceeded;
    if (!allowed) return "refused a text nlohmann accepts: " + diags.all().front().message;
  }
  return {};
}

TEST(JsonFastRead, NumbersAreTypedAsNlohmannTypesThem) {
  for (const char* text :
       {"0", "-0", "7", "-7", "18446744073709551615", "18446744073709551616", "-9223372036854775808",
        "-9223372036854775809", "1.0", "-0.0", "1e2", "1E+2", "2.5e-3", "0.1", "1e-310", "1e-400", "-1e-400",
        "3.4028234663852886e38", "1.7976931348623157e308", "123456789012345678901234567890", "[1,22 ,333]",
        "{\"a\":-1.5e1}"}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(disagreement(text), "");
    DomRecorder events(text);
    EXPECT_TRUE(readWellFormedJsonEvents(text, events));
  }
}

TEST(JsonFastRead, StringsDecodeAsNlohmannDecodesThem) {
  for (const char* text :
       {R"("")", R"("plain")", R"("\"\\\/\b\f\n\r\t")", R"("\u0041\u00e9\u20AC")", R"("\ud83c\udf0a")",
        R"("\u0000")", "\"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8C\x8A \xED\x9F\xBF \xEE\x80\x80 \xF4\x8F\xBF\xBF\"",
        "\"\x7F\"", "{\"k\\u00e9y\": [\"a\", \"b\"]}"}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(disagreement(text), "");
    DomRecorder events(text);
    EXPECT_TRUE(readWellFormedJsonEvents(text, events));
  }
}

TEST(JsonFastRead, RefusesWhatNlohmannRefusesAndParseJsonEventsSaysWhy) {
  using namespace std::string_literals;
  for (const std::string& text : std::vector<std::string>{
           ""s, " "s, "01"s, "-", "1.", ".5", "1e", "+1", "1e400", "-1e400", "[1,]", "{\"a\":1,}", "{\"a\" 1}", "[1 2]",
        "tru", "nulll", "[", "{", "\"open", "\"\\x\"", R"("\ud83c")", R"("\udf0a")", R"("\ud83c\u0041")",
        "\"\\u12\"", "\"a\x01\"", "\"\xC0\x80\"", "\"\xC2\"", "\"\xE0\x80\x80\"", "\"\xED\xA0\x80\"",
        "\"\xF4\x90\x80\x80\"", "\"\xF5\x80\x80\x80\"", "\"\xFF\"", "1 2"s, "{} x"s, "[1,\0]"s, "{\"a\":1,\"a\":2}"s,
        "{\"a\":{\"b\":1},\"b\":{\"b\":2,\"b\":3}}"s}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(disagreement(text), "");
    DomRecorder events(text);
    EXPECT_FALSE(readWellFormedJsonEvents(text, events));
  }
}

// nlohmann ends its input at a NUL byte outside a string; so does this reader.
TEST(JsonFastRead, ANulByteEndsTheInput) {
  using namespace std::string_literals;
  for (const std::string& text : {"[]\0"s, "{\"a\": 1}  \0 anything"s}) {
    EXPECT_EQ(disagreement(text), "");
    DomRecorder events(text);
    EXPECT_TRUE(readWellFormedJsonEvents(text, events));
  }
}

TEST(JsonFastRead, NestingUpToTheLimitAndNoDeeper) {
  std::string ok(64, '['), deep(65, '[');
  ok += std::string(64, ']');
  deep += std::string(65, ']');
  DomRecorder a(ok), b(deep);
  EXPECT_TRUE(readWellFormedJsonEvents(ok, a));
  EXPECT_FALSE(readWellFormedJsonEvents(deep, b));
  EXPECT_EQ(disagreement(deep), "");
  Diagnostics diags;
  EXPECT_FALSE(parseJsonEvents(deep, "t.json", diags, b));
  ASSERT_TRUE(diags.hasErrors());
  EXPECT_EQ(diags.all().front().code, DiagCode::LimitExceeded);
}

// Every graph of the repository, then mutations of each: a byte replaced by one that
// matters to JSON, a byte removed, the text cut short.
TEST(JsonFastRead, AgreesWithNlohmannOnEveryGraphAndItsMutations) {
  std::vector<std::string> texts;
  for (const auto& e : std::filesystem::recursive_directory_iterator(sourcePath("graphs")))
    if (e.path().extension() == ".json") texts.push_back(readFile(e.path().string()));
  ASSERT_GT(texts.size(), 10u);
  const char bytes[] = {'"', '\\', ',', '}', ']', '{', '[', ':', '0', '-', 'e', '.', ' ', '\n', 'u', 't',
                        '\x7F', '\x80', '\xC3', '\xE0', '\xED', '\xF4', '\x00', '\x1F'};
  uint32_t lcg = 2024;
  auto next = [&lcg](uint32_t n) {
    lcg = lcg * 1664525u + 1013904223u;
    return (lcg >> 8) % n;
  };
  int mutations = 0, accepted = 0;
  for (const std::string& text : texts) {
    EXPECT_EQ(disagreement(text), "") << "an unmodified graph";
    for (int k = 0; k < 200; ++k) {
      std::string m = text;
      auto at = static_cast<std::size_t>(next(static_cast<uint32_t>(m.size())));
      switch (next(3)) {
        case 0: m[at] = bytes[next(sizeof bytes)]; break;
        case 1: m.erase(at, 1); break;
        default: m.resize(at); break;
      }
      std::string why = disagreement(m);
      EXPECT_EQ(why, "") << "mutation " << k << " at byte " << at;
      ++mutations;
      DomRecorder events(m);
      accepted += readWellFormedJsonEvents(m, events);
    }
  }
  // Both kinds occur: a mutation inside a string or a number often leaves valid JSON.
  EXPECT_GT(accepted, mutations / 20);
  EXPECT_LT(accepted, mutations - mutations / 20);
}

}  // namespace
}  // namespace wg
