// A JSON reader over the bytes in place for files that are valid (core/json_fast_read.h).
// Every rule below is nlohmann 3.11's for the same input: anything it would refuse, this
// reader refuses too, and leaves the telling to it.
#include "core/json_fast_read.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

#include "core/json_key_set.h"
#include "core/load_limits.h"

namespace wg {
namespace {

// Bytes that stand for themselves inside a string: printable ASCII but '"' and '\\'
// (nlohmann takes 0x7F as is too). Control characters must be escaped; a byte from 0x80 on
// starts a UTF-8 sequence, checked on its own. A table: one load per byte of a string.
struct PlainStringBytes {
  bool plain[256] = {};
  constexpr PlainStringBytes() {
    for (int c = 0x20; c < 0x80; ++c) plain[c] = c != '"' && c != '\\';
  }
};
constexpr PlainStringBytes kPlainStringBytes;

constexpr bool isJsonDigit(char c) { return c >= '0' && c <= '9'; }

int jsonHexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void appendJsonUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

class WellFormedReader {
 public:
  WellFormedReader(std::string_view text, JsonEventHandler& handler)
      : p_(text.data()), end_(text.data() + text.size()), lineStart_(text.data()), handler_(handler) {
    keys_.reserve(kMaxJsonDepth);  // an object holds its key set while nested ones add theirs
  }

  bool document() {
    if (!value(0)) return false;
    skipWhitespace();
    // nlohmann's lexer takes a NUL byte for the end of the input: what follows one is
    // never read.
    return p_ == end_ || *p_ == '\0';
  }

 private:
  JsonPosition here() const { return {line_, static_cast<int>(p_ - lineStart_) + 1}; }

  void skipWhitespace() {
    const char* p = p_;
    const char* const end = end_;
    for (; p < end; ++p) {
      const char c = *p;
      if (c == '\n') {
        ++line_;
        lineStart_ = p + 1;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        break;
      }
    }
    p_ = p;
  }

  // The value at p_ (after whitespace); `depth` containers are open around it.
  bool value(int depth) {
    skipWhitespace();
    if (p_ == end_) return false;
    const JsonPosition at = here();
    switch (*p_) {
      case '{': return object(depth, at);
      case '[': return array(depth, at);
      case '"': {
        if (!string(text_)) return false;
        JsonScalar s;
        s.type = nlohmann::json::value_t::string;
        s.string = &text_;
        handler_.scalar(s, at);
        return true;
      }
      case 't': return literal("true", nlohmann::json::value_t::boolean, true, at);
      case 'f': return literal("false", nlohmann::json::value_t::boolean, false, at);
      case 'n': return literal("null", nlohmann::json::value_t::null, false, at);
      default: return number(at);
    }
  }

  bool literal(std::string_view word, nlohmann::json::value_t type, bool truth, JsonPosition at) {
    if (static_cast<std::size_t>(end_ - p_) < word.size() || std::string_view(p_, word.size()) != word) return false;
    p_ += word.size();
    JsonScalar s;
    s.type = type;
    s.boolean = truth;
    handler_.scalar(s, at);
    return true;
  }

  bool object(int depth, JsonPosition at) {
    if (depth >= kMaxJsonDepth) return false;
    if (keys_.size() <= static_cast<std::size_t>(depth)) keys_.resize(static_cast<std::size_t>(depth) + 1);
    JsonKeySet& seen = keys_[static_cast<std::size_t>(depth)];
    seen.clear();
    ++p_;
    handler_.startContainer(false, at);
    skipWhitespace();
    if (p_ < end_ && *p_ == '}') {
      ++p_;
      handler_.endContainer(false);
      return true;
    }
    for (;;) {
      skipWhitespace();
      if (p_ == end_ || *p_ != '"') return false;
      const JsonPosition keyAt = here();
      if (!string(key_)) return false;
      // A duplicate is an error; the nested objects reuse the deeper key sets, so `seen`
      // still holds this object's keys here.
      if (seen.seenOrAdd(key_, keyAt)) return false;
      skipWhitespace();
      if (p_ == end_ || *p_ != ':') return false;
      ++p_;
      handler_.key(key_, keyAt, false);
      if (!value(depth + 1)) return false;
      skipWhitespace();
      if (p_ == end_) return false;
      if (*p_ == ',') {
        ++p_;
        continue;
      }
      if (*p_ != '}') return false;
      ++p_;
      handler_.endContainer(false);
      return true;
    }
  }

  bool array(int depth, JsonPosition at) {
    if (depth >= kMaxJsonDepth) return false;
    ++p_;
    handler_.startContainer(true, at);
    skipWhitespace();
    if (p_ < end_ && *p_ == ']') {
      ++p_;
      handler_.endContainer(true);
      return true;
    }
    for (;;) {
      if (!value(depth + 1)) return false;
      skipWhitespace();
      if (p_ == end_) return false;
      if (*p_ == ',') {
        ++p_;
        continue;
      }
      if (*p_ != ']') return false;
      ++p_;
      handler_.endContainer(true);
      return true;
    }
  }

  // The string whose opening quote is at p_, decoded into `out`.
  bool string(std::string& out) {
    ++p_;
    out.clear();
    for (;;) {
      const char* run = p_;
      const char* p = p_;
      const char* const end = end_;
      while (p < end && kPlainStringBytes.plain[static_cast<unsigned char>(*p)]) ++p;
      p_ = p;
      out.append(run, static_cast<std::size_t>(p - run));
      if (p_ == end_) return false;
      const auto c = static_cast<unsigned char>(*p_);
      if (c == '"') {
        ++p_;
        return true;
      }
      if (c == '\\') {
        if (!escape(out)) return false;
      } else if (c >= 0x80) {
        if (!utf8Sequence(out)) return false;
      } else {
        return false;  // a control character
      }
    }
  }

  bool escape(std::string& out) {
    if (end_ - p_ < 2) return false;
    char e = p_[1];
    p_ += 2;
    switch (e) {
      case '"': out += '"'; return true;
      case '\\': out += '\\'; return true;
      case '/': out += '/'; return true;
      case 'b': out += '\b'; return true;
      case 'f': out += '\f'; return true;
      case 'n': out += '\n'; return true;
      case 'r': out += '\r'; return true;
      case 't': out += '\t'; return true;
      case 'u': break;
      default: return false;
    }
    std::uint32_t cp = 0;
    if (!hex4(cp)) return false;
    if (cp >= 0xDC00 && cp <= 0xDFFF) return false;  // a low surrogate first
    if (cp >= 0xD800 && cp <= 0xDBFF) {
      std::uint32_t low = 0;
      if (end_ - p_ < 2 || p_[0] != '\\' || p_[1] != 'u') return false;
      p_ += 2;
      if (!hex4(low) || low < 0xDC00 || low > 0xDFFF) return false;
      cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }
    appendJsonUtf8(out, cp);
    return true;
  }

  bool hex4(std::uint32_t& cp) {
    if (end_ - p_ < 4) return false;
    cp = 0;
    for (int i = 0; i < 4; ++i) {
      int h = jsonHexValue(p_[i]);
      if (h < 0) return false;
      cp = cp * 16 + static_cast<std::uint32_t>(h);
    }
    p_ += 4;
    return true;
  }

  // A multi-byte UTF-8 sequence as RFC 3629 allows it (no overlong forms, no surrogates,
  // nothing past U+10FFFF): the lead byte fixes the range of the first continuation byte.
  bool utf8Sequence(std::string& out) {
    const auto lead = static_cast<unsigned char>(*p_);
    int continuation = 0;
    unsigned char low = 0x80, high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
      continuation = 1;
    } else if (lead == 0xE0) {
      continuation = 2, low = 0xA0;
    } else if ((lead >= 0xE1 && lead <= 0xEC) || lead == 0xEE || lead == 0xEF) {
      continuation = 2;
    } else if (lead == 0xED) {
      continuation = 2, high = 0x9F;
    } else if (lead == 0xF0) {
      continuation = 3, low = 0x90;
    } else if (lead >= 0xF1 && lead <= 0xF3) {
      continuation = 3;
    } else if (lead == 0xF4) {
      continuation = 3, high = 0x8F;
    } else {
      return false;
    }
    if (end_ - p_ <= continuation) return false;
    for (int i = 1; i <= continuation; ++i) {
      const auto b = static_cast<unsigned char>(p_[i]);
      if (b < low || b > high) return false;
      low = 0x80, high = 0xBF;
    }
    out.append(p_, static_cast<std::size_t>(continuation) + 1);
    p_ += continuation + 1;
    return true;
  }

  // JSON's number grammar; typed as nlohmann types it: without a fraction or an exponent a
  // signed (leading '-') or unsigned 64-bit integer, else (or when the integer overflows) a
  // double, correctly rounded as strtod rounds it.
  bool number(JsonPosition at) {
    const char* start = p_;
    const bool negative = *p_ == '-';
    if (negative) ++p_;
    if (p_ == end_) return false;
    if (*p_ == '0') {
      ++p_;
    } else if (*p_ >= '1' && *p_ <= '9') {
      while (p_ < end_ && isJsonDigit(*p_)) ++p_;
    } else {
      return false;
    }
    bool integral = true;
    if (p_ < end_ && *p_ == '.') {
      integral = false;
      ++p_;
      if (p_ == end_ || !isJsonDigit(*p_)) return false;
      while (p_ < end_ && isJsonDigit(*p_)) ++p_;
    }
    if (p_ < end_ && (*p_ == 'e' || *p_ == 'E')) {
      integral = false;
      ++p_;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !isJsonDigit(*p_)) return false;
      while (p_ < end_ && isJsonDigit(*p_)) ++p_;
    }
    JsonScalar s;
    if (integral) {
      if (negative) {
        if (std::from_chars(start, p_, s.integer).ec == std::errc{}) {
          s.type = nlohmann::json::value_t::number_integer;
          handler_.scalar(s, at);
          return true;
        }
      } else if (std::from_chars(start, p_, s.unsignedInteger).ec == std::errc{}) {
        s.type = nlohmann::json::value_t::number_unsigned;
        handler_.scalar(s, at);
        return true;
      }
    }
    auto parsed = std::from_chars(start, p_, s.number);
    if (parsed.ec == std::errc::result_out_of_range) {
      // Beyond double (nlohmann refuses it) or below its smallest normal number, where
      // from_chars gives no value but strtod gives its rounding, which nlohmann takes.
      std::string token(start, p_);
      s.number = std::strtod(token.c_str(), nullptr);
    } else if (parsed.ec != std::errc{}) {
      return false;
    }
    if (!std::isfinite(s.number)) return false;
    s.type = nlohmann::json::value_t::number_float;
    handler_.scalar(s, at);
    return true;
  }

  const char* p_;
  const char* end_;
  const char* lineStart_;
  int line_ = 1;
  JsonEventHandler& handler_;
  std::string text_;  // the string value being read (the handler may move from it)
  std::string key_;   // the member key being read (likewise)
  std::vector<JsonKeySet> keys_;  // by depth: the keys of the object open there
};

}  // namespace

bool readWellFormedJsonEvents(std::string_view text, JsonEventHandler& handler) {
  return WellFormedReader(text, handler).document();
}

}  // namespace wg
