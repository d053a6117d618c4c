#version 330 core
// Seed 000's water, written by hand: the vertex stage only places the grid and hands the
// world position, normal and texture coordinate on (the names are those of the manifest
// of graphs/classic_webgl.json, so the runtime drives both versions the same way).

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
out vec3 v_world_position;
out vec3 v_normal;
out vec2 v_uv;
uniform mat4 u_model;
uniform mat4 u_view_projection;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  gl_Position = u_view_projection * world;
  v_world_position = world.xyz;
  v_normal = mat3(u_model) * a_normal;  // normalised per fragment
  v_uv = a_uv;
}
