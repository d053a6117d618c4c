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

// --- The filtered lobe: a normal averaged over a pixel's footprint (ocean_surface's filter)
// stands for facets whose slopes spread around it with variance V (both axes' summed). The
// pixel's mean radiance is the base lobe convolved with that spread (LEAN mapping, Olano and
// Baker 2010): for a Gaussian spread and a Beckmann base of alpha^2 exactly a Beckmann lobe
// of alpha'^2 = alpha^2 + V. GGX is a Student-t in slope space, whose convolution has no
// closed form; its share of the widened lobe is w = alpha^2 / alpha'^2 (1 where V = 0, 0
// where the spread dominates), the rest a Beckmann of alpha'^2. Exact at both ends; between,
// the peak is above the numerically convolved lobe's by at most 25 % (24 % at V = alpha^2), 3 %
// at V = 100 alpha^2 (docs/ocean.md, "Filtered shading").

// Beckmann exp(-tan^2 / a2) / (pi a2 cos^4), tan^2 = s2 / c2 (s2 as the GGX term's). 0 where
// the exponent passes 80: there the term is below e^-80 / c2^2 of the lobe's scale, and
// c2^2 could underflow (an exponent of NaN, 0 / 0, is caught there too).
float wg_ggx_specular_beckmann(float ndoth, float sin2, float a2) {
  float c2 = ndoth * ndoth;
  float s2 = ndoth > 0.0 && sin2 >= 0.0 ? sin2 : 1.0 - c2;
  float x = s2 / (c2 * a2);
  if (!(x <= 80.0)) return 0.0;
  return exp(-x) / (3.14159265358979 * a2 * c2 * c2);
}

// The filtered BRDF for slope variance `variance` (clamped to [0, 1e4]; 0: wg_ggx_specular).
// D = w GGX(alpha'^2) + (1 - w) Beckmann(alpha'^2) at N.H; the facets that reflect L into V
// are those near H, weighted by the base lobe against the spread: their normal
// N* = normalize(w (N.H) N + (1 - w) H) (between N and H by the variances' ratio), and
// Smith's G, N.L and N.V are theirs, at the base roughness; (N.H) / (N*.H) carries the
// facets' area per unit of the pixel's. Returns vec4(brdf, D, F, N*.L): brdf * N*.L is the
// pixel's mean reflected radiance per unit light.
vec4 wg_ggx_specular_filtered(vec3 n, vec3 v, vec3 l, float roughness, float variance, float f0) {
  float spread = min(variance, 1e4);
  if (!(spread > 0.0)) return wg_ggx_specular(n, v, l, roughness, f0);
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 vv = wg_safe_normalize_vec3(v);
  vec3 ll = wg_safe_normalize_vec3(l);
  vec3 h = wg_half_vector(ll, vv);
  float rough = clamp(roughness, 0.001, 1.0);
  float a = rough * rough;
  float a2 = a * a;
  float wide = a2 + spread;
  float w = a2 / wide;
  float ndoth = clamp(dot(nn, h), 0.0, 1.0);
  float sin2 = wg_unit_sin2(nn, h);
  float d = w * wg_ggx_specular_distribution(ndoth, sin2, wide) + (1.0 - w) * wg_ggx_specular_beckmann(ndoth, sin2, wide);
  vec3 facet = wg_safe_normalize_vec3(w * ndoth * nn + (1.0 - w) * h);
  float fdotl = clamp(dot(facet, ll), 0.0, 1.0);
  float fdotv = clamp(dot(facet, vv), 0.0, 1.0);
  float fdoth = clamp(dot(facet, h), 0.0, 1.0);
  float vdoth = clamp(dot(vv, h), 0.0, 1.0);
  float area = fdoth > 0.0 ? ndoth / fdoth : 0.0;
  float f = wg_fresnel_schlick(vdoth, f0);
  float brdf = d * area * f * wg_ggx_specular_visibility(fdotl, fdotv, rough);
  return vec4(brdf, d, f, fdotl);
}
