// JSON with positions: a handler of the positioned SAX events (core/json_events.h) that
// builds the DOM itself, recording where every value and key starts.
#include "core/json_source.h"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <utility>
#include <vector>

namespace wg {

namespace {

// Builds the DOM and the position tree beside it from the events.
class DomBuilder : public JsonEventHandler {
 public:
  explicit DomBuilder(JsonSource& out) : out_(out) {}

  void scalar(JsonScalar& v, JsonPosition at) override { place(v.toJson(), at, false); }

  void startContainer(bool isArray, JsonPosition at) override {
    auto [ptr, entry] = place(isArray ? nlohmann::json::array() : nlohmann::json::object(), at, isArray);
    stack_.push_back(Frame{ptr, entry, isArray, {}, {}, false, nullptr});
  }

  void endContainer(bool) override { stack_.pop_back(); }

  void key(std::string& k, JsonPosition at, bool duplicate) override {
    Frame& f = stack_.back();
    f.keyPos = at;
    f.duplicate = duplicate;
    if (duplicate) return;
    // The member's slot is made now (null until its value arrives): one look-up per key.
    f.slot = &f.value->get_ref<nlohmann::json::object_t&>().emplace(k, nullptr).first->second;
    f.key = std::move(k);
  }

 private:
  struct Frame {
    nlohmann::json* value;
    uint32_t entry;  // its JsonSource::Entry
    bool isArray;
    std::string key;  // objects: the member being read
    JsonPosition keyPos;
    bool duplicate = false;
    nlohmann::json* slot = nullptr;  // objects: where the member's value goes
  };

  // Places `v` in the current container and records its entry; returns both.
  std::pair<nlohmann::json*, uint32_t> place(nlohmann::json&& v, JsonPosition where, bool isArray) {
    auto index = static_cast<uint32_t>(out_.entries.size());
    out_.entries.emplace_back();
    out_.entries.back().value = where;
    out_.entries.back().isArray = isArray;
    if (stack_.empty()) {
      out_.root = std::move(v);
      return {&out_.root, index};
    }
    Frame& f = stack_.back();
    if (f.isArray) {
      f.value->push_back(std::move(v));
      out_.entries[f.entry].children.push_back(index);
      return {&f.value->back(), index};
    }
    if (f.duplicate) {
      // Parsed for its errors, then dropped: the first definition stays (an orphan entry).
      scratch_.push_back(std::move(v));
      return {&scratch_.back(), index};
    }
    out_.entries[index].key = f.keyPos;
    out_.entries[index].name = std::move(f.key);
    out_.entries[f.entry].children.push_back(index);
    *f.slot = std::move(v);
    return {f.slot, index};
  }

  JsonSource& out_;
  std::vector<Frame> stack_;
  std::deque<nlohmann::json> scratch_;  // values of duplicate keys (stable addresses)
};

}  // namespace

const JsonSource::Entry* JsonSource::member(const Entry& object, std::string_view name) const {
  constexpr size_t kScanLimit = 16;  // beyond this, a hash index (big "parameters" objects)
  if (object.children.size() <= kScanLimit) {
    for (uint32_t c : object.children)
      if (entries[c].name == name) return &entries[c];
    return nullptr;
  }
  auto [it, made] = memberIndex_.try_emplace(static_cast<uint32_t>(&object - entries.data()));
  if (made)
    for (uint32_t c : object.children) it->second.emplace(entries[c].name, c);
  auto m = it->second.find(std::string(name));
  return m == it->second.end() ? nullptr : &entries[m->second];
}

const JsonSource::Entry* JsonSource::find(std::string_view pointer) const {
  if (entries.empty()) return nullptr;
  const Entry* at = &entries[0];
  std::string segment;
  while (!pointer.empty()) {
    if (pointer[0] != '/') return nullptr;
    pointer.remove_prefix(1);
    size_t end = std::min(pointer.find('/'), pointer.size());
    segment.clear();
    for (size_t i = 0; i < end; ++i) {  // "~1" is '/', "~0" is '~'
      if (pointer[i] == '~' && i + 1 < end && (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
        segment += pointer[++i] == '1' ? '/' : '~';
      } else {
        segment += pointer[i];
      }
    }
    pointer.remove_prefix(end);
    if (at->isArray) {
      size_t index = 0;
      if (segment.empty() || segment.size() > 9) return nullptr;
      for (char c : segment) {
        if (c < '0' || c > '9') return nullptr;
        index = index * 10 + static_cast<size_t>(c - '0');
      }
      if (index >= at->children.size()) return nullptr;
      at = &entries[at->children[index]];
    } else {
      at = member(*at, segment);
      if (!at) return nullptr;
    }
  }
  return at;
}

SourceRef JsonSource::valueOf(const Entry* e) const {
  return e ? SourceRef{file, e->value.line, e->value.col} : SourceRef{entries.empty() ? FileName() : file, 0, 0};
}

SourceRef JsonSource::keyOf(const Entry* e) const {
  return e ? SourceRef{file, e->key.line, e->key.col} : SourceRef{entries.empty() ? FileName() : file, 0, 0};
}

SourceRef JsonSource::value(const std::string& pointer) const { return valueOf(find(pointer)); }

SourceRef JsonSource::key(const std::string& pointer) const { return keyOf(pointer.empty() ? nullptr : find(pointer)); }

std::vector<std::string> JsonSource::keysInOrder(const std::string& pointer) const {
  std::vector<std::string> keys;
  const Entry* e = find(pointer);
  if (!e || e->isArray) return keys;
  keys.reserve(e->children.size());
  for (uint32_t c : e->children) keys.push_back(entries[c].name);
  return keys;
}

std::string jsonPointerEscape(std::string_view key) {
  std::string out;
  out.reserve(key.size());
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::optional<JsonSource> parseJsonWithPositions(std::string_view text, const std::string& file,
                                                 Diagnostics& diags) {
  JsonSource out;
  out.file = file;
  out.entries.reserve(text.size() / 12 + 16);  // about one value per 12 bytes of a graph
  DomBuilder builder(out);
  if (!parseJsonEvents(text, file, diags, builder)) return std::nullopt;
  return out;
}

}  // namespace wg
