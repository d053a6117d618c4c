#pragma once
// "WIDTHxHEIGHT" as every command and the editor take a frame size (--size 1280x720).
// A hand-written reader rather than std::regex: <regex> cost minutes of compile time per
// translation unit under the sanitizers, for five one-line patterns.
#include <optional>
#include <string_view>

namespace wg {

struct FrameSizeText {
  int width = 0;
  int height = 0;
};

// The two numbers of `text` when it is exactly decimal digits, 'x', decimal digits (no sign,
// space or other character) and each lies in [minSide, maxSide]; nullopt otherwise.
std::optional<FrameSizeText> parseFrameSizeText(std::string_view text, int minSide, int maxSide);

}  // namespace wg
