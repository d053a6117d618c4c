#version 330 core
#extension GL_ARB_tessellation_shader : require
// Seed 003's Gerstner waves, written by hand: three trochoidal waves displace each
// tessellated vertex, and the normal comes from the summed tangents.

layout(triangles, fractional_odd_spacing, ccw) in;
in vec3 te_position[];
in vec2 te_uv[];
out vec3 v_world_position;
out vec3 v_normal;
out vec2 v_uv;
uniform mat4 u_view_projection;
// omega t wrapped to [0, 2 pi) per wave, supplied by the runtime (manifest: time_phase).
uniform float u_phase5;
uniform float u_phase6;
uniform float u_phase7;

// wave: unit direction xy, steepness Q, wavelength L. k = 2 pi / L, amplitude A = Q / k,
// in the GPU Gems form the graph uses: height A sin, horizontal excursion Q A cos.
void gerstner(vec4 wave, float phase, vec2 xz, inout vec3 p, inout vec3 tangent, inout vec3 binormal) {
  vec2 d = wave.xy;
  float q = wave.z;
  float k = 6.283185307 / wave.w;
  float a = q / k;
  float f = k * dot(d, xz) - phase;
  float s = sin(f), c = cos(f);
  float qs = q * q * s;  // Q k A sin
  p += vec3(d.x * q * a * c, a * s, d.y * q * a * c);
  tangent += vec3(-d.x * d.x * qs, d.x * q * c, -d.x * d.y * qs);
  binormal += vec3(-d.x * d.y * qs, d.y * q * c, -d.y * d.y * qs);
}

void main() {
  vec3 world = gl_TessCoord.x * te_position[0] + gl_TessCoord.y * te_position[1] + gl_TessCoord.z * te_position[2];
  vec2 uv = gl_TessCoord.x * te_uv[0] + gl_TessCoord.y * te_uv[1] + gl_TessCoord.z * te_uv[2];
  vec3 p = world;
  vec3 tangent = vec3(1.0, 0.0, 0.0);
  vec3 binormal = vec3(0.0, 0.0, 1.0);
  gerstner(vec4(0.9805807, 0.19611613, 0.4, 8.0), u_phase5, world.xz, p, tangent, binormal);
  gerstner(vec4(0.28734788, 0.95782626, 0.3, 5.0), u_phase6, world.xz, p, tangent, binormal);
  gerstner(vec4(-0.7592566, 0.65079135, 0.2, 3.0), u_phase7, world.xz, p, tangent, binormal);
  gl_Position = u_view_projection * vec4(p, 1.0);
  v_world_position = p;
  v_normal = normalize(cross(binormal, tangent));
  v_uv = uv;
}
