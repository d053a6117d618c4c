// Flow maps (the stylized water shader; Catlike Coding's "Texture Distortion"): a texture dragged along a
// flow vector in two phases half a cycle apart, cross-faded by triangle waves so the
// reset of each phase is never seen.

// A phase's progress fract(time * speed + offset), in [0, 1), and its triangle-wave weight
// 1 - |1 - 2 progress| (0 at the reset, 1 half-way; two phases half a cycle apart sum to
// 1) are the same for every pixel of a draw: the node computes them by math ops of their
// own (its derived inputs), and the shader reads them.

// The flow vector of a flow texture: xy * 2 - 1.
vec2 wg_flow_map_decode(vec4 texel) { return texel.xy * 2.0 - 1.0; }
