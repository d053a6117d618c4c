float f(mat2 m) { return m[0][0]; }
