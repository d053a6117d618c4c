// underwater: the deferred water article's five camera/pixel cases of deferred water, run as a full-screen
// pass. `water` is the water G-buffer at this pixel: the surface's world position (xyz)
// and its depth-buffer value (w; 1.0 where no water surface covers the pixel). `scene` is
// the opaque scene's world position there and `sky` 1 where the scene depth is 1.0.

// Largest component: the deferred water article scales the caustics by the brightest channel of the scene.
float wg_underwater_max3(vec3 c) { return max(c.r, max(c.g, c.b)); }

// Camera above the water (cases 1, 4, 5). Returns (colour, case).
// 1: no water between the camera and the scene point (scene above the surface height
//    along this ray): the scene colour unchanged.
// 4: scene under water and light still comes through (max transmittance > 1/256 over the
//    in-water distance d_S - d_W) and nearer than the haze distance: Beer-Lambert
//    absorption, refraction by a distortion strength * (1 - T.b) * N.xz (the article's listing 16),
//    caustics scaled by the brightest channel (listing 18), the water's own colour by the
//    absorbed part, the surface light added on top, then haze by the surface distance.
// 5: otherwise the water body is opaque: only its own colour, the surface light and haze
//    (the article's case 5; no scene look-ups).
vec4 wg_underwater_from_above(sampler2D scene_color, vec2 uv, vec4 water, vec3 scene, float sky, vec3 camera,
                              vec3 n, vec3 surface, float transmittance, vec3 water_color, float diffuse,
                              vec3 sigma, float strength, float caustics, vec3 caustics_color,
                              float haze_distance, vec3 haze_color, float level) {
  bool covered = water.w < 1.0;
  float height = covered ? water.y : level;
  if (!covered || height - scene.y <= 0.0) return vec4(textureLod(scene_color, uv, 0.0).rgb, 1.0);
  float dw = length(water.xyz - camera);
  float ds = sky > 0.5 ? 1e30 : length(scene - camera);
  vec3 t = wg_absorption_beer_lambert(sigma, max(ds - dw, 0.0));
  vec3 body = water_color * diffuse;
  float which = 5.0;
  if (wg_underwater_max3(t) > 0.00390625 && ds < haze_distance) {
    vec2 ruv = wg_scene_color_uv(uv, strength * (1.0 - t.b) * n.xz);
    vec3 refr = textureLod(scene_color, ruv, 0.0).rgb;
    float c = caustics * wg_underwater_max3(refr);
    body = t * (refr + caustics_color * c) + (vec3(1.0) - t) * water_color * diffuse;
    which = 4.0;
  }
  vec3 lit = transmittance * body + surface;
  return vec4(mix(lit, haze_color, wg_haze_factor(dw, haze_distance)), which);
}

// Camera under the water (cases 2, 3). Returns (colour, case). Light falls off with the
// camera's depth below the water level: k = min(1, depth_light / depth) (the article's listings
// 10-11, floored depth 1e-6).
// 2: the scene point is under water (or no surface lies in between): absorption over the
//    camera-scene distance, caustics, the water's colour by the absorbed part.
// 3: looking up through the surface: absorption over the camera-surface distance, the
//    scene above refracted by strength * N.xz and passed by transmittance_below (Snell's
//    window, e.g. fresnel water_to_air), plus the light the surface sends down.
vec4 wg_underwater_from_below(sampler2D scene_color, vec2 uv, vec4 water, vec3 scene, float sky, vec3 camera,
                              vec3 n, vec3 surface_below, float transmittance_below, vec3 water_color,
                              float diffuse, vec3 sigma, float strength, float caustics, vec3 caustics_color,
                              float depth_light, float level) {
  bool covered = water.w < 1.0;
  float height = covered ? water.y : level;
  float k = min(1.0, max(depth_light, 0.0) / max(level - camera.y, 1e-6));
  if (!covered || height - scene.y > 0.0) {
    float ds = sky > 0.5 ? 1e30 : length(scene - camera);
    vec3 t = wg_absorption_beer_lambert(sigma, ds);
    vec3 col = textureLod(scene_color, uv, 0.0).rgb;
    float c = caustics * wg_underwater_max3(col);
    return vec4(k * (t * (col + caustics_color * c) + (vec3(1.0) - t) * water_color * diffuse), 2.0);
  }
  vec3 t = wg_absorption_beer_lambert(sigma, length(water.xyz - camera));
  vec3 seen = textureLod(scene_color, wg_scene_color_uv(uv, strength * n.xz), 0.0).rgb;
  return vec4(k * (t * (transmittance_below * seen + surface_below) + (vec3(1.0) - t) * water_color * diffuse), 3.0);
}
