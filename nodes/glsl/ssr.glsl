// ssr: screen-space reflection by a fixed number of ray-march steps (the deferred water article, listing 8).

// Marches the reflected ray origin + t dir, t = (i + 0.5) step, with the deferred water article's step
// length step / max(0.6, cos^2) (longer steps for grazing reflections, cos = R.N) and a
// hit test whose squared tolerance grows by `growth` per step (the article: 16 * 1.1^i), here on
// the difference between the ray's view depth and the scene's linear depth at the ray's
// screen position. A point with clip w <= 1e-6 (behind or at the camera) or outside the
// screen ends the march without a hit, so no division by w <= 0 ever happens.
// Returns (uv of the hit, 1) or (0.5, 0.5, 0). textureLod: the loop is non-uniform flow.
vec3 wg_ssr_march(sampler2D scene_depth, vec3 origin, vec3 dir, float cos_rn, mat4 view, mat4 proj, vec2 near_far,
                  int steps, float step_length, float tolerance, float growth) {
  float stride = max(step_length, 1e-4) / max(0.6, cos_rn * cos_rn);
  float t = 0.5 * stride;
  float tol2 = tolerance * tolerance;
  float g = max(growth, 0.0);
  for (int i = 0; i < steps; ++i) {
    vec4 vp = view * vec4(origin + t * dir, 1.0);
    t += stride;
    vec4 clip = proj * vp;
    if (clip.w <= 1e-6) break;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) break;
    float diff = -vp.z - wg_linearize_depth(textureLod(scene_depth, uv, 0.0).r, near_far);
    if (diff * diff < tol2) return vec3(uv, 1.0);
    tol2 *= g;
  }
  return vec3(0.5, 0.5, 0.0);
}

// The deferred water article's fade of a reflection found at uv: towards the screen edges
// max(1 - (0.01 + |2 uv - 1|^2)^(1/4), 0) (0.68 at the centre, 0 near the corners), times
// min(1, fade_distance / d) with d the surface's view distance (floored at 1e-6).
float wg_ssr_fade(vec2 uv, float dist, float fade_distance) {
  vec2 d = uv * 2.0 - 1.0;
  float edge = max(1.0 - sqrt(sqrt(0.01 + dot(d, d))), 0.0);
  return edge * min(1.0, max(fade_distance, 0.0) / max(dist, 1e-6));
}
