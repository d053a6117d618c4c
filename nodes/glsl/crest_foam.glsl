// Crest foam (the top-down water plan's calculateFoam): whitecaps where the wave is high or steep, broken
// into patches by two layers of drifting value noise.

// height: the wave height (the top-down water plan's 0..1 raw height); normal: the surface normal (y up,
// so the slope is the length of its xz part once normalised); drift: the two noise time
// offsets, already wrapped to the noise lattice's 256-cell period by the caller so the
// patches drift seamlessly at any time. The product is clamped to [0, 1] before the
// sharpness power (pow never sees a negative base), and sharpness is floored at 1e-3.
float wg_crest_foam(float height, vec3 normal, vec2 xz, vec2 drift, float threshold, float intensity,
                    float coverage, float sharpness) {
  float heightFoam = wg_smoothstep_float(threshold, threshold + 0.15, height);
  vec3 n = wg_safe_normalize_vec3(normal);
  float slopeFoam = wg_smoothstep_float(0.3, 0.7, length(n.xz));
  float base = max(heightFoam, slopeFoam * 0.4);
  float nz = (wg_value_noise_tiled_vec2(xz * 0.12 + drift.x, 255u) +
                 0.5 * wg_value_noise_tiled_vec2(xz * 0.25 - drift.y, 255u)) / 1.5;
  float t = 1.0 - coverage;
  float mask = wg_smoothstep_float(t - 0.1, t + 0.1, nz);
  return wg_safe_pow_float(clamp(base * mask * intensity, 0.0, 1.0), 1.0 / max(sharpness, 1e-3));
}
