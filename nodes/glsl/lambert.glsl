// lambert: diffuse lighting by Lambert's cosine law (the advanced shaders tutorial, level 1).

// max(N.L, 0) with both vectors normalised safely, kept in [0, 1]: a zero vector gives 0.
float wg_lambert(vec3 n, vec3 l) {
  return clamp(dot(wg_safe_normalize_vec3(n), wg_safe_normalize_vec3(l)), 0.0, 1.0);
}
