// absorption: light absorbed along a path through water, per colour channel.

// Beer-Lambert: T = exp(-sigma d) per channel; distance clamped to [0, 1e30] and the
// coefficients to >= 0, so T is in [0, 1] and never NaN (0 * inf cannot occur).
vec3 wg_absorption_beer_lambert(vec3 sigma, float dist) {
  float d = clamp(dist, 0.0, 1e30);
  return exp(-max(sigma, vec3(0.0)) * d);
}

// The deferred water article's relative-coefficient model (listings 10-12): blue falls linearly to 0 over
// max_distance, green and red are blue times (1 - d k_g) and (1 - d k_r), each clamped to
// [0, 1], then squared. max_distance floored at 1e-6; distance clamped to [0, 1e30].
vec3 wg_absorption_relative(float dist, float max_distance, float k_red, float k_green) {
  float d = clamp(dist, 0.0, 1e30);
  float m = max(max_distance, 1e-6);
  float b = clamp((m - d) / m, 0.0, 1.0);
  float g = clamp(b * (1.0 - d * k_green), 0.0, 1.0);
  float r = clamp(b * (1.0 - d * k_red), 0.0, 1.0);
  return vec3(r * r, g * g, b * b);
}
