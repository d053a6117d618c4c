#include "core/frame_size_text.h"

namespace wg {
namespace {

// Reads 1..maxDigits digits from the front of `text`, advancing it; nullopt when there are
// none or too many (the next character is then a digit).
std::optional<int> readDigits(std::string_view& text, int maxDigits) {
  int value = 0, count = 0;
  while (!text.empty() && text.front() >= '0' && text.front() <= '9') {
    if (++count > maxDigits) return std::nullopt;
    value = value * 10 + (text.front() - '0');
    text.remove_prefix(1);
  }
  if (count == 0) return std::nullopt;
  return value;
}

}  // namespace

std::optional<FrameSizeText> parseFrameSizeText(std::string_view text, int maxDigits) {
  auto width = readDigits(text, maxDigits);
  if (!width || text.empty() || text.front() != 'x') return std::nullopt;
  text.remove_prefix(1);
  auto height = readDigits(text, maxDigits);
  if (!height || !text.empty()) return std::nullopt;
  return FrameSizeText{*width, *height};
}

}  // namespace wg
