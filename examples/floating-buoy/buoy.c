/* A buoy floating on a watergraph sea, driven by the generated surface query.
 *
 *   watergraph compile graphs/ocean.json -o out --target glsl330,query-c
 *   cc -std=c99 -O2 -I out -DQUERY_HEADER='"ocean.query.h"' -D'QUERY(f)=wg_ocean_##f' \
 *      examples/floating-buoy/buoy.c -o buoy -lm && ./buoy
 *
 * Each step the buoy asks the water where its surface is under the buoy's centre now
 * (height) and how it is tilted there: it displaces the water point found under the buoy
 * to read the surface normal and the water's velocity. Heave follows the height through a
 * damped spring (buoyancy against gravity), the buoy's axis follows the normal (pitch and
 * roll), and the water's horizontal velocity drags it along. It prints one line per
 * simulated second: time, position, height of the water there, tilt from vertical. */
#include <math.h>
#include <stdio.h>

#include QUERY_HEADER

int main(void) {
  QUERY(params) water;
  double pos[3] = {3.0, 0.0, -2.0}, vel[3] = {0.0, 0.0, 0.0}, axis[3] = {0.0, 1.0, 0.0};
  const double dt = 1.0 / 60.0, stiffness = 40.0, damping = 6.0, drag = 0.8;
  int step;
  QUERY(params_default)(&water);
  for (step = 0; step <= 20 * 60; ++step) {
    const double t = step * dt;
    double h = QUERY(height)(&water, pos[0], pos[2], t);
    double P[3], N[3], V[3];
    /* The water point under the buoy: displace() at the buoy's (x, z) is close enough for
     * the normal and velocity of a buoy smaller than a wavelength. */
    QUERY(displace)(&water, pos[0], pos[2], t, P, N, V);
    vel[1] += dt * (stiffness * (h - pos[1]) - damping * (vel[1] - V[1]));
    vel[0] += dt * drag * (V[0] - vel[0]);
    vel[2] += dt * drag * (V[2] - vel[2]);
    for (int i = 0; i < 3; ++i) {
      pos[i] += dt * vel[i];
      axis[i] += 0.2 * (N[i] - axis[i]); /* the buoy's axis eases towards the normal */
    }
    if (step % 60 == 0) {
      double tilt = acos(axis[1] / sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]));
      printf("t %5.1f s  buoy (%7.3f, %6.3f, %7.3f)  water %6.3f  tilt %5.1f deg\n", t, pos[0], pos[1], pos[2], h,
             tilt * 180.0 / 3.14159265358979);
    }
  }
  return 0;
}
