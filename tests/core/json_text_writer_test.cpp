// JsonTextWriter writes the bytes nlohmann's dump(2) writes for the same value: checked
// against nlohmann on values that take every path (empty and nested containers, escapes,
// UTF-8, control characters, doubles that need their shortest form), and a key out of
// byte order is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/json_text_writer.h"

namespace wg {
namespace {

// Writes `j` (whose objects iterate in byte order, as nlohmann's std::map does) through
// the writer, member by member.
void writeThrough(JsonTextWriter& w, const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object:
      w.beginObject();
      for (const auto& [k, v] : j.items()) {
        w.key(k);
        writeThrough(w, v);
      }
      w.endObject();
      return;
    case nlohmann::json::value_t::array:
      w.beginArray();
      for (const auto& v : j) writeThrough(w, v);
      w.endArray();
      return;
    case nlohmann::json::value_t::string: return w.string(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::number_float: return w.number(j.get<double>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned: return w.integer(j.get<long long>());
    default: FAIL() << "not written by the writer: " << j.dump();
  }
}

std::string written(const nlohmann::json& j) {
  std::string out;
  JsonTextWriter w(out);
  writeThrough(w, j);
  return out;
}

TEST(JsonTextWriter, WritesTheBytesOfNlohmannsDumpWithIndentTwo) {
  const nlohmann::json cases[] = {
      nlohmann::json::object(),
      nlohmann::json::array(),
      {{"a", nlohmann::json::array()}, {"b", nlohmann::json::object()}, {"c", {1, 2, {{"d", "e"}}}}},
      {{"quote \" and \\ backslash", "tab\tnew\nline\rcr\bbs\fff"}},
      {{"control", std::string("\x01\x1f\x7f", 3)}, {"utf8", "\xc3\xa9t\xc3\xa9 \xe2\x88\x9e \xf0\x9f\x8c\x8a"}},
      {{"numbers", {0.0, -0.0, 1.0, 0.1, 1e-5, 1.5e300, 123456789.0, 2.0 / 3.0, -7.25e-310}}},
      {{"integers", {0, -1, 42, 2147483647}}},
      {{"nested", {{{"x", {{{"y", nlohmann::json::array({nlohmann::json::array()})}}}}}}}},
  };
  for (const auto& j : cases) EXPECT_EQ(written(j), j.dump(2)) << j.dump();
}

TEST(JsonTextWriter, NonFiniteDoublesAreNullAsInNlohmann) {
  nlohmann::json j = {std::numeric_limits<double>::infinity(), std::nan("")};
  EXPECT_EQ(written(j), j.dump(2));
}

TEST(JsonTextWriter, RefusesAKeyOutOfByteOrder) {
  std::string out;
  JsonTextWriter w(out);
  w.beginObject();
  w.member("b", "1");
  EXPECT_THROW(w.key("a"), std::logic_error);
  EXPECT_THROW(w.key("b"), std::logic_error) << "a repeated key";
}

TEST(JsonTextWriter, RefusesAValueWithoutAKeyInAnObject) {
  std::string out;
  JsonTextWriter w(out);
  w.beginObject();
  EXPECT_THROW(w.string("x"), std::logic_error);
}

}  // namespace
}  // namespace wg
