// subsurface: the fake subsurface glow of wave crests lit from behind (the stylized water shader, section 8).

// H = normalize(L + N distortion); I = saturate(V.(-H))^power * saturate(height * 2 + 0.5).
// All vectors normalised safely; the safe pow keeps 0^power at 0 (power > 0) and the
// result finite for any power.
float wg_subsurface_intensity(vec3 n, vec3 v, vec3 l, float distortion, float power, float height) {
  vec3 h = wg_safe_normalize_vec3(wg_safe_normalize_vec3(l) + wg_safe_normalize_vec3(n) * distortion);
  float vdoth = clamp(dot(wg_safe_normalize_vec3(v), -h), 0.0, 1.0);
  return wg_safe_pow_float(vdoth, power) * clamp(height * 2.0 + 0.5, 0.0, 1.0);
}

// The same where n, v and l are proven normalized (value facts: unit length or exactly
// zero, so safe re-normalisation leaves them unchanged) and power > 0 (so vdoth in [0, 1]
// makes native pow defined and equal to the safe one). Same values.
float wg_subsurface_intensity_unit(vec3 n, vec3 v, vec3 l, float distortion, float power, float height) {
  vec3 h = wg_safe_normalize_vec3(l + n * distortion);
  float vdoth = clamp(dot(v, -h), 0.0, 1.0);
  return pow(vdoth, power) * clamp(height * 2.0 + 0.5, 0.0, 1.0);
}
