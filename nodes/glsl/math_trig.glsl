// The trigonometric vocabulary's guarded forms. Each equals the GLSL built-in wherever
// that is defined and finite; emitters call the raw built-in where value facts prove the
// guard dead.

// tan as sin / cos with |cos| floored at 1e-30 (its sign kept): a GPU whose cos rounds to
// 0 near an odd multiple of pi/2 gives at most 1e30 in magnitude instead of inf.
float wg_safe_tan_float(float x) {
  float c = cos(x);
  return sin(x) / (c < 0.0 ? min(c, -1e-30) : max(c, 1e-30));
}
vec2 wg_safe_tan_vec2(vec2 x) {
  vec2 c = cos(x);
  return sin(x) / mix(max(c, 1e-30), min(c, -1e-30), lessThan(c, vec2(0.0)));
}
vec3 wg_safe_tan_vec3(vec3 x) {
  vec3 c = cos(x);
  return sin(x) / mix(max(c, 1e-30), min(c, -1e-30), lessThan(c, vec3(0.0)));
}
vec4 wg_safe_tan_vec4(vec4 x) {
  vec4 c = cos(x);
  return sin(x) / mix(max(c, 1e-30), min(c, -1e-30), lessThan(c, vec4(0.0)));
}

// asin and acos with x clamped to [-1, 1] (GLSL leaves |x| > 1 undefined: NaN): a unit
// vector's component rounded to 1.0000001 gives asin = pi/2, acos = 0.
float wg_safe_asin_float(float x) { return asin(clamp(x, -1.0, 1.0)); }
vec2 wg_safe_asin_vec2(vec2 x) { return asin(clamp(x, -1.0, 1.0)); }
vec3 wg_safe_asin_vec3(vec3 x) { return asin(clamp(x, -1.0, 1.0)); }
vec4 wg_safe_asin_vec4(vec4 x) { return asin(clamp(x, -1.0, 1.0)); }
float wg_safe_acos_float(float x) { return acos(clamp(x, -1.0, 1.0)); }
vec2 wg_safe_acos_vec2(vec2 x) { return acos(clamp(x, -1.0, 1.0)); }
vec3 wg_safe_acos_vec3(vec3 x) { return acos(clamp(x, -1.0, 1.0)); }
vec4 wg_safe_acos_vec4(vec4 x) { return acos(clamp(x, -1.0, 1.0)); }

// atan(y, x) with the origin (GLSL: undefined) at angle 0. |x| + |y| is 0 exactly when
// both are (GLSL has no component-wise 'and' of two bvecs).
float wg_safe_atan2_float(float y, float x) {
  // The angle of |y|, then y's sign: a zero y of either sign (-0.0 comes out of -a or a * b
  // with a = 0) gives +pi on the negative x axis, where atan(-0.0, -1) is -pi.
  float a = atan(abs(y), x);
  float withSign = y < 0.0 ? -a : a;
  return abs(x) + abs(y) == 0.0 ? 0.0 : withSign;
}
vec2 wg_safe_atan2_vec2(vec2 y, vec2 x) { return vec2(wg_safe_atan2_float(y.x, x.x), wg_safe_atan2_float(y.y, x.y)); }
vec3 wg_safe_atan2_vec3(vec3 y, vec3 x) { return vec3(wg_safe_atan2_vec2(y.xy, x.xy), wg_safe_atan2_float(y.z, x.z)); }
vec4 wg_safe_atan2_vec4(vec4 y, vec4 x) { return vec4(wg_safe_atan2_vec2(y.xy, x.xy), wg_safe_atan2_vec2(y.zw, x.zw)); }

// sinh and cosh with x clamped to [-88, 88]: GLSL defines them through e^x, which
// overflows float past 88.7 (inf, and inf - inf = NaN for sinh on some drivers); at 88
// they are +-8.26e37 and 8.26e37.
float wg_safe_sinh_float(float x) { return sinh(clamp(x, -88.0, 88.0)); }
vec2 wg_safe_sinh_vec2(vec2 x) { return sinh(clamp(x, -88.0, 88.0)); }
vec3 wg_safe_sinh_vec3(vec3 x) { return sinh(clamp(x, -88.0, 88.0)); }
vec4 wg_safe_sinh_vec4(vec4 x) { return sinh(clamp(x, -88.0, 88.0)); }
float wg_safe_cosh_float(float x) { return cosh(clamp(x, -88.0, 88.0)); }
vec2 wg_safe_cosh_vec2(vec2 x) { return cosh(clamp(x, -88.0, 88.0)); }
vec3 wg_safe_cosh_vec3(vec3 x) { return cosh(clamp(x, -88.0, 88.0)); }
vec4 wg_safe_cosh_vec4(vec4 x) { return cosh(clamp(x, -88.0, 88.0)); }

// tanh with x clamped to [-10, 10]: a driver forming (e^x - e^-x) / (e^x + e^-x) gets
// inf / inf = NaN for large x; tanh(10) = 1 - 4e-9 is 1 in float.
float wg_safe_tanh_float(float x) { return tanh(clamp(x, -10.0, 10.0)); }
vec2 wg_safe_tanh_vec2(vec2 x) { return tanh(clamp(x, -10.0, 10.0)); }
vec3 wg_safe_tanh_vec3(vec3 x) { return tanh(clamp(x, -10.0, 10.0)); }
vec4 wg_safe_tanh_vec4(vec4 x) { return tanh(clamp(x, -10.0, 10.0)); }
