// The rounding vocabulary's guarded form: mod. floor, ceil, roundEven, trunc, fract, step
// and sign are GLSL built-ins, finite for every finite input, and emitted as such.

// GLSL's mod, x - y * floor(x / y), except where the quotient overflows float or is not a
// number (y = 0, or y tiny against x): there it gives 0, the limit of mod(x, y) as y goes
// to 0 (the raw built-in gives NaN: 0 * inf). Both sides are computed, then one chosen.
float wg_safe_mod_float(float x, float y) {
  float q = x / y;
  float r = x - y * floor(q);
  return abs(q) <= 1e38 ? r : 0.0;
}
vec2 wg_safe_mod_vec2(vec2 x, vec2 y) {
  vec2 q = x / y;
  return mix(vec2(0.0), x - y * floor(q), lessThanEqual(abs(q), vec2(1e38)));
}
vec3 wg_safe_mod_vec3(vec3 x, vec3 y) {
  vec3 q = x / y;
  return mix(vec3(0.0), x - y * floor(q), lessThanEqual(abs(q), vec3(1e38)));
}
vec4 wg_safe_mod_vec4(vec4 x, vec4 y) {
  vec4 q = x / y;
  return mix(vec4(0.0), x - y * floor(q), lessThanEqual(abs(q), vec4(1e38)));
}
