float g(float a) { return a; }
