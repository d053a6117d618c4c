#version 330 core
#extension GL_ARB_tessellation_shader : require
// Seed 003's distance-based tessellation, written by hand: full detail (factor 4) up to
// 4 m from the camera, falling linearly to 1% at 25 m, never below one segment.

layout(vertices = 3) out;
in vec3 tc_position[];
in vec2 tc_uv[];
out vec3 te_position[];
out vec2 te_uv[];
uniform vec3 u_camera_position;

float tessFactor(vec3 p) {
  float f = clamp(1.0 - (distance(p, u_camera_position) - 4.0) / 21.0, 0.01, 1.0);
  return max(f * 4.0, 1.0);
}

void main() {
  te_position[gl_InvocationID] = tc_position[gl_InvocationID];
  te_uv[gl_InvocationID] = tc_uv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    float f0 = tessFactor(tc_position[0]);
    float f1 = tessFactor(tc_position[1]);
    float f2 = tessFactor(tc_position[2]);
    gl_TessLevelOuter[0] = 0.5 * (f1 + f2);
    gl_TessLevelOuter[1] = 0.5 * (f2 + f0);
    gl_TessLevelOuter[2] = 0.5 * (f0 + f1);
    gl_TessLevelInner[0] = (f0 + f1 + f2) / 3.0;
  }
}
