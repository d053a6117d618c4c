// haze: distance blend towards the background colour (the deferred water article, case 5).

// The haze amount 1 - max(0, (H - d) / H) of the deferred water article (H = 2000 units there), kept in
// [0, 1]: 0 at the camera, 1 from the haze distance on. H is floored at 1e-6.
float wg_haze_factor(float dist, float haze_distance) {
  return clamp(dist / max(haze_distance, 1e-6), 0.0, 1.0);
}
