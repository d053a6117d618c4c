// Fractal Brownian motion: octaves of value noise, each at lacunarity times the previous
// frequency and gain times the previous amplitude, normalised by the sum of amplitudes so
// the result stays in [0, 1). Gain is clamped to [0, 4] and lacunarity to [0, 8] so the
// amplitudes and frequencies of 8 octaves stay finite; each octave is shifted by a
// non-integer offset so the lattices of the octaves do not line up at the origin.
float wg_fbm_vec2(vec2 p, int octaves, float lacunarity, float gain) {
  float lac = clamp(lacunarity, 0.0, 8.0);
  float g = clamp(gain, 0.0, 4.0);
  float sum = 0.0;
  float norm = 0.0;
  float amp = 1.0;
  vec2 q = p;
  for (int i = 0; i < 8; ++i) {
    if (i >= octaves) break;
    sum += amp * wg_value_noise_vec2(q + float(i) * vec2(17.31, 9.73));
    norm += amp;
    amp *= g;
    q *= lac;
  }
  return sum / norm;
}
float wg_fbm_vec3(vec3 p, int octaves, float lacunarity, float gain) {
  float lac = clamp(lacunarity, 0.0, 8.0);
  float g = clamp(gain, 0.0, 4.0);
  float sum = 0.0;
  float norm = 0.0;
  float amp = 1.0;
  vec3 q = p;
  for (int i = 0; i < 8; ++i) {
    if (i >= octaves) break;
    sum += amp * wg_value_noise_vec3(q + float(i) * vec3(17.31, 9.73, 5.47));
    norm += amp;
    amp *= g;
    q *= lac;
  }
  return sum / norm;
}
