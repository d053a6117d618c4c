// A small hand-written caustic (used by graphs/lib/caustic_light.json through a
// glsl_function node, docs/graph-format.md#glsl-function-nodes): bright lines where two
// wavy ridges cross, drifting with `phase`. Plain GLSL: helpers and constants, no uniforms.
const float CAUSTIC_TWO_PI = 6.28318530718;

// 1 on the lines x = n (integer n), falling to 0 half-way between them.
float ridge(float x) {
  return 1.0 - abs(sin(x * CAUSTIC_TWO_PI));
}

float caustic(vec2 uv, float scale, float phase) {
  vec2 p = uv * scale;
  return ridge(p.x + 0.3 * sin(p.y + phase)) * ridge(p.y + 0.3 * sin(p.x - phase));
}
