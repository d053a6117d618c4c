// The rounding vocabulary's guarded form: mod. floor, ceil, roundEven, trunc, fract, step
// and sign are GLSL built-ins, finite for every finite input, and emitted as such.

// GLSL's mod, x - y * floor(x / y), except where the quotient overflows float or is not a
// number (y = 0, or y tiny against x): there it gives 0, the limit of mod(x, y) as y goes
// to 0 (the raw built-in gives NaN: 0 * inf). Both sides are computed, then one chosen.
// The choice tests |x| < 1e38 |y| (|x / y| < 1e38) rather than the quotient itself: a
// driver may fold y to 0 where it is y - y and then x / y and 0 * inf as if both were
// finite, so a test on the inf the division gave does not survive its optimiser. (Not
// |x| 1e-38 < |y|: 1e-38 is below float's smallest normal, and a driver that flushes
// denormals makes it 0.) 1e38 |y| may overflow to inf, where the quotient is small.
float wg_safe_mod_float(float x, float y) {
  float r = x - y * floor(x / y);
  return abs(x) < 1e38 * abs(y) ? r : 0.0;
}
vec2 wg_safe_mod_vec2(vec2 x, vec2 y) {
  return mix(vec2(0.0), x - y * floor(x / y), lessThan(abs(x), 1e38 * abs(y)));
}
vec3 wg_safe_mod_vec3(vec3 x, vec3 y) {
  return mix(vec3(0.0), x - y * floor(x / y), lessThan(abs(x), 1e38 * abs(y)));
}
vec4 wg_safe_mod_vec4(vec4 x, vec4 y) {
  return mix(vec4(0.0), x - y * floor(x / y), lessThan(abs(x), 1e38 * abs(y)));
}
