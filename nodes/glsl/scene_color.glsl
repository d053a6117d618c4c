// scene_color / planar_reflection: screen-space look-ups of the scene textures.

// The screen position uv moved by a distortion offset and clamped to [0, 1], so a
// distorted look-up never reads outside the texture (no wrap-around to the far side of
// the screen, no stretched border texels).
vec2 wg_scene_color_uv(vec2 uv, vec2 offset) { return clamp(uv + offset, vec2(0.0), vec2(1.0)); }
