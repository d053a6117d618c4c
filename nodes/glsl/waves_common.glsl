// Helpers shared by the wave and flow nodes (gerstner_waves, trochoid_wave, sine_normals,
// ripple_normals, normal_map_scroll, normal_from_height, flow_map).

// The unit vector of v, or `fallback` when v is (nearly) zero: a degenerate frame (a
// Gerstner cusp, two opposite normals blended) still yields a unit direction, never NaN.
vec3 wg_waves_unit_or_vec3(vec3 v, vec3 fallback) {
  float l2 = dot(v, v);
  vec3 unit = v * inversesqrt(l2);  // inf or NaN at l2 = 0: then not chosen (a select, no branch)
  return l2 < 1e-12 ? fallback : unit;
}

// A tangent-space normal (x along T, y along B, z along N) taken to world space and made
// unit; the up vector when the result degenerates. A (nearly) zero N carries no direction
// and is taken as up: otherwise the result would rest on the tangent-space x and y alone
// (about 0.01 long), whose 1/255 texture-filtering error turns it by 0.3.
vec3 wg_waves_tangent_to_world(vec3 ts, vec3 t, vec3 b, vec3 n) {
  vec3 frameN = dot(n, n) < 1e-12 ? vec3(0.0, 1.0, 0.0) : n;
  return wg_waves_unit_or_vec3(t * ts.x + b * ts.y + frameN * ts.z, vec3(0.0, 1.0, 0.0));
}

// The same for the flat frame T = +x, B = +z (constant inputs): t * ts.x + b * ts.y is
// (ts.x, 0, ts.y) exactly for a finite ts, which glslang and spirv-opt cannot fold
// (0 * x is NaN for an infinite x), so it is written out.
vec3 wg_waves_tangent_to_world_flat(vec3 ts, vec3 n) {
  vec3 frameN = dot(n, n) < 1e-12 ? vec3(0.0, 1.0, 0.0) : n;
  return wg_waves_unit_or_vec3(vec3(ts.x, 0.0, ts.y) + frameN * ts.z, vec3(0.0, 1.0, 0.0));
}
