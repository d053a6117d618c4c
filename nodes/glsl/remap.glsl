// Range remapping, one name per type. An empty source range (in_min == in_max) maps to out_min instead of
// dividing by zero (the quotient is computed, then not chosen: one OpSelect, no branch).
float wg_remap_float(float x, float a, float b, float c, float d) {
  float q = (x - a) / (b - a);
  float t = b == a ? 0.0 : q;
  return mix(c, d, t);
}
vec2 wg_remap_vec2(vec2 x, vec2 a, vec2 b, vec2 c, vec2 d) {
  return vec2(wg_remap_float(x.x, a.x, b.x, c.x, d.x), wg_remap_float(x.y, a.y, b.y, c.y, d.y));
}
vec3 wg_remap_vec3(vec3 x, vec3 a, vec3 b, vec3 c, vec3 d) {
  return vec3(wg_remap_vec2(x.xy, a.xy, b.xy, c.xy, d.xy), wg_remap_float(x.z, a.z, b.z, c.z, d.z));
}
vec4 wg_remap_vec4(vec4 x, vec4 a, vec4 b, vec4 c, vec4 d) {
  return vec4(wg_remap_vec2(x.xy, a.xy, b.xy, c.xy, d.xy), wg_remap_vec2(x.zw, a.zw, b.zw, c.zw, d.zw));
}

float wg_remap_clamped_float(float x, float a, float b, float c, float d) {
  float q = clamp((x - a) / (b - a), 0.0, 1.0);
  float t = b == a ? 0.0 : q;
  return mix(c, d, t);
}
vec2 wg_remap_clamped_vec2(vec2 x, vec2 a, vec2 b, vec2 c, vec2 d) {
  return vec2(wg_remap_clamped_float(x.x, a.x, b.x, c.x, d.x), wg_remap_clamped_float(x.y, a.y, b.y, c.y, d.y));
}
vec3 wg_remap_clamped_vec3(vec3 x, vec3 a, vec3 b, vec3 c, vec3 d) {
  return vec3(wg_remap_clamped_vec2(x.xy, a.xy, b.xy, c.xy, d.xy), wg_remap_clamped_float(x.z, a.z, b.z, c.z, d.z));
}
vec4 wg_remap_clamped_vec4(vec4 x, vec4 a, vec4 b, vec4 c, vec4 d) {
  return vec4(wg_remap_clamped_vec2(x.xy, a.xy, b.xy, c.xy, d.xy), wg_remap_clamped_vec2(x.zw, a.zw, b.zw, c.zw, d.zw));
}

// The same where the compiler proved in_min != in_max for every input the shader receives
// (value facts: disjoint ranges of a and b, e.g. a = 0 and a parameter b with min 0.01):
// the empty-range select is dead, so it is left out. Same values as the guarded forms.
float wg_remap_nonempty_float(float x, float a, float b, float c, float d) { return mix(c, d, (x - a) / (b - a)); }
vec2 wg_remap_nonempty_vec2(vec2 x, vec2 a, vec2 b, vec2 c, vec2 d) { return mix(c, d, (x - a) / (b - a)); }
vec3 wg_remap_nonempty_vec3(vec3 x, vec3 a, vec3 b, vec3 c, vec3 d) { return mix(c, d, (x - a) / (b - a)); }
vec4 wg_remap_nonempty_vec4(vec4 x, vec4 a, vec4 b, vec4 c, vec4 d) { return mix(c, d, (x - a) / (b - a)); }
float wg_remap_clamped_nonempty_float(float x, float a, float b, float c, float d) {
  return mix(c, d, clamp((x - a) / (b - a), 0.0, 1.0));
}
vec2 wg_remap_clamped_nonempty_vec2(vec2 x, vec2 a, vec2 b, vec2 c, vec2 d) {
  return mix(c, d, clamp((x - a) / (b - a), 0.0, 1.0));
}
vec3 wg_remap_clamped_nonempty_vec3(vec3 x, vec3 a, vec3 b, vec3 c, vec3 d) {
  return mix(c, d, clamp((x - a) / (b - a), 0.0, 1.0));
}
vec4 wg_remap_clamped_nonempty_vec4(vec4 x, vec4 a, vec4 b, vec4 c, vec4 d) {
  return mix(c, d, clamp((x - a) / (b - a), 0.0, 1.0));
}
