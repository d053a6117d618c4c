/* Surface-query cost (issue 42): height and displace queries per second on one core, for the
 * header `watergraph compile GRAPH --target query-c` writes. Built and run by
 * bench/query_cost.sh, which passes the header's name and prefix as QUERY_HEADER and
 * QUERY(name). Points cover a 200 m square at several times, so the Newton inversion of
 * height() meets every phase of the waves. Times are the thread's CPU time.
 * With QUERY_OCEAN (a spectral ocean's header, whose functions take its state): the cost of
 * ocean_init and of one ocean_update, then the queries at the updated state's time. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include QUERY_HEADER

static double seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts); /* CPU time: other processes on the core do not count */
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#ifdef QUERY_OCEAN
static QUERY(ocean) sea; /* megabytes: static storage */
#define STATE &sea,
#define TIME(t)
#else
#define STATE
#define TIME(t) , t
#endif

int main(int argc, char** argv) {
  const long n = argc > 1 ? atol(argv[1]) : 2000000;
  QUERY(params) p;
  double sum = 0.0, start, heightSeconds, displaceSeconds;
  long i;
  QUERY(params_default)(&p);
#ifdef QUERY_OCEAN
  {
    const double camera[3] = {0.0, 10.0, 0.0};
    const int updates = 5;
    double initSeconds;
    start = seconds();
    QUERY(ocean_init)(&sea);
    initSeconds = seconds() - start;
    start = seconds();
    for (i = 0; i < updates; ++i) QUERY(ocean_update)(&sea, 3.5 + (double)i / 60.0, camera);
    printf("ocean_init:   %.1f ms (state %.1f MiB)\n", 1e3 * initSeconds, (double)sizeof sea / 1048576.0);
    printf("ocean_update: %.1f ms each (mean of %d)\n", 1e3 * (seconds() - start) / updates, updates);
  }
#endif
  start = seconds();
  for (i = 0; i < n; ++i) {
    double x = -100.0 + 200.0 * (double)(i % 1000) / 1000.0, z = -100.0 + 200.0 * (double)((i / 1000) % 1000) / 1000.0;
    sum += QUERY(height)(&p, STATE x, z TIME(0.37 * (double)(i % 7)));
  }
  heightSeconds = seconds() - start;
  start = seconds();
  for (i = 0; i < n; ++i) {
    double P[3], N[3], V[3];
    double x = -100.0 + 200.0 * (double)(i % 1000) / 1000.0, z = -100.0 + 200.0 * (double)((i / 1000) % 1000) / 1000.0;
    QUERY(displace)(&p, STATE x, z TIME(0.37 * (double)(i % 7)), P, N, V);
    sum += P[1] + N[1] + V[1];
  }
  displaceSeconds = seconds() - start;
  printf("height:   %.2f million queries/s (%.0f ns each)\n", 1e-6 * (double)n / heightSeconds, 1e9 * heightSeconds / (double)n);
  printf("displace: %.2f million queries/s (%.0f ns each, with normal and velocity)\n", 1e-6 * (double)n / displaceSeconds,
         1e9 * displaceSeconds / (double)n);
  printf("(checksum %.6f)\n", sum);
  return 0;
}
