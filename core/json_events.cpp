// A file's JSON events: read by core/json_fast_read.h when the file is valid; when it is
// not, nlohmann's SAX parser, fed through a byte-counting iterator so that every error can be
// given the position where its token starts, says what is wrong.
#include "core/json_events.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

#include "core/json_fast_read.h"
#include "core/json_key_set.h"
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
  JsonPosition position(std::size_t offset) const {
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
  using value_t = nlohmann::json::value_t;

  PositionSax(std::string_view text, const std::string& file, Diagnostics& diags, JsonEventHandler& handler,
              const std::size_t& consumed)
      : text_(text), file_(file), diags_(diags), handler_(handler), consumed_(consumed), lines_(text) {}

  bool null() { return scalar(JsonScalar{}, false); }
  bool boolean(bool v) {
    JsonScalar s;
    s.type = value_t::boolean;
    s.boolean = v;
    return scalar(s, false);
  }
  bool number_integer(number_integer_t v) {
    JsonScalar s;
    s.type = value_t::number_integer;
    s.integer = v;
    return scalar(s, true);
  }
  bool number_unsigned(number_unsigned_t v) {
    JsonScalar s;
    s.type = value_t::number_unsigned;
    s.unsignedInteger = v;
    return scalar(s, true);
  }
  bool number_float(number_float_t v, const string_t&) {
    JsonScalar s;
    s.type = value_t::number_float;
    s.number = v;
    return scalar(s, true);
  }
  bool string(string_t& v) {
    JsonScalar s;
    s.type = value_t::string;
    s.string = &v;
    return scalar(s, false);
  }
  bool binary(binary_t&) { return true; }  // never produced by the JSON lexer

  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(false); }
  bool end_array() { return close(true); }

  bool key(string_t& k) {
    std::size_t start = tokenStart();
    prevEnd_ = consumed_;
    JsonPosition at = lines_.position(start);
    const JsonPosition* first = keys_[depth_ - 1].seenOrAdd(k, at);
    if (first) {
      auto& d = diags_.error(DiagCode::DuplicateKey, ref(at), "duplicate key '" + k + "'");
      d.notes.push_back("first defined at " + std::to_string(first->line) + ":" + std::to_string(first->col));
    }
    handler_.key(k, at, first != nullptr);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::detail::exception& ex) {
    // `position` counts the bytes read, including the offending one (or end of input).
    // The lexer reads a whole token before the parser refuses it, so step back from the
    // last byte read to the token's first: a string's opening quote, a literal's first
    // character.
    std::size_t offset = std::min(position > 0 ? position - 1 : 0, text_.size());
    offset = tokenStartBefore(offset);
    SourceRef where = at(offset);
    std::string what = ex.what();
    if (ex.id == 406) {  // out_of_range: a float literal that overflows double
      diags_.error(DiagCode::NonFiniteLiteral, at(tokenStart()), "number " + lastToken + " is outside float32 range");
      return false;
    }
    std::string message = cleanParseMessage(what);
    if (what.find("ill-formed UTF-8") != std::string::npos) {
      // Point at the bad byte; a sequence cut short is reported at its lead byte.
      std::size_t bad = std::min(position > 0 ? position - 1 : 0, text_.size());
      std::size_t lead = bad;
      while (lead > 0 && (static_cast<unsigned char>(text_[lead - 1]) & 0xC0u) == 0x80u) --lead;
      if (lead > 0 && static_cast<unsigned char>(text_[lead - 1]) >= 0xC0u) bad = lead - 1;
      diags_.error(DiagCode::JsonEncoding, at(bad), "invalid UTF-8 in a string: the file must be saved as UTF-8");
      return false;
    }
    diags_.error(DiagCode::JsonSyntax, where, message);
    return false;
  }

 private:
  SourceRef ref(JsonPosition p) const { return SourceRef{file_, p.line, p.col}; }
  SourceRef at(std::size_t offset) const { return ref(lines_.position(offset)); }

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

  static bool isSkippable(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ':'; }

  // The current token's first byte: the first byte after the previous token that is not
  // whitespace or a separator.
  std::size_t tokenStart() const {
    std::size_t i = std::min(prevEnd_, text_.size());
    while (i < text_.size() && isSkippable(text_[i])) ++i;
    return i;
  }

  bool scalar(JsonScalar s, bool isNumber) {
    std::size_t start = tokenStart();
    // After a number the lexer has read one byte of lookahead (unless at end of input).
    std::size_t end = consumed_;
    if (isNumber && end > start && end <= text_.size()) {
      char last = text_[end - 1];
      bool numberChar =
          (last >= '0' && last <= '9') || last == '.' || last == 'e' || last == 'E' || last == '+' || last == '-';
      if (!numberChar) --end;
    }
    prevEnd_ = end;
    handler_.scalar(s, lines_.position(start));
    return true;
  }

  bool open(bool isArray) {
    std::size_t start = tokenStart();
    prevEnd_ = consumed_;
    JsonPosition where = lines_.position(start);
    if (depth_ >= kMaxDepth) {
      diags_.error(DiagCode::LimitExceeded, ref(where),
                   "JSON nesting is deeper than " + std::to_string(kMaxDepth) + " levels");
      return false;
    }
    // Frames are kept, not popped, so their key lists keep their capacity.
    if (keys_.size() <= static_cast<std::size_t>(depth_)) keys_.emplace_back();
    if (!isArray) keys_[depth_].clear();
    ++depth_;
    handler_.startContainer(isArray, where);
    return true;
  }

  bool close(bool isArray) {
    prevEnd_ = consumed_;
    --depth_;
    handler_.endContainer(isArray);
    return true;
  }

  std::string_view text_;
  const std::string& file_;
  Diagnostics& diags_;
  JsonEventHandler& handler_;
  const std::size_t& consumed_;
  LineTable lines_;
  std::size_t prevEnd_ = 0;
  int depth_ = 0;
  std::vector<JsonKeySet> keys_;  // per open container (unused for arrays)
};

class IgnoredEvents : public JsonEventHandler {
 public:
  void scalar(JsonScalar&, JsonPosition) override {}
  void startContainer(bool, JsonPosition) override {}
  void endContainer(bool) override {}
  void key(std::string&, JsonPosition, bool) override {}
};

}  // namespace

bool parseJsonEvents(std::string_view text, const std::string& file, Diagnostics& diags, JsonEventHandler& handler) {
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  if (text.size() >= 3 && byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) {
    diags.error(DiagCode::JsonEncoding, SourceRef{file, 1, 1},
                "the file starts with a UTF-8 byte-order mark; save it without one");
    return false;
  }
  // UTF-16 (either byte order; what some Windows editors save) is not a syntax error but
  // the wrong encoding: say so instead of "invalid literal".
  if (text.size() >= 2 && ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))) {
    diags.error(DiagCode::JsonEncoding, SourceRef{file, 1, 1},
                "the file starts with a UTF-16 byte-order mark; save it as UTF-8 without one");
    return false;
  }
  if (readWellFormedJsonEvents(text, handler)) return true;
  // Not a well-formed file: nlohmann's parser says what is wrong, and where, to a handler
  // that keeps nothing (the caller drops what its handler holds on failure).
  IgnoredEvents ignored;
  const std::size_t errorsBefore = diags.errorCount();
  std::size_t consumed = 0;
  PositionSax sax(text, file, diags, ignored, consumed);
  const char* base = text.data();
  CountingIterator first(base, base, &consumed);
  CountingIterator last(base, base + text.size(), nullptr);
  bool ok = nlohmann::json::sax_parse(first, last, &sax);
  // Both readers refuse the same files, so nlohmann finds an error here; if it ever did not,
  // the events went to `ignored` and the load must fail all the same.
  if (diags.errorCount() == errorsBefore)
    diags.error(DiagCode::JsonSyntax, SourceRef{file, 1, 1}, "the file could not be parsed as JSON");
  (void)ok;
  return false;
}

}  // namespace wg
