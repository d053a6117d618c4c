#include "core/view_transform.h"

#include <algorithm>
#include <cmath>

#include "core/color_space.h"

namespace wg {
namespace {

constexpr std::array<std::string_view, 4> kNames = {"none", "aces", "agx", "neutral"};

using Matrix = std::array<Rgb, 3>;  // rows

Rgb multiply(const Matrix& m, const Rgb& v) {
  Rgb out{};
  for (size_t r = 0; r < 3; ++r) out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
  return out;
}

Rgb clamp01(Rgb v) {
  for (double& c : v) c = std::clamp(c, 0.0, 1.0);
  return v;
}

// Hill's fit: linear sRGB -> (RRT + ODT) -> display-linear sRGB.
Rgb aces(const Rgb& c) {
  static constexpr Matrix kInput = {{{0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}}};
  static constexpr Matrix kOutput = {
      {{1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}}};
  Rgb v = multiply(kInput, c);
  for (double& x : v) x = (x * (x + 0.0245786) - 0.000090537) / (x * (0.983729 * x + 0.4329510) + 0.238081);
  return clamp01(multiply(kOutput, v));
}

// AgX base: the inset matrix (rows of the column-major GLSL constant), log2 encoding over
// a fixed EV window, the polynomial sigmoid, the outset matrix, and the 2.2 power that
// makes its display encoding linear again (the sRGB encoding follows).
Rgb agx(const Rgb& c) {
  static constexpr Matrix kInset = {{{0.842479062253094, 0.0784335999999992, 0.0792237451477643},
                                     {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
                                     {0.0423756549057051, 0.0784336, 0.879142973793104}}};
  static constexpr Matrix kOutset = {{{1.19687900512017, -0.0980208811401368, -0.0990297440797205},
                                      {-0.0528968517574562, 1.15190312990417, -0.0989611768448433},
                                      {-0.0529716355144438, -0.0980434501171241, 1.15107367264116}}};
  constexpr double kMinEv = -12.47393, kMaxEv = 4.026069;
  Rgb v = multiply(kInset, c);
  for (double& x : v) {
    // log2 of 0 is -Inf: the floor is far below the window's bottom (2^-12.5 = 1.8e-4).
    x = std::clamp(std::log2(std::max(x, 1e-10)), kMinEv, kMaxEv);
    x = (x - kMinEv) / (kMaxEv - kMinEv);
    const double x2 = x * x, x4 = x2 * x2;
    x = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
  }
  v = multiply(kOutset, v);
  for (double& x : v) x = std::pow(std::clamp(x, 0.0, 1.0), 2.2);
  return v;
}

// Khronos PBR Neutral, as its specification gives it.
Rgb neutral(Rgb c) {
  constexpr double kStart = 0.8 - 0.04, kDesaturation = 0.15;
  const double x = std::min({c[0], c[1], c[2]});
  const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  for (double& v : c) v -= offset;
  const double peak = std::max({c[0], c[1], c[2]});
  if (peak < kStart) return clamp01(c);
  const double d = 1.0 - kStart;
  const double newPeak = 1.0 - d * d / (peak + d - kStart);
  const double g = 1.0 - 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
  for (double& v : c) v = v * (newPeak / peak) * (1.0 - g) + newPeak * g;
  return clamp01(c);
}

}  // namespace

std::span<const std::string_view> toneMapperNames() { return kNames; }

std::string_view toneMapperName(ToneMapper t) { return kNames[static_cast<size_t>(t)]; }

std::optional<ToneMapper> parseToneMapper(std::string_view name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<ToneMapper>(i);
  return std::nullopt;
}

std::string toneMapperList() {
  std::string s;
  for (size_t i = 0; i < kNames.size(); ++i) s += (i == 0 ? "" : i + 1 == kNames.size() ? " or " : ", ") + std::string(kNames[i]);
  return s;
}

double sanitiseRadiance(double v) {
  if (std::isnan(v) || v < 0) return 0.0;
  return std::min(v, kLargestHalf);
}

Rgb toneMap(ToneMapper t, const Rgb& exposed) {
  switch (t) {
    case ToneMapper::None: return clamp01(exposed);
    case ToneMapper::Aces: return aces(exposed);
    case ToneMapper::Agx: return agx(exposed);
    case ToneMapper::Neutral: return neutral(exposed);
  }
  return clamp01(exposed);
}

Rgb outputTransform(const ViewTransform& view, const Rgb& radiance) {
  const double scale = std::exp2(view.exposureEv);
  Rgb exposed{};
  for (size_t i = 0; i < 3; ++i) exposed[i] = sanitiseRadiance(radiance[i]) * scale;
  Rgb display = toneMap(view.toneMapper, exposed);
  for (double& c : display) c = linearToSrgb(c);
  return display;
}

}  // namespace wg
