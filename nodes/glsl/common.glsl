// Safe forms of GLSL built-ins, shared by every node. The double references in
// nodes/eval_math.h use the same constants. One name per type (no overloads), so a
// shader carries only the variants it calls.

// Unit vector, or the zero vector when the input is (nearly) zero: never NaN.
float wg_safe_normalize_float(float v) { return v * inversesqrt(max(v * v, 1e-30)); }
vec2 wg_safe_normalize_vec2(vec2 v) { return v * inversesqrt(max(dot(v, v), 1e-30)); }
vec3 wg_safe_normalize_vec3(vec3 v) { return v * inversesqrt(max(dot(v, v), 1e-30)); }
vec4 wg_safe_normalize_vec4(vec4 v) { return v * inversesqrt(max(dot(v, v), 1e-30)); }

// The unit half vector of two safe-normalised vectors l and v (blinn_phong, ggx_specular):
// normalize(l + v). Where they are more than 90 degrees apart, l + v is short and carries
// the rounding of both lengths (|l| and |v| are 1 only within a float32 ulp) magnified
// by 1 / |l + v|: a low sun behind the water seen at grazing turns H by ~1e-6 rad, which a
// smooth lobe makes 1e-3 of its value. For vectors of one length the true l + v is
// perpendicular to d = l - v ((l + v).(l - v) = |l|^2 - |v|^2 = 0), so that component of the
// computed sum is the length rounding and is taken out. Vectors of different lengths (one
// zero, or a short one from a tiny input) keep the plain sum.
vec3 wg_half_vector(vec3 l, vec3 v) {
  vec3 s = l + v;
  vec3 d = l - v;
  float dd = dot(d, d);
  float ll = dot(l, l), vv = dot(v, v);
  bool oneLength = abs(ll - vv) <= 4e-6 * max(ll, vv);  // a few float32 roundings of unit lengths
  vec3 h = dot(s, s) < dd && oneLength ? s - d * (dot(s, d) / dd) : s;
  return wg_safe_normalize_vec3(h);
}

// sin^2 of the angle between two safe-normalised vectors n and h as |n x h|^2, which keeps
// its digits where the angle is small (1 - (n.h)^2 keeps few there); -1 unless both are unit
// (|n|^2 |h|^2 within 4e-6 of 1, a few float32 roundings): a zero vector, or a short one
// from a tiny input, is not, and its callers keep their textbook form for it.
float wg_unit_sin2(vec3 n, vec3 h) {
  vec3 c = cross(n, h);
  return abs(dot(n, n) * dot(h, h) - 1.0) < 4e-6 ? dot(c, c) : -1.0;
}

// pow with the base clamped at 0 (GLSL leaves x < 0, and x = 0 with y <= 0, undefined):
// 0^y is 0 for y > 0 and 1 for y <= 0; the exponent of 2 is capped at 127, as exp2's, so
// a result past float's range is 2^127 = 1.70e38, not +inf (pow(10, 39), pow(0.5, -129)).
// Guarded functions here compute both sides first and choose with ?: between plain values:
// glslang turns that into one OpSelect, where ?: or an early return around an expression
// becomes branches and blocks that spirv-opt does not merge (issue 10: the hand-written
// water is smaller in SPIR-V). The value not chosen may be inf or NaN; it is never used.
float wg_safe_pow_float(float x, float y) {
  float p = exp2(min(y * log2(x), 127.0));
  float edge = y > 0.0 ? 0.0 : 1.0;
  return x > 0.0 ? p : edge;
}
vec2 wg_safe_pow_vec2(vec2 x, vec2 y) { return vec2(wg_safe_pow_float(x.x, y.x), wg_safe_pow_float(x.y, y.y)); }
vec3 wg_safe_pow_vec3(vec3 x, vec3 y) { return vec3(wg_safe_pow_vec2(x.xy, y.xy), wg_safe_pow_float(x.z, y.z)); }
vec4 wg_safe_pow_vec4(vec4 x, vec4 y) { return vec4(wg_safe_pow_vec2(x.xy, y.xy), wg_safe_pow_vec2(x.zw, y.zw)); }

// smoothstep defined for equal edges (a step at the edge) and reversed edges (GLSL leaves
// edge0 >= edge1 undefined).
float wg_smoothstep_float(float e0, float e1, float x) {
  float t = clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  float eased = t * t * (3.0 - 2.0 * t);
  float stepped = x < e0 ? 0.0 : 1.0;
  return e0 == e1 ? stepped : eased;
}
vec2 wg_smoothstep_vec2(vec2 e0, vec2 e1, vec2 x) {
  return vec2(wg_smoothstep_float(e0.x, e1.x, x.x), wg_smoothstep_float(e0.y, e1.y, x.y));
}
vec3 wg_smoothstep_vec3(vec3 e0, vec3 e1, vec3 x) {
  return vec3(wg_smoothstep_vec2(e0.xy, e1.xy, x.xy), wg_smoothstep_float(e0.z, e1.z, x.z));
}
vec4 wg_smoothstep_vec4(vec4 e0, vec4 e1, vec4 x) {
  return vec4(wg_smoothstep_vec2(e0.xy, e1.xy, x.xy), wg_smoothstep_vec2(e0.zw, e1.zw, x.zw));
}

// Native pow where the compiler proved 0 <= x <= 1 and y > 0 for every input the shader
// receives (value facts: e.g. a clamped cosine raised to a parameter with min > 0). GLSL
// defines pow there (only x < 0, and x = 0 with y <= 0, are undefined), the result lies in
// [0, 1] (no overflow to cap) and it equals wg_safe_pow (0^y = 0 for y > 0); one
// instruction instead of the guarded select.
float wg_pow_known_safe_float(float x, float y) { return pow(x, y); }
vec2 wg_pow_known_safe_vec2(vec2 x, vec2 y) { return pow(x, y); }
vec3 wg_pow_known_safe_vec3(vec3 x, vec3 y) { return pow(x, y); }
vec4 wg_pow_known_safe_vec4(vec4 x, vec4 y) { return pow(x, y); }
