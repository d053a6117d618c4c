// The deferred water article's 3D wave: a trochoid-like wave sin(phase - 0.5 cos(phase)) plus a height-texture
// detail, found along the view ray by bisection (the deferred water renderer's listing 6).

// The height-texture coordinate of a world point: (s x + 0.5, 0.5 - s z), as in the deferred water article.
vec2 wg_trochoid_wave_uv(vec2 xz, float texScale) {
  return vec2(texScale * xz.x + 0.5, 0.5 - texScale * xz.y);
}

// The wave's phase at a world point, wrapped to [0, 2 pi): dot(K, xz) + mod(omega t, 2 pi).
float wg_trochoid_wave_phase(vec2 xz, vec2 waveVector, float timePhase) {
  return mod(dot(waveVector, xz) + timePhase, 6.283185307179586);
}

// Height above the flat surface: A (sin(phi - 0.5 cos phi) + detail (2 h(uv) - 1)).
float wg_trochoid_wave_height(vec2 xz, float amplitude, vec2 waveVector, float timePhase, float detail,
                              float texScale, sampler2D heightTex) {
  float phi = wg_trochoid_wave_phase(xz, waveVector, timePhase);
  float h = texture(heightTex, wg_trochoid_wave_uv(xz, texScale)).x;
  return amplitude * (sin(phi - 0.5 * cos(phi)) + detail * (2.0 * h - 1.0));
}

// Bisection along the ray from `origin` in the unit direction `dir` (the deferred water article, listing 6).
// The ray meets the flat surface y = surfaceY at P0 (distance clamped to [0, maxDistance],
// |dir.y| floored at 1e-6). The wave lies within +-M = A (1 + |detail|) of that plane, so
// along the ray within L = M / max(|dir.y|, 0.1) of P0 (the deferred water article's 10 M at grazing views).
// The deferred water article searches only the stretch before P0 and so misses troughs below the plane; here
// the search is centred on P0: each step halves, moving towards the camera while the point
// is below the wave and away from it while above (the signs swap for a camera below).
vec3 wg_trochoid_wave_march(vec3 origin, vec3 dir, float surfaceY, float amplitude, vec2 waveVector, float timePhase,
                            float detail, float texScale, float maxDistance, int steps, sampler2D heightTex) {
  float dy = abs(dir.y) < 1e-6 ? (dir.y < 0.0 ? -1e-6 : 1e-6) : dir.y;
  float t0 = clamp((surfaceY - origin.y) / dy, 0.0, maxDistance);
  vec3 p = origin + t0 * dir;
  float maxAmplitude = abs(amplitude) * (1.0 + abs(detail));
  float stepLength = (origin.y > surfaceY ? 1.0 : -1.0) * maxAmplitude / max(abs(dir.y), 0.1);
  for (int i = 0; i < steps; ++i) {
    float h = wg_trochoid_wave_height(p.xz, amplitude, waveVector, timePhase, detail, texScale, heightTex);
    stepLength *= 0.5;
    p += ((p.y - surfaceY) < h ? -stepLength : stepLength) * dir;
  }
  return p;
}

// The unit normal of the wave surface at xz: the trochoid term by its analytic derivative
// d/dphi sin(phi - 0.5 cos phi) = cos(phi - 0.5 cos phi)(1 + 0.5 sin phi), the texture
// detail by central differences `e` apart in texture space; normalize(-dh/dx, 1, -dh/dz).
vec3 wg_trochoid_wave_normal(vec2 xz, float amplitude, vec2 waveVector, float timePhase, float detail, float texScale,
                             float e, sampler2D heightTex) {
  float phi = wg_trochoid_wave_phase(xz, waveVector, timePhase);
  float dphi = cos(phi - 0.5 * cos(phi)) * (1.0 + 0.5 * sin(phi));
  vec2 uv = wg_trochoid_wave_uv(xz, texScale);
  float du = texture(heightTex, uv + vec2(e, 0.0)).x - texture(heightTex, uv - vec2(e, 0.0)).x;
  float dv = texture(heightTex, uv + vec2(0.0, e)).x - texture(heightTex, uv - vec2(0.0, e)).x;
  float inv2e = 0.5 / max(e, 1e-6);
  float dhdx = amplitude * (dphi * waveVector.x + detail * 2.0 * du * inv2e * texScale);
  float dhdz = amplitude * (dphi * waveVector.y - detail * 2.0 * dv * inv2e * texScale);
  return wg_safe_normalize_vec3(vec3(-dhdx, 1.0, -dhdz));
}
