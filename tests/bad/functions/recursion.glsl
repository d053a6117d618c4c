float f(float a) { return a < 1.0 ? a : f(a * 0.5); }
