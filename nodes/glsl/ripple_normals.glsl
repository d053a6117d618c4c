// The top-down water plan's high-frequency ripples: sin-based analytic noise, three layers of two sines
// each at high, incommensurate frequencies, added to the normal's horizontal components.

// One layer: (sin(dot(fa, uv) + phase.x), sin(dot(fb, uv) + phase.y)) with freq = (fa, fb);
// the spatial part is wrapped to [0, 2 pi) before the time phase is added.
vec2 wg_ripple_normals_layer(vec2 uv, vec4 freq, vec2 phase) {
  return vec2(sin(mod(dot(freq.xy, uv), 6.283185307179586) + phase.x),
              sin(mod(dot(freq.zw, uv), 6.283185307179586) + phase.y));
}
