// The classic WebGL water renderer's du/dv distortion: a scrolling du/dv map turned into a small UV offset that
// ripples the refraction and reflection lookups.

// (dudv(uv * tiling + (move, 0)).rg * 2 - 1) * strength. The scroll move = fract(time *
// speed), wrapped because the texture repeats, is computed once per draw by ops of its own
// (the node's derived input `scroll`).
vec2 wg_dudv_distortion_offset(sampler2D dudv, vec2 uv, float tiling, float move, float strength) {
  return (texture(dudv, uv * tiling + vec2(move, 0.0)).xy * 2.0 - 1.0) * strength;
}
