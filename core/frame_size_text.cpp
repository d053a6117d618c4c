#include "core/frame_size_text.h"

namespace wg {
namespace {

// Reads the digits at the front of `text`, advancing it; nullopt when there are none or
// their value passes `max` (read no further: no overflow however many digits follow).
std::optional<int> readSide(std::string_view& text, int max) {
  long long value = 0;
  bool any = false;
  while (!text.empty() && text.front() >= '0' && text.front() <= '9') {
    value = value * 10 + (text.front() - '0');
    if (value > max) return std::nullopt;
    any = true;
    text.remove_prefix(1);
  }
  if (!any) return std::nullopt;
  return static_cast<int>(value);
}

}  // namespace

std::optional<FrameSizeText> parseFrameSizeText(std::string_view text, int minSide, int maxSide) {
  auto width = readSide(text, maxSide);
  if (!width || *width < minSide || text.empty() || text.front() != 'x') return std::nullopt;
  text.remove_prefix(1);
  auto height = readSide(text, maxSide);
  if (!height || *height < minSide || !text.empty()) return std::nullopt;
  return FrameSizeText{*width, *height};
}

}  // namespace wg
