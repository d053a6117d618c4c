// A normal from a height texture by central differences (seed 001's wave normals).

// The height gradient d h / d(u, v) in texture units: central differences `e` apart
// (e floored at 1e-6), red channel.
vec2 wg_normal_from_height_gradient(sampler2D tex, vec2 uv, float e) {
  float d = max(e, 1e-6);
  float hx = texture(tex, uv + vec2(d, 0.0)).x - texture(tex, uv - vec2(d, 0.0)).x;
  float hy = texture(tex, uv + vec2(0.0, d)).x - texture(tex, uv - vec2(0.0, d)).x;
  return vec2(hx, hy) * (0.5 / d);
}
