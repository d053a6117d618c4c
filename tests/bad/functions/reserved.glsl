float wg_f(float a) { return a; }
float f(float a) { return wg_f(a); }
