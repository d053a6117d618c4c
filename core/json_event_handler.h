#pragma once
// What a reader of JSON events sees (core/json_events.h feeds it): positions, scalars as the
// lexer typed them, containers and keys. Apart from parseJsonEvents so that the two readers
// behind it (core/json_fast_read.h for valid files, nlohmann's parser for the others) and
// the duplicate-key set they share (core/json_key_set.h) sit below it, not beside it.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace wg {

// 1-based line, 1-based column in bytes (a tab or a multi-byte UTF-8 character counts as
// its byte length; a CR before LF is an ordinary byte).
struct JsonPosition {
  int line = 0;
  int col = 0;
};

// One scalar as the lexer produced it. `string` points at the lexer's buffer: a handler may
// move from it.
struct JsonScalar {
  nlohmann::json::value_t type = nlohmann::json::value_t::null;
  bool boolean = false;
  std::int64_t integer = 0;
  std::uint64_t unsignedInteger = 0;
  double number = 0;
  std::string* string = nullptr;

  bool isNumber() const;
  double asDouble() const;  // any number type
  nlohmann::json toJson();  // moves the string
};

class JsonEventHandler {
 public:
  virtual ~JsonEventHandler() = default;
  virtual void scalar(JsonScalar& value, JsonPosition at) = 0;
  virtual void startContainer(bool isArray, JsonPosition at) = 0;
  virtual void endContainer(bool isArray) = 0;
  // An object member's key at its opening quote. A duplicate is reported already; its
  // value follows as usual and a handler drops it (the first definition stays).
  virtual void key(std::string& name, JsonPosition at, bool duplicate) = 0;
};

}  // namespace wg
