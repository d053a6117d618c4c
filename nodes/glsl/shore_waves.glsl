// Shore waves (the stylized water shader, section 9): bands of foam running up the shore,
// (sin(depth * frequency + speed * t) / 2 + 1/2)^2, fading out by `dist` metres of depth.
// A crest sits where depth * frequency + speed * t = pi / 2: as t grows its depth falls,
// so a positive speed moves the bands towards the waterline. (The source subtracts the
// time term, which moves them out to sea while it describes waves breaking on the shore.)

// phase = mod(speed t, 2 pi) from the caller. Depth is clamped to [0, dist] first, so
// the sky's depth (huge) gives 0 instead of sin of infinity times 0; the argument of sin is
// wrapped with mod; dist is floored at 1e-6.
float wg_shore_waves(float depth, float frequency, float phase, float amplitude, float dist) {
  float dmax = max(dist, 1e-6);
  float d = clamp(depth, 0.0, dmax);
  float w = sin(mod(d * frequency + phase, 6.283185307179586)) * 0.5 + 0.5;
  w *= w;
  return clamp(w * amplitude * (1.0 - d / dmax), 0.0, 1.0);
}
