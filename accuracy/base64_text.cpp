#include "accuracy/base64_text.h"

namespace wg::accuracy {
namespace {

constexpr char kBase64Digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int base64DigitValue(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

std::string base64Text(const void* data, size_t size) {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    std::uint32_t v = std::uint32_t(bytes[i]) << 16;
    if (i + 1 < size) v |= std::uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < size) v |= bytes[i + 2];
    out += kBase64Digits[(v >> 18) & 63];
    out += kBase64Digits[(v >> 12) & 63];
    out += i + 1 < size ? kBase64Digits[(v >> 6) & 63] : '=';
    out += i + 2 < size ? kBase64Digits[v & 63] : '=';
  }
  return out;
}

std::optional<std::vector<std::uint8_t>> bytesOfBase64Text(const std::string& text) {
  if (text.size() % 4 != 0) return std::nullopt;
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  for (size_t i = 0; i < text.size(); i += 4) {
    int d[4];
    int padding = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = text[i + static_cast<size_t>(k)];
      // '=' only at the end of the last group, and only in its last two places.
      if (c == '=' && i + 4 == text.size() && k >= 2) {
        d[k] = 0;
        ++padding;
        continue;
      }
      if (padding > 0) return std::nullopt;
      d[k] = base64DigitValue(c);
      if (d[k] < 0) return std::nullopt;
    }
    const std::uint32_t v = std::uint32_t(d[0]) << 18 | std::uint32_t(d[1]) << 12 | std::uint32_t(d[2]) << 6 | std::uint32_t(d[3]);
    out.push_back(static_cast<std::uint8_t>(v >> 16));
    if (padding < 2) out.push_back(static_cast<std::uint8_t>(v >> 8));
    if (padding < 1) out.push_back(static_cast<std::uint8_t>(v));
  }
  return out;
}

}  // namespace wg::accuracy
