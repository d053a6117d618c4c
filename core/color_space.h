#pragma once
// The sRGB transfer functions (IEC 61966-2-1), in double: the piecewise curve, not a 2.2
// power. One definition for everything that decodes or encodes sRGB on the CPU: the
// reference sampling of sRGB textures (nodes/texture_sampling.h), the srgb_to_linear
// node's reference, colour parameters and literals linearised by resolve
// (core/color_parameters.h), and the output transform's last step (core/view_transform.h).
#include "core/value.h"

namespace wg {

// An sRGB-encoded component c decoded to linear: c / 12.92 for c <= 0.04045, else
// ((c + 0.055) / 1.055)^2.4, as GL states it for sRGB textures. Extended as scRGB-style
// pipelines do: a negative c mirrors the curve (-f(-c)) and c > 1 continues the power
// segment (an HDR colour), capped at 2^127 as the GLSL's guarded pow is. [0, 1] maps into
// [0, 1] exactly: f(1) = 1, never an ulp above.
double srgbToLinear(double c);

// A colour value decoded component by component; a vec4's alpha (w) is linear already and
// passes through unchanged.
Value srgbToLinear(const Value& c);

// Linear -> sRGB-encoded, for l in [0, 1]: 12.92 l up to 0.0031308, else 1.055 l^(1/2.4) - 0.055.
double linearToSrgb(double l);

}  // namespace wg
