// inverse_mix: where x lies between a and b, the inverse of mix.

// (x - a) / (b - a), or 0 for an empty range a == b (the quotient is computed, then not
// chosen: one select, no branch).
float wg_inverse_mix_float(float a, float b, float x) {
  float q = (x - a) / (b - a);
  return b == a ? 0.0 : q;
}
vec2 wg_inverse_mix_vec2(vec2 a, vec2 b, vec2 x) { return mix((x - a) / (b - a), vec2(0.0), equal(a, b)); }
vec3 wg_inverse_mix_vec3(vec3 a, vec3 b, vec3 x) { return mix((x - a) / (b - a), vec3(0.0), equal(a, b)); }
vec4 wg_inverse_mix_vec4(vec4 a, vec4 b, vec4 x) { return mix((x - a) / (b - a), vec4(0.0), equal(a, b)); }
