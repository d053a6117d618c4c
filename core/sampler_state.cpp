#include "core/sampler_state.h"

#include <array>

namespace wg {
namespace {

constexpr std::array<std::string_view, 3> kWrapNames = {"repeat", "clamp", "mirror"};
constexpr std::array<std::string_view, 3> kFilterNames = {"nearest", "linear", "mipmapped"};
constexpr std::array<std::string_view, 2> kColorSpaceNames = {"linear", "srgb"};

template <class E, size_t N>
std::optional<E> parseName(const std::array<std::string_view, N>& names, std::string_view name) {
  for (size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<E>(i);
  return std::nullopt;
}

}  // namespace

std::string_view wrapName(TextureWrap w) { return kWrapNames.at(static_cast<size_t>(w)); }
std::string_view filterName(TextureFilter f) { return kFilterNames.at(static_cast<size_t>(f)); }
std::string_view colorSpaceName(TextureColorSpace c) { return kColorSpaceNames.at(static_cast<size_t>(c)); }
std::optional<TextureWrap> parseWrap(std::string_view name) { return parseName<TextureWrap>(kWrapNames, name); }
std::optional<TextureFilter> parseFilter(std::string_view name) { return parseName<TextureFilter>(kFilterNames, name); }
std::optional<TextureColorSpace> parseColorSpace(std::string_view name) {
  return parseName<TextureColorSpace>(kColorSpaceNames, name);
}

}  // namespace wg
