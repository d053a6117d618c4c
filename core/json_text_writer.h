#pragma once
// JSON text written straight into one string, in the layout nlohmann's dump(2) gives
// (two-space indent, "key": value, "{}" and "[]" when empty, keys in byte order), so a
// large file such as a 10,000-node manifest is written without building a DOM first and
// its bytes stay those of the DOM's dump.
//
// Keys are written in the order they are given; nlohmann's objects are std::maps, so the
// caller gives them in byte order, and a key out of order throws std::logic_error (our
// defect, found by the first test that writes that object).
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg {

class JsonTextWriter {
 public:
  explicit JsonTextWriter(std::string& out) : out_(out) {}

  void beginObject();
  void endObject();
  void beginArray();
  void endArray();
  void key(std::string_view k);  // inside an object, before its value
  void string(std::string_view s);
  void number(double d);  // as nlohmann writes a double (shortest round trip, "1.0")
  void integer(long long i);
  void boolean(bool b);
  void null();
  // A whole nlohmann value, as its dump(2) writes it (objects' keys are already in byte
  // order); its keys must outlive the writer's use of the enclosing object.
  void value(const nlohmann::json& j);

  // One member with a plain value, for the common case.
  void member(std::string_view k, std::string_view s) {
    key(k);
    string(s);
  }
  void memberNumber(std::string_view k, double d) {
    key(k);
    number(d);
  }
  void memberInteger(std::string_view k, long long i) {
    key(k);
    integer(i);
  }

 private:
  struct Level {
    bool object = false;
    bool empty = true;
    std::string_view lastKey;  // keys are literals or strings that outlive the writer
  };
  void quoted(std::string_view s);
  void beforeValue();  // the separator and indentation of a new array element
  void newLine(size_t depth);
  void open(char bracket, bool object);
  void close(char bracket);

  std::string& out_;
  std::vector<Level> levels_;
  bool afterKey_ = false;
};

}  // namespace wg
