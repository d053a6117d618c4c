// blinn_phong: specular highlight from the half vector (the advanced shaders tutorial, level 2).

// pow(max(N.H, 0), shininess) with H = normalize(L + V). When L = -V the half vector is
// zero and N.H = 0, so the highlight is 0 (the safe pow: 0^s = 0 for s > 0, 1 for s <= 0).
// Near the lobe's peak N.H is within 1e-5 of 1, where float32 holds it to a few digits and
// a sharp exponent (2048) multiplies its relative error: there the power is formed from
// sin^2 = |N x H|^2, which keeps its digits, as exp(shininess * ln(cos)) with
// ln(cos) = ln(1 - sin^2) / 2 = -(sin^2 / 2)(1 + sin^2 / 2 + sin^4 / 3) (the rest of the
// series is below sin^6 / 4 < 2.5e-7 for sin^2 < 0.01). N and H must be unit for that
// (wg_unit_sin2 >= 0); elsewhere the safe pow of N.H.
float wg_blinn_phong_specular(vec3 n, vec3 v, vec3 l, float shininess) {
  vec3 h = wg_half_vector(wg_safe_normalize_vec3(l), wg_safe_normalize_vec3(v));
  vec3 nn = wg_safe_normalize_vec3(n);
  float ndoth = clamp(dot(nn, h), 0.0, 1.0);
  float sin2 = wg_unit_sin2(nn, h);
  bool nearPeak = ndoth > 0.0 && sin2 >= 0.0 && sin2 < 0.01;
  float lnCos = -0.5 * sin2 * (1.0 + sin2 * (0.5 + sin2 / 3.0));
  return nearPeak ? exp(shininess * lnCos) : wg_safe_pow_float(ndoth, shininess);
}
