#include "core/json_text_writer.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace wg {
namespace {

// Bytes nlohmann writes as they are: printable ASCII other than '"' and '\'. Anything
// else (escapes, UTF-8 sequences, which it validates) goes through nlohmann itself, so
// the two can never disagree.
// A table: the manifest of a large graph quotes tens of thousands of ids, and four tests
// per byte were most of its writing.
struct JsonVerbatimBytes {
  bool verbatim[256] = {};
  constexpr JsonVerbatimBytes() {
    for (int c = 0x20; c < 0x80; ++c) verbatim[c] = c != '"' && c != '\\';
  }
};
constexpr JsonVerbatimBytes kJsonVerbatimBytes;

bool writtenVerbatim(std::string_view s) {
  for (unsigned char c : s)
    if (!kJsonVerbatimBytes.verbatim[c]) return false;
  return true;
}

}  // namespace

void JsonTextWriter::newLine(size_t depth) {
  out_ += '\n';
  out_.append(2 * depth, ' ');
}

void JsonTextWriter::beforeValue() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (levels_.empty()) return;
  Level& level = levels_.back();
  if (level.object) throw std::logic_error("JsonTextWriter: a value in an object needs a key");
  if (!level.empty) out_ += ',';
  level.empty = false;
  newLine(levels_.size());
}

void JsonTextWriter::key(std::string_view k) {
  if (levels_.empty() || !levels_.back().object || afterKey_)
    throw std::logic_error("JsonTextWriter: a key outside an object");
  Level& level = levels_.back();
  if (!level.empty && !(level.lastKey < k))
    throw std::logic_error("JsonTextWriter: key '" + std::string(k) + "' after '" + std::string(level.lastKey) +
                           "' (keys go in byte order)");
  if (!level.empty) out_ += ',';
  level.empty = false;
  level.lastKey = k;
  newLine(levels_.size());
  quoted(k);
  out_ += ": ";
  afterKey_ = true;
}

void JsonTextWriter::open(char bracket, bool object) {
  beforeValue();
  out_ += bracket;
  levels_.push_back({object, true, {}});
}

void JsonTextWriter::close(char bracket) {
  bool empty = levels_.back().empty;
  levels_.pop_back();
  if (!empty) newLine(levels_.size());
  out_ += bracket;
}

void JsonTextWriter::beginObject() { open('{', true); }
void JsonTextWriter::beginArray() { open('[', false); }
void JsonTextWriter::endObject() { close('}'); }
void JsonTextWriter::endArray() { close(']'); }

void JsonTextWriter::quoted(std::string_view s) {
  if (writtenVerbatim(s)) {
    // One growth check and two copies rather than three appends.
    const std::size_t at = out_.size();
    out_.resize(at + s.size() + 2);
    char* p = out_.data() + at;
    p[0] = '"';
    s.copy(p + 1, s.size());
    p[s.size() + 1] = '"';
  } else {
    out_ += nlohmann::json(std::string(s)).dump();
  }
}

void JsonTextWriter::string(std::string_view s) {
  beforeValue();
  quoted(s);
}

void JsonTextWriter::number(double d) {
  beforeValue();
  out_ += nlohmann::json(d).dump();
}

void JsonTextWriter::integer(long long i) {
  beforeValue();
  out_ += std::to_string(i);
}

void JsonTextWriter::boolean(bool b) {
  beforeValue();
  out_ += b ? "true" : "false";
}

void JsonTextWriter::null() {
  beforeValue();
  out_ += "null";
}

void JsonTextWriter::value(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object:
      beginObject();
      for (auto it = j.begin(); it != j.end(); ++it) {  // a std::map: keys in byte order
        key(it.key());
        value(it.value());
      }
      endObject();
      return;
    case nlohmann::json::value_t::array:
      beginArray();
      for (const auto& v : j) value(v);
      endArray();
      return;
    case nlohmann::json::value_t::string: return string(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean: return boolean(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return integer(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned: return integer(static_cast<long long>(j.get<unsigned long long>()));
    case nlohmann::json::value_t::number_float: return number(j.get<double>());
    default: return null();
  }
}

}  // namespace wg
