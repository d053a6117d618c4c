// Flow maps (the stylized water shader; Catlike Coding's "Texture Distortion"): a texture dragged along a
// flow vector in two phases half a cycle apart, cross-faded by triangle waves so the
// reset of each phase is never seen.

// A phase's progress in [0, 1): fract(time * speed + offset).
float wg_flow_map_progress(float time, float speed, float offset) { return fract(time * speed + offset); }

// Triangle-wave weight 1 - |1 - 2 progress|: 0 at the reset, 1 half-way. The weights of
// two phases half a cycle apart sum to 1.
float wg_flow_map_weight(float progress) { return 1.0 - abs(1.0 - 2.0 * progress); }

// The flow vector of a flow texture: xy * 2 - 1.
vec2 wg_flow_map_decode(vec4 texel) { return texel.xy * 2.0 - 1.0; }
