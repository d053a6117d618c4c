// The classic WebGL water renderer's du/dv distortion: a scrolling du/dv map turned into a small UV offset that
// ripples the refraction and reflection lookups.

// The scroll: fract(time * speed), wrapped because the texture repeats (finite and exact
// in period at t = 524288 s).
float wg_dudv_distortion_move(float time, float speed) { return fract(time * speed); }

// (dudv(uv * tiling + (move, 0)).rg * 2 - 1) * strength.
vec2 wg_dudv_distortion_offset(sampler2D dudv, vec2 uv, float tiling, float move, float strength) {
  return (texture(dudv, uv * tiling + vec2(move, 0.0)).xy * 2.0 - 1.0) * strength;
}
