#pragma once
// The output transform: how the linear, scene-referred radiance a frame holds becomes the
// display values written to an 8-bit image. Applied once, last, by every runtime and client:
//   1. sanitise: NaN and negative values become 0, +Inf (and anything larger) 65504, the
//      largest half float, so every input gives a finite output;
//   2. exposure: multiply by 2^EV;
//   3. tone mapper, giving display-linear values in [0, 1]:
//        none     clamp to [0, 1]
//        aces     Stephen Hill's fit of the ACES RRT + sRGB ODT (sRGB -> AP1-like input
//                 matrix, the rational fit (v (v + 0.0245786) - 0.000090537) /
//                 (v (0.983729 v + 0.4329510) + 0.238081), output matrix), no pre-exposure
//        agx      Troy Sobotka's AgX base look: inset matrix, log2 encoding over
//                 [-12.47393, 4.026069] EV, the 6th-order polynomial fit of its sigmoid by
//                 Benjamin Wrensch, outset matrix, then the 2.2 power back to linear
//        neutral  Khronos PBR Neutral (compression starts at 0.76, desaturation 0.15)
//   4. the sRGB transfer function (IEC 61966-2-1, core/color_space.h).
// These double functions are the reference the GPU pass (runtime/output_transform.h) and
// the three.js client are measured against.
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace wg {

enum class ToneMapper { None, Aces, Agx, Neutral };

// "none", "aces", "agx", "neutral", in enumerator order.
std::span<const std::string_view> toneMapperNames();
std::string_view toneMapperName(ToneMapper t);
std::optional<ToneMapper> parseToneMapper(std::string_view name);

// Exposure is in EV (stops): values are multiplied by 2^EV. The range keeps 2^EV times the
// largest half float finite in float32 and covers night to noon sun.
inline constexpr double kMinExposureEv = -20.0, kMaxExposureEv = 20.0;
// The largest finite half float: what +Inf becomes before the exposure.
inline constexpr double kLargestHalf = 65504.0;

struct ViewTransform {
  ToneMapper toneMapper = ToneMapper::None;
  double exposureEv = 0.0;
  bool operator==(const ViewTransform&) const = default;
};

// "none, aces, agx or neutral" (for messages and help).
std::string toneMapperList();

using Rgb = std::array<double, 3>;

// Step 1: NaN and negatives to 0, above kLargestHalf (+Inf included) to kLargestHalf.
double sanitiseRadiance(double v);
// Step 3 alone: exposed scene-linear -> display-linear in [0, 1].
Rgb toneMap(ToneMapper t, const Rgb& exposed);
// Steps 1-4: scene-linear radiance -> sRGB-encoded display values in [0, 1].
Rgb outputTransform(const ViewTransform& view, const Rgb& radiance);

}  // namespace wg
