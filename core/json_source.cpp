// JSON with positions: nlohmann's SAX parser fed through a byte-counting iterator, and a
// SAX handler that builds the DOM itself, recording where every value and key starts.
//
// Positions are 1-based lines and 1-based columns counted in bytes (a tab or a multi-byte
// UTF-8 character counts as its byte length; a CR before LF is an ordinary byte).
#include "core/json_source.h"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <iterator>
#include <utility>
#include <vector>

#include "core/load_limits.h"

namespace wg {

namespace {

constexpr int kMaxDepth = kMaxJsonDepth;

// An input iterator over the text that publishes how many bytes the lexer has consumed.
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator() = default;
  CountingIterator(const char* base, const char* p, std::size_t* consumed)
      : base_(base), p_(p), consumed_(consumed) {}

  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    ++p_;
    if (consumed_) *consumed_ = static_cast<std::size_t>(p_ - base_);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const CountingIterator& o) const { return p_ != o.p_; }

 private:
  const char* base_ = nullptr;
  const char* p_ = nullptr;
  std::size_t* consumed_ = nullptr;
};

// Byte offsets to line:col.
class LineTable {
 public:
  explicit LineTable(std::string_view text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  JsonSource::Position position(std::size_t offset) const {
    // The parser asks in file order: step forward from the last line found, and search
    // only when asked for an earlier offset (an error's position).
    std::size_t line = last_;  // 1-based: starts_[line - 1] <= offset < starts_[line]
    if (offset >= starts_[line - 1]) {
      while (line < starts_.size() && starts_[line] <= offset) ++line;
    } else {
      auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
      line = static_cast<std::size_t>(it - starts_.begin());  // >= 1
    }
    last_ = line;
    std::size_t col = offset - starts_[line - 1] + 1;
    return {static_cast<int>(line), static_cast<int>(col)};
  }
  SourceRef at(const std::string& file, std::size_t offset) const {
    auto p = position(offset);
    return SourceRef{file, p.line, p.col};
  }

 private:
  std::vector<std::size_t> starts_;
  mutable std::size_t last_ = 1;
};

std::string cleanParseMessage(std::string what) {
  // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error while
  //  parsing object - unexpected end of input; expected '}'"
  if (!what.empty() && what[0] == '[') {
    auto close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
  }
  if (what.rfind("parse error", 0) == 0) {
    auto colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
  }
  const std::string prefix = "syntax error while parsing ";
  if (what.rfind(prefix, 0) == 0) {
    auto dash = what.find(" - ");
    if (dash != std::string::npos) what = "syntax error: " + what.substr(dash + 3);
  }
  return what;
}

class PositionSax {
 public:
  using number_integer_t = nlohmann::json::number_integer_t;
  using number_unsigned_t = nlohmann::json::number_unsigned_t;
  using number_float_t = nlohmann::json::number_float_t;
  using string_t = nlohmann::json::string_t;
  using binary_t = nlohmann::json::binary_t;

  PositionSax(std::string_view text, const std::string& file, Diagnostics& diags, JsonSource& out,
              const std::size_t& consumed)
      : text_(text), file_(file), diags_(diags), out_(out), consumed_(consumed), lines_(text) {}

  bool null() { return scalar(nullptr, false); }
  bool boolean(bool v) { return scalar(v, false); }
  bool number_integer(number_integer_t v) { return scalar(v, true); }
  bool number_unsigned(number_unsigned_t v) { return scalar(v, true); }
  bool number_float(number_float_t v, const string_t&) { return scalar(v, true); }
  bool string(string_t& v) { return scalar(std::move(v), false); }
  bool binary(binary_t&) { return true; }  // never produced by the JSON lexer

  bool start_object(std::size_t) { return open(nlohmann::json::object(), false); }
  bool start_array(std::size_t) { return open(nlohmann::json::array(), true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(string_t& k) {
    std::size_t start = tokenStart();
    prevEnd_ = consumed_;
    Frame& f = stack_.back();
    f.key = k;
    f.keyPos = lines_.position(start);
    f.duplicate = false;
    // The member's slot is made now (null until its value arrives): one look-up per key.
    auto [slot, inserted] = f.value->get_ref<nlohmann::json::object_t&>().emplace(k, nullptr);
    f.slot = &slot->second;
    if (!inserted) {
      for (uint32_t c : out_.entries[f.entry].children) {
        const JsonSource::Entry& first = out_.entries[c];
        if (first.name != k) continue;
        auto& d = diags_.error(DiagCode::DuplicateKey, SourceRef{file_, f.keyPos.line, f.keyPos.col},
                               "duplicate key '" + k + "'");
        d.notes.push_back("first defined at " + std::to_string(first.key.line) + ":" + std::to_string(first.key.col));
        f.duplicate = true;
        break;
      }
    }
    return true;
  }

  bool parse_error(std::size_t position, const std::string& lastToken,
                   const nlohmann::detail::exception& ex) {
    // `position` counts the bytes read, including the offending one (or end of input).
    // The lexer reads a whole token before the parser refuses it, so step back from the
    // last byte read to the token's first: a string's opening quote, a literal's first
    // character.
    std::size_t offset = std::min(position > 0 ? position - 1 : 0, text_.size());
    offset = tokenStartBefore(offset);
    SourceRef where = lines_.at(file_, offset);
    std::string what = ex.what();
    if (ex.id == 406) {  // out_of_range: a float literal that overflows double
      std::size_t start = tokenStart();
      diags_.error(DiagCode::NonFiniteLiteral, lines_.at(file_, start),
                   "number " + lastToken + " is outside float32 range");
      return false;
    }
    std::string message = cleanParseMessage(what);
    if (what.find("ill-formed UTF-8") != std::string::npos) {
      // Point at the bad byte; a sequence cut short is reported at its lead byte.
      std::size_t bad = std::min(position > 0 ? position - 1 : 0, text_.size());
      std::size_t lead = bad;
      while (lead > 0 && (static_cast<unsigned char>(text_[lead - 1]) & 0xC0u) == 0x80u) --lead;
      if (lead > 0 && static_cast<unsigned char>(text_[lead - 1]) >= 0xC0u) bad = lead - 1;
      where = lines_.at(file_, bad);
      diags_.error(DiagCode::JsonEncoding, where,
                   "invalid UTF-8 in a string: the file must be saved as UTF-8");
      return false;
    }
    diags_.error(DiagCode::JsonSyntax, where, message);
    return false;
  }

  bool depthExceeded() const { return depthExceeded_; }

  std::size_t tokenStartBefore(std::size_t last) const {
    if (last >= text_.size()) return last;
    auto literalChar = [](char c) {
      return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' || c == '+' ||
             c == '-';
    };
    auto escaped = [&](std::size_t i) {
      std::size_t backslashes = 0;
      while (i > backslashes && text_[i - 1 - backslashes] == '\\') ++backslashes;
      return backslashes % 2 == 1;
    };
    if (text_[last] == '"' && last > 0) {
      for (std::size_t j = last; j-- > 0;)
        if (text_[j] == '"' && !escaped(j)) return j;
      return last;
    }
    if (literalChar(text_[last]))
      while (last > 0 && literalChar(text_[last - 1])) --last;
    return last;
  }

 private:
  struct Frame {
    nlohmann::json* value;
    uint32_t entry;  // its JsonSource::Entry
    bool isArray;
    std::string key;                 // objects: the member being read
    JsonSource::Position keyPos;
    bool duplicate = false;
    nlohmann::json* slot = nullptr;  // objects: where the member's value goes
  };

  static bool isSkippable(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ':';
  }

  // The current token's first byte: the first byte after the previous token that is not
  // whitespace or a separator.
  std::size_t tokenStart() const {
    std::size_t i = std::min(prevEnd_, text_.size());
    while (i < text_.size() && isSkippable(text_[i])) ++i;
    return i;
  }

  // Places `v` in the current container and records its entry; returns both.
  std::pair<nlohmann::json*, uint32_t> place(nlohmann::json&& v, JsonSource::Position where, bool isArray) {
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

  template <typename T>
  bool scalar(T&& v, bool isNumber) {
    std::size_t start = tokenStart();
    // After a number the lexer has read one byte of lookahead (unless at end of input).
    std::size_t end = consumed_;
    if (isNumber && end > start && end <= text_.size()) {
      char last = text_[end - 1];
      bool numberChar = (last >= '0' && last <= '9') || last == '.' || last == 'e' ||
                        last == 'E' || last == '+' || last == '-';
      if (!numberChar) --end;
    }
    prevEnd_ = end;
    place(nlohmann::json(std::forward<T>(v)), lines_.position(start), false);
    return true;
  }

  bool open(nlohmann::json&& container, bool isArray) {
    std::size_t start = tokenStart();
    prevEnd_ = consumed_;
    JsonSource::Position where = lines_.position(start);
    if (static_cast<int>(stack_.size()) >= kMaxDepth) {
      diags_.error(DiagCode::LimitExceeded, SourceRef{file_, where.line, where.col},
                   "JSON nesting is deeper than " + std::to_string(kMaxDepth) + " levels");
      depthExceeded_ = true;
      return false;
    }
    auto [ptr, entry] = place(std::move(container), where, isArray);
    stack_.push_back(Frame{ptr, entry, isArray, {}, {}, false, nullptr});
    return true;
  }

  bool close() {
    prevEnd_ = consumed_;
    stack_.pop_back();
    return true;
  }

  std::string_view text_;
  const std::string& file_;
  Diagnostics& diags_;
  JsonSource& out_;
  const std::size_t& consumed_;
  LineTable lines_;
  std::size_t prevEnd_ = 0;
  std::vector<Frame> stack_;
  std::deque<nlohmann::json> scratch_;  // values of duplicate keys (stable addresses)
  bool depthExceeded_ = false;
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
  return e ? SourceRef{file, e->value.line, e->value.col} : SourceRef{entries.empty() ? std::string() : file, 0, 0};
}

SourceRef JsonSource::keyOf(const Entry* e) const {
  return e ? SourceRef{file, e->key.line, e->key.col} : SourceRef{entries.empty() ? std::string() : file, 0, 0};
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
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
      static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF) {
    diags.error(DiagCode::JsonEncoding, SourceRef{file, 1, 1},
                "the file starts with a UTF-8 byte-order mark; save it without one");
    return std::nullopt;
  }
  // UTF-16 (either byte order; what some Windows editors save) is not a syntax error but
  // the wrong encoding: say so instead of "invalid literal".
  if (text.size() >= 2 && ((static_cast<unsigned char>(text[0]) == 0xFF && static_cast<unsigned char>(text[1]) == 0xFE) ||
                           (static_cast<unsigned char>(text[0]) == 0xFE && static_cast<unsigned char>(text[1]) == 0xFF))) {
    diags.error(DiagCode::JsonEncoding, SourceRef{file, 1, 1},
                "the file starts with a UTF-16 byte-order mark; save it as UTF-8 without one");
    return std::nullopt;
  }
  size_t errorsBefore = diags.errorCount();
  JsonSource out;
  out.file = file;
  out.entries.reserve(text.size() / 12 + 16);  // about one value per 12 bytes of a graph
  std::size_t consumed = 0;
  PositionSax sax(text, file, diags, out, consumed);
  const char* base = text.data();
  CountingIterator first(base, base, &consumed);
  CountingIterator last(base, base + text.size(), nullptr);
  bool ok = nlohmann::json::sax_parse(first, last, &sax);
  if (!ok && diags.errorCount() == errorsBefore) {
    diags.error(DiagCode::JsonSyntax, SourceRef{file, 1, 1}, "the file could not be parsed as JSON");
  }
  if (!ok || diags.errorCount() > errorsBefore) return std::nullopt;
  return out;
}

}  // namespace wg
