// camera_forward: the camera's forward axis from the view matrix.

// -(row 2) of the view matrix (column-major: view[col][2]), safe-normalised. A degenerate
// view matrix (|row 2|^2 < 0.5, e.g. all zero) gives the zero vector, which its readers
// (wg_water_depth_ray_factor_axis) take as "no axis"; a rigid one has |row 2| = 1.
vec3 wg_camera_forward(mat4 view) {
  vec3 f = -vec3(view[0][2], view[1][2], view[2][2]);
  return dot(f, f) < 0.5 ? vec3(0.0) : wg_safe_normalize_vec3(f);
}
