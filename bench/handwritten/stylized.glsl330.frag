#version 330 core
// Seed 003's stylized water, written by hand: two scrolling normal-map layers tilted by a
// flow map, Fresnel (1 - N.V)^power between the planar reflection and the refracted scene,
// a depth tint, Voronoi caustics on the floor, a subsurface glow on the crests, and shore
// waves plus edge foam. Same uniforms and samplers as the generated shader.

in vec3 v_world_position;
in vec3 v_normal;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;

uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec3 u_camera_position;
uniform vec2 u_camera_near_far;
uniform float u_time;
uniform vec2 u_viewport_size;
uniform vec3 u_sun_direction;  // unit
// omega t wrapped to [0, 2 pi), supplied by the runtime (manifest: time_phase).
uniform float u_phase0;  // foam scroll, x
uniform float u_phase1;  // foam scroll, y
uniform float u_phase2;  // shore waves
uniform float u_phase3;  // caustics, layer 1
uniform float u_phase4;  // caustics, layer 2
uniform vec3 p_shallow_color;
uniform vec3 p_deep_color;
uniform float p_max_distance;
uniform float p_fresnel_power;
uniform float p_caustics_strength;
uniform vec3 p_sss_color;
uniform vec3 p_foam_color;
uniform sampler2D t0_water_normal;
uniform sampler2D t1_dudv;
uniform sampler2D t2_foam;
uniform sampler2D u_scene_depth;
uniform sampler2D u_scene_color;
uniform sampler2D u_reflection;

const float TAU = 6.283185307;

float linearDepth(float d) {
  float n = u_camera_near_far.x;
  return n / ((1.0 - d) + d * (n / u_camera_near_far.y));
}

// PCG3D hash, so the cells match the generated shader's pattern exactly.
uvec3 pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// Distance to the nearest animated feature point (Voronoi F1) over the 3x3 cells.
float voronoi(vec2 p, float phase) {
  vec2 cell = floor(p);
  vec2 f = p - cell;
  uvec2 icell = uvec2(ivec2(cell));
  float best = 1e30;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      vec2 h = vec2(pcg3d(uvec3(icell + uvec2(ivec2(i, j)), 0u)).xy >> 8u) * 5.9604644775390625e-8;
      vec2 q = vec2(i, j) + 0.5 + 0.5 * vec2(sin(phase + TAU * h.x), cos(phase + TAU * h.y)) - f;
      best = min(best, dot(q, q));
    }
  }
  return sqrt(best);
}

float causticLayer(vec2 p, float phase) {
  float m = 1.0 - min(voronoi(p, phase), 1.0);
  return m * m * m;
}

// The colour uniforms hold sRGB values (what a colour picker shows, within [0, 1] by their
// range); shading is linear, so they are decoded first (IEC 61966-2-1).
vec3 linearFromSrgb(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c)); }

void main() {
  vec3 V = normalize(u_camera_position - v_world_position);
  vec2 screenUv = gl_FragCoord.xy / u_viewport_size;

  // Two scrolling normal-map layers, blended, slope halved, in the flat water's frame.
  vec3 a = texture(t0_water_normal, v_uv * 4.0 + fract(vec2(0.05, 0.03) * u_time)).rgb * 2.0 - 1.0;
  vec3 b = texture(t0_water_normal, v_uv * 8.0 + fract(vec2(-0.03, 0.07) * u_time)).rgb * 2.0 - 1.0;
  vec3 ts = normalize(a + b);
  vec3 normal = normalize(vec3(ts.x * 0.5, 0.0, ts.y * 0.5) + normalize(v_normal) * ts.z);

  // Flow map: the normal map dragged along the du/dv flow in two cross-faded phases.
  vec2 flow = (texture(t1_dudv, v_uv).rg * 2.0 - 1.0) * 0.08;
  float progressA = fract(u_time * 0.15);
  float progressB = fract(u_time * 0.15 + 0.5);
  vec4 flowed = texture(t0_water_normal, v_uv - flow * progressA) * (1.0 - abs(1.0 - 2.0 * progressA)) +
                texture(t0_water_normal, v_uv - flow * progressB) * (1.0 - abs(1.0 - 2.0 * progressB));
  vec2 tilt = flowed.xz * 0.5 - 0.25;
  normal = normalize(normal + vec3(tilt.x, 0.0, tilt.y));

  float fresnel = pow(1.0 - clamp(dot(normal, V), 0.0, 1.0), p_fresnel_power);
  vec2 sceneUv = clamp(screenUv + normal.xz * 0.04, 0.0, 1.0);
  vec3 reflection = texture(u_reflection, sceneUv).rgb;
  vec3 refraction = texture(u_scene_color, sceneUv).rgb;

  // Water thickness along the view ray.
  float floorDepth = linearDepth(texture(u_scene_depth, screenUv).r);
  vec3 forward = -vec3(u_view[0][2], u_view[1][2], u_view[2][2]);
  float thickness = max(floorDepth - linearDepth(gl_FragCoord.z), 0.0) / max(dot(-V, forward), 0.1);

  // Foam: two scrolling foam samples masked at the edges, and shore-wave bands.
  vec2 scroll = vec2(u_phase0, u_phase1) * (1.0 / TAU);
  vec2 xz = v_world_position.xz;
  float foamTexture = 0.5 * (texture(t2_foam, xz * 0.1 + scroll).r + texture(t2_foam, xz * 0.08 + vec2(-scroll.y, scroll.x)).r);
  float edgeFoam = step(0.35, foamTexture * (1.0 - clamp(thickness * 2.0, 0.0, 1.0)));
  float shoreDepth = min(thickness, 1.5);
  float band = sin(shoreDepth * 5.0 + u_phase2) * 0.5 + 0.5;  // + : the bands run ashore
  float shore = band * band * 0.8 * (1.0 - shoreDepth / 1.5);
  float foam = max(shore, edgeFoam);

  // Body: refraction tinted by depth, lit by caustics on the floor below.
  float depthFactor = clamp(thickness / p_max_distance, 0.0, 1.0);
  vec3 body = mix(refraction, mix(linearFromSrgb(p_shallow_color), linearFromSrgb(p_deep_color), depthFactor), depthFactor);
  vec2 ndc = screenUv * 2.0 - 1.0;
  vec3 ray = vec3((ndc.x + u_projection[2][0]) / u_projection[0][0], (ndc.y + u_projection[2][1]) / u_projection[1][1], -1.0);
  vec2 floorXz = (u_camera_position + transpose(mat3(u_view)) * ray * floorDepth).xz * 0.6;
  float caustics = 0.5 * (causticLayer(floorXz, u_phase3) + causticLayer(floorXz * 1.3 + 5.0, u_phase4));
  body += caustics * p_caustics_strength * (1.0 - depthFactor);

  vec3 color = mix(body, reflection, fresnel);

  // Subsurface glow where the sun shines through the crests.
  vec3 H = normalize(u_sun_direction + normal * 0.3);
  float sss = pow(clamp(dot(V, -H), 0.0, 1.0), 4.0) * clamp(v_world_position.y * 2.0 + 0.5, 0.0, 1.0);
  color += linearFromSrgb(p_sss_color) * (0.6 * sss);

  o_color = vec4(mix(color, linearFromSrgb(p_foam_color), foam), 1.0);
}
