#pragma once
// The sRGB transfer functions (IEC 61966-2-1), in double: the piecewise curve, not a 2.2
// power. One definition for everything that decodes or encodes sRGB on the CPU: the
// reference sampling of sRGB textures, colour parameters authored in sRGB, and the output
// transform's last step (core/view_transform.h).
namespace wg {

// sRGB-encoded value -> linear. c <= 0.04045: c / 12.92; else ((c + 0.055) / 1.055)^2.4.
// Values above 1 continue the power segment (extended sRGB).
double srgbDecode(double encoded);

// Linear -> sRGB-encoded. l <= 0.0031308: 12.92 l; else 1.055 l^(1/2.4) - 0.055.
double srgbEncode(double linear);

}  // namespace wg
