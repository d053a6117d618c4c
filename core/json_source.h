#pragma once
// JSON parsed into a DOM plus the file position of every value and key (nlohmann's own DOM
// keeps none and silently drops duplicate keys), for readers that walk a DOM (probe cases
// files). The graph loader reads the events directly (core/json_events.h).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "core/json_events.h"
#include "core/source_ref.h"

namespace wg {

struct JsonSource {
  // A line and column in `file`; SourceRefs are made from them only when asked for.
  using Position = JsonPosition;
  // One parsed value, in a tree beside the DOM: positions, the member key, and children in
  // file order. One entry per value, with no string per value beyond its key: a map keyed by
  // JSON pointer cost two heap strings and two map nodes per value, most of a load's time.
  struct Entry {
    Position value;                  // the value's first character
    Position key;                    // object members: the key's opening quote
    std::string name;                // object members: the key
    std::vector<uint32_t> children;  // containers: elements, or members (first of duplicates)
    bool isArray = false;
  };

  FileName file;
  nlohmann::json root;
  std::vector<Entry> entries;  // entries[0] is the root; values of duplicate keys are orphans

  // By JSON pointer ("/nodes/3/inputs/normal"); line 0 when there is no such value.
  SourceRef value(const std::string& pointer) const;
  SourceRef key(const std::string& pointer) const;  // the member key's opening quote
  // Member keys of the object at `pointer` in file order (nlohmann's object sorts them);
  // duplicate keys appear once. Empty for anything else.
  std::vector<std::string> keysInOrder(const std::string& pointer) const;

  // The same look-ups from an entry already found, without making pointer strings (the
  // loader walks every node this way). `entry` takes a pointer; `member` a member's name
  // (nullptr when absent); `valueOf`/`keyOf` accept nullptr like value()/key() accept a
  // pointer to nothing.
  const Entry* entry(std::string_view pointer) const { return find(pointer); }
  const Entry* member(const Entry& object, std::string_view name) const;
  const Entry& child(const Entry& container, size_t i) const { return entries[container.children[i]]; }
  SourceRef valueOf(const Entry* e) const;
  SourceRef keyOf(const Entry* e) const;

 private:
  const Entry* find(std::string_view pointer) const;
  // Objects with many members get a name index on first look-up (mutable: a cache), by
  // entry number, so a copy of the JsonSource stays correct.
  mutable std::unordered_map<uint32_t, std::unordered_map<std::string, uint32_t>> memberIndex_;
};

// Reports what parseJsonEvents reports (syntax, encoding, duplicate keys, depth).
std::optional<JsonSource> parseJsonWithPositions(std::string_view text, const std::string& file,
                                                 Diagnostics& diags);

// Escapes '~' and '/' in a key for use in a JSON pointer.
std::string jsonPointerEscape(std::string_view key);

}  // namespace wg
