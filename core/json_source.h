#pragma once
// JSON parsed by nlohmann's SAX interface into a DOM plus the file position of every
// value and key (nlohmann's own DOM keeps none and silently drops duplicate keys).
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "core/source_ref.h"

namespace wg {

struct JsonSource {
  // A line and column in `file`; SourceRefs are made from them only when asked for, so a
  // large file does not hold one copy of its name per value.
  struct Position {
    int line = 0;
    int col = 0;
  };
  std::string file;
  nlohmann::json root;
  // Keyed by JSON pointer ("/nodes/3/inputs/normal"): the value's first character.
  std::unordered_map<std::string, Position> valueAt;
  // Keyed by the pointer of the member: the member key's opening quote.
  std::unordered_map<std::string, Position> keyAt;
  // Keyed by the pointer of an object: its member keys in file order (nlohmann's object
  // sorts them). Duplicate keys appear once, at their first position.
  std::unordered_map<std::string, std::vector<std::string>> keyOrder;

  SourceRef value(const std::string& pointer) const;
  SourceRef key(const std::string& pointer) const;
};

// Reports JSON syntax (WG001), encoding (WG002: invalid UTF-8, a byte-order mark) and
// duplicate keys (WG003, every duplicate, with the first occurrence as a note).
std::optional<JsonSource> parseJsonWithPositions(std::string_view text, const std::string& file,
                                                 Diagnostics& diags);

// Escapes '~' and '/' in a key for use in a JSON pointer.
std::string jsonPointerEscape(std::string_view key);

}  // namespace wg
