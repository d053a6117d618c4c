// subsurface: the fake subsurface glow of wave crests lit from behind (seed 003, section 8).

// H = normalize(L + N distortion); I = saturate(V.(-H))^power * saturate(height * 2 + 0.5).
// All vectors normalised safely; the safe pow keeps 0^power at 0 (power > 0) and the
// result finite for any power.
float wg_subsurface_intensity(vec3 n, vec3 v, vec3 l, float distortion, float power, float height) {
  vec3 h = wg_safe_normalize_vec3(wg_safe_normalize_vec3(l) + wg_safe_normalize_vec3(n) * distortion);
  float vdoth = clamp(dot(wg_safe_normalize_vec3(v), -h), 0.0, 1.0);
  return wg_safe_pow_float(vdoth, power) * clamp(height * 2.0 + 0.5, 0.0, 1.0);
}
