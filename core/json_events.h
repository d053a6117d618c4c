#pragma once
// nlohmann's SAX parse with the file position of every value and key, and the JSON-level
// checks every reader of a graph-shaped file wants: syntax (WG001), encoding (WG002: invalid
// UTF-8, a byte-order mark), duplicate keys (WG003, every duplicate, with the first
// occurrence as a note), a float literal beyond double (WG010) and nesting deeper than 64
// levels (WG035). A handler sees the events; it builds a DOM (core/json_source.h) or a
// Graph directly (core/graph_parse.cpp) without one.
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"

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

// Feeds `text` to `handler`. False, with the diagnostics saying why, on any of the errors
// above; events already delivered stand, and the handler's result is not to be used.
bool parseJsonEvents(std::string_view text, const std::string& file, Diagnostics& diags, JsonEventHandler& handler);

}  // namespace wg
