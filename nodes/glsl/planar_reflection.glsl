// planar_reflection: the reflection pass's texture looked up at this pixel.

// For reflection passes rendered through a camera mirrored about the water plane (the
// classic WebGL water renderer: reflectTexCoords = (ndc.x, -ndc.y)): the image is upside down, so v is flipped after
// the distortion and the clamp to [0, 1]. watergraph's runtime renders the mirrored scene
// through the real camera instead and needs no flip (wg_scene_color_uv alone).
vec2 wg_planar_reflection_uv_flipped(vec2 uv, vec2 offset) {
  vec2 p = wg_scene_color_uv(uv, offset);
  return vec2(p.x, 1.0 - p.y);
}
