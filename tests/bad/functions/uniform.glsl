uniform float u_time;
float f(float a) { return a * u_time; }
