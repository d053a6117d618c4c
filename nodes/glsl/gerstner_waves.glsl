// Gerstner waves (GPU Gems 1 ch. 1; the stylized water shader): the sum of trochoidal waves, each moving
// the surface point horizontally along its direction and vertically, with the exact
// partial derivatives of the displaced surface so vertex displacement and fragment normals
// agree.

// Adds one wave to the running sums: acc[0] the displacement, acc[1] dP/dx - (1,0,0),
// acc[2] dP/dz - (0,0,1), all at the undisplaced point xz. The phase is
// theta = k * mod(dot(D, xz), wavelength) + phase, where `phase` = phi - mod(omega t, 2 pi):
// reducing dot(D, xz) by whole wavelengths first keeps sin/cos arguments small at 1e5 m.
// Derivatives: d theta / dx = k D.x, d theta / dz = k D.y, so each wave contributes
// dP/dx = (-Q A k Dx^2 sin, A k Dx cos, -Q A k Dx Dz sin) and the same with z for dP/dz.
mat3 wg_gerstner_wave_add(mat3 acc, vec2 xz, vec2 dir, float k, float wavelength, float amplitude,
                          float steepness, float phase) {
  float theta = k * mod(dot(dir, xz), wavelength) + phase;
  float s = sin(theta);
  float c = cos(theta);
  float qa = steepness * amplitude;
  float ka = k * amplitude;
  float qka = steepness * ka;
  acc[0] += vec3(qa * dir.x * c, amplitude * s, qa * dir.y * c);
  acc[1] += vec3(-qka * dir.x * dir.x * s, ka * dir.x * c, -qka * dir.x * dir.y * s);
  acc[2] += vec3(-qka * dir.x * dir.y * s, ka * dir.y * c, -qka * dir.y * dir.y * s);
  return acc;
}

// The unit surface normal cross(dP/dz, dP/dx), oriented up (y >= 0). At a cusp
// (sum Q k A = 1 on a crest) both tangents can vanish: the up vector is returned there.
vec3 wg_gerstner_normal(mat3 acc) {
  vec3 n = wg_waves_unit_or_vec3(cross(vec3(0.0, 0.0, 1.0) + acc[2], vec3(1.0, 0.0, 0.0) + acc[1]),
                                 vec3(0.0, 1.0, 0.0));
  return n.y < 0.0 ? -n : n;
}
