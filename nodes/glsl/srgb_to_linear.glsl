// The sRGB transfer function (IEC 61966-2-1) decoding an sRGB-encoded component to linear:
// c / 12.92 up to the knee 0.04045, ((c + 0.055) / 1.055)^2.4 above it. Extended: a negative
// c mirrors the curve (-f(-c)), c > 1 continues the power segment (an HDR colour), capped at
// 2^127 by the guarded pow (the base is >= 0.052, never negative). For c <= 1 the power is
// held at 1, so [0, 1] maps into [0, 1] even where float rounds (c + 0.055) / 1.055 up.
float wg_srgb_to_linear_float(float c) {
  float a = abs(c);
  float p = wg_safe_pow_float((a + 0.055) / 1.055, 2.4);
  float curve = a <= 0.04045 ? a / 12.92 : (a <= 1.0 ? min(p, 1.0) : p);
  return c < 0.0 ? -curve : curve;
}
vec2 wg_srgb_to_linear_vec2(vec2 c) { return vec2(wg_srgb_to_linear_float(c.x), wg_srgb_to_linear_float(c.y)); }
vec3 wg_srgb_to_linear_vec3(vec3 c) { return vec3(wg_srgb_to_linear_vec2(c.xy), wg_srgb_to_linear_float(c.z)); }
// Alpha is not a colour: it passes through unchanged.
vec4 wg_srgb_to_linear_vec4(vec4 c) { return vec4(wg_srgb_to_linear_vec3(c.rgb), c.a); }
