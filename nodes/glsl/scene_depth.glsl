// scene_depth: the opaque scene behind this pixel, from the depth pre-pass (u_scene_depth).

// World position of the scene point seen at screen position uv whose linear view depth is
// lin, for a perspective projection: x_view = (ndc.x + P[2][0]) lin / P[0][0] (likewise y),
// z_view = -lin, then back to world with the transposed rotation of the (rigid) view
// matrix: no matrix inverse per pixel. Projection scales below 1e-6 are floored (a
// degenerate matrix gives a finite point) and the result is clamped to +-1e30, so the sky
// (lin up to 1e30) stays finite.
vec3 wg_scene_depth_position(vec2 uv, float lin, vec3 camera, mat4 view, mat4 proj) {
  vec2 ndc = uv * 2.0 - 1.0;
  float px = abs(proj[0][0]) < 1e-6 ? 1e-6 : proj[0][0];
  float py = abs(proj[1][1]) < 1e-6 ? 1e-6 : proj[1][1];
  vec3 ray = vec3((ndc.x + proj[2][0]) / px, (ndc.y + proj[2][1]) / py, -1.0);
  vec3 world = transpose(mat3(view)) * ray;
  return clamp(camera + world * lin, vec3(-1e30), vec3(1e30));
}
