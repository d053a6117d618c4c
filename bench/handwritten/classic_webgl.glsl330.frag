#version 330 core
// Seed 000's water, written by hand: a scrolling du/dv map ripples the reflection and
// refraction look-ups, two normal-map samples give the surface normal, Fresnel is
// (N.V)^strength, a Phong sun highlight fades in over the shore, and a shallow-to-deep
// tint is laid over the refraction. Same uniforms and samplers as the generated shader.

in vec3 v_world_position;
in vec3 v_normal;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;

uniform mat4 u_view;
uniform vec3 u_camera_position;
uniform vec2 u_camera_near_far;
uniform float u_time;
uniform vec2 u_viewport_size;
uniform vec3 u_sun_direction;  // unit
uniform vec3 p_shallow_color;
uniform vec3 p_deep_color;
uniform float p_tint_depth;
uniform float p_tint_strength;
uniform float p_wave_speed;
uniform float p_distortion;
uniform float p_fresnel_strength;
uniform float p_shine_damper;
uniform float p_reflectivity;
uniform float p_edge_softness;
uniform sampler2D t0_dudv;
uniform sampler2D t1_water_normal;
uniform sampler2D u_scene_depth;
uniform sampler2D u_reflection;
uniform sampler2D u_refraction;

const float kTiling = 4.0;
const float kNormalStrength = 0.6;

// Depth-buffer value to linear view depth: n / ((1 - d) + d n / f).
float linearDepth(float d) {
  float n = u_camera_near_far.x;
  return n / ((1.0 - d) + d * (n / u_camera_near_far.y));
}

// The colour uniforms hold sRGB values (what a colour picker shows, within [0, 1] by their
// range); shading is linear, so they are decoded first (IEC 61966-2-1).
vec3 linearFromSrgb(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c)); }

void main() {
  vec3 N = normalize(v_normal);
  vec3 V = normalize(u_camera_position - v_world_position);
  vec2 screenUv = gl_FragCoord.xy / u_viewport_size;

  // du/dv distortion, scrolling along u.
  vec2 dudvUv = v_uv * kTiling + vec2(fract(u_time * p_wave_speed), 0.0);
  vec2 distortion = (texture(t0_dudv, dudvUv).rg * 2.0 - 1.0) * p_distortion;
  vec2 rippledUv = screenUv + distortion;

  // Two normal-map layers at the rippled screen position, the second half-size and drifting.
  vec3 n1 = texture(t1_water_normal, rippledUv).rgb * 2.0 - 1.0;
  vec3 n2 = texture(t1_water_normal, rippledUv * 0.5 + fract(vec2(0.01, -0.02) * u_time)).rgb * 2.0 - 1.0;
  vec3 ts = normalize(n1 + n2);
  // Tangent frame of the flat water: T = +x, B = +z.
  vec3 normal = normalize(vec3(ts.x * kNormalStrength, 0.0, ts.y * kNormalStrength) + N * ts.z);

  float cosi = clamp(dot(normal, V), 0.0, 1.0);
  float reflectance = 1.0 - pow(cosi, p_fresnel_strength);

  vec2 sceneUv = clamp(rippledUv, 0.0, 1.0);
  vec3 refraction = texture(u_refraction, sceneUv).rgb;
  vec3 reflection = texture(u_reflection, sceneUv).rgb;

  // Water thickness along the view ray, from the depth pre-pass.
  float sceneDepth = linearDepth(texture(u_scene_depth, screenUv).r);
  float surfaceDepth = linearDepth(gl_FragCoord.z);
  vec3 forward = -vec3(u_view[0][2], u_view[1][2], u_view[2][2]);
  float thickness = max(sceneDepth - surfaceDepth, 0.0) / max(dot(-V, forward), 0.1);

  vec3 tint = mix(linearFromSrgb(p_shallow_color), linearFromSrgb(p_deep_color), clamp(thickness / p_tint_depth, 0.0, 1.0));
  vec3 color = mix(mix(refraction, tint, p_tint_strength), reflection, reflectance);

  vec3 R = reflect(-u_sun_direction, normal);
  float specular = pow(max(dot(R, V), 0.0), p_shine_damper);
  float shoreFade = clamp(thickness / p_edge_softness, 0.0, 1.0);
  o_color = vec4(color + specular * p_reflectivity * shoreFade, 1.0);
}
