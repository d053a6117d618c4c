// ggx_specular: Cook-Torrance microfacet specular of the advanced shaders tutorial (GGX D, Schlick F, Smith G).

// GGX / Trowbridge-Reitz normal distribution a2 / (pi d^2), d = NdotH^2 a2 + (1 - NdotH^2)
// (the textbook's NdotH^2 (a2 - 1) + 1 cancels to 0 in float32 at NdotH = 1 for a smooth
// surface, a2 < 6e-8, and divides by zero). Where H is within a degree of N, where a smooth
// surface's D is steepest (the sun's glitter on the water), 1 - NdotH^2 keeps only a few
// bits: there sin2 (wg_unit_sin2, >= 0 for unit N and H) stands for it, where H faces N.
// Elsewhere (a clamped NdotH of 0, a zero or short vector) the textbook term:
// d >= min(a2, 1) > 0.
float wg_ggx_specular_distribution(float ndoth, float sin2, float a2) {
  float c2 = ndoth * ndoth;
  float s2 = ndoth > 0.0 && sin2 >= 0.0 ? sin2 : 1.0 - c2;
  float d = c2 * a2 + s2;
  return a2 / (3.14159265358979 * d * d);
}

// Smith's G with the Schlick-GGX G1 = x / (x (1 - k) + k), k = (roughness + 1)^2 / 8,
// folded into the Cook-Torrance denominator: G / (4 NdotL NdotV) =
// 1 / (4 (NdotL (1 - k) + k)(NdotV (1 - k) + k)). Exact wherever the textbook form is
// defined, and its finite limit where NdotL or NdotV is 0 (k >= 1/8, so no division by 0).
float wg_ggx_specular_visibility(float ndotl, float ndotv, float roughness) {
  float r = roughness + 1.0;
  float k = r * r / 8.0;
  return 1.0 / (4.0 * (ndotl * (1.0 - k) + k) * (ndotv * (1.0 - k) + k));
}

// The BRDF D F G / (4 NdotL NdotV) for unit-safe N, V, L; roughness clamped to
// [0.001, 1] (a2 >= 1e-12, so D <= 3.2e11 stays finite), F Schlick with F0 at V.H.
// Returns vec4(brdf, D, F, NdotL).
vec4 wg_ggx_specular(vec3 n, vec3 v, vec3 l, float roughness, float f0) {
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 vv = wg_safe_normalize_vec3(v);
  vec3 ll = wg_safe_normalize_vec3(l);
  vec3 h = wg_half_vector(ll, vv);
  float rough = clamp(roughness, 0.001, 1.0);
  float a = rough * rough;
  float ndotl = clamp(dot(nn, ll), 0.0, 1.0);
  float ndotv = clamp(dot(nn, vv), 0.0, 1.0);
  float ndoth = clamp(dot(nn, h), 0.0, 1.0);
  float vdoth = clamp(dot(vv, h), 0.0, 1.0);
  float d = wg_ggx_specular_distribution(ndoth, wg_unit_sin2(nn, h), a * a);
  float f = wg_fresnel_schlick(vdoth, f0);
  float brdf = d * f * wg_ggx_specular_visibility(ndotl, ndotv, rough);
  return vec4(brdf, d, f, ndotl);
}
