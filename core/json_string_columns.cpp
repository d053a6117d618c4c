#include "core/json_string_columns.h"

namespace wg {
namespace {

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The code unit of the \u escape (four hex digits) at `raw` (which starts with the backslash); -1 if
// it is not one.
long unicodeEscape(std::string_view raw) {
  if (raw.size() < 6 || raw[0] != '\\' || raw[1] != 'u') return -1;
  long v = 0;
  for (std::size_t i = 2; i < 6; ++i) {
    int d = hexDigit(raw[i]);
    if (d < 0) return -1;
    v = v * 16 + d;
  }
  return v;
}

// Bytes of UTF-8 for code point cp.
std::size_t utf8Length(long cp) { return cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4; }

}  // namespace

int jsonStringByteColumn(std::string_view line, int quoteColumn, std::size_t decoded) {
  if (quoteColumn < 1 || static_cast<std::size_t>(quoteColumn) > line.size()) return static_cast<int>(line.size()) + 1;
  std::size_t at = static_cast<std::size_t>(quoteColumn);  // 0-based index of the first byte after the quote
  std::size_t produced = 0;                                // decoded bytes before `at`
  while (at < line.size() && line[at] != '"') {
    std::size_t rawLength = 1, decodedLength = 1;
    if (line[at] == '\\' && at + 1 < line.size()) {
      rawLength = 2;
      long unit = unicodeEscape(line.substr(at));
      if (unit >= 0) {
        rawLength = 6;
        long low = unicodeEscape(line.substr(at + 6));
        if (unit >= 0xD800 && unit <= 0xDBFF && low >= 0xDC00 && low <= 0xDFFF) {
          rawLength = 12;  // a surrogate pair: one code point beyond the basic plane
          decodedLength = 4;
        } else {
          decodedLength = utf8Length(unit);
        }
      }
    }
    if (decoded < produced + decodedLength) return static_cast<int>(at) + 1;
    produced += decodedLength;
    at += rawLength;
  }
  return static_cast<int>(at) + 1;  // the closing quote (or the line's end)
}

}  // namespace wg
