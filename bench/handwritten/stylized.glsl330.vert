#version 330 core
// Seed 003's stylized water, written by hand: the vertex stage only takes the grid to
// world space; the tessellation stages subdivide it and add the Gerstner waves.

layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec3 tc_position;
out vec2 tc_uv;
uniform mat4 u_model;

void main() {
  tc_position = (u_model * vec4(a_position, 1.0)).xyz;
  tc_uv = a_uv;
  gl_Position = vec4(tc_position, 1.0);
}
