// The spectral ocean of a surface query, C form (codegen/query_ocean.h). The physics is
// core/ocean_spectrum.cpp and core/ocean_fft_reference.cpp written again in C99, line for
// line and in the same order of operations, so that h0 comes out bit for bit as the
// compiler's (tests/codegen/query_ocean_test.cpp compares them).
#include <algorithm>
#include <string>
#include <vector>

#include "codegen/query_ocean.h"
#include "core/number_format.h"

namespace wg {

namespace {

// Shared by every ocean query header: the spectrum (core/ocean_spectrum.cpp), the
// counter-based Gaussian numbers (core/ocean_random.cpp), the loop's 32-bit phases and
// the radix-2 inverse transform.
const char* oceanCHelpers() {
  return R"(#ifndef WGQ_OCEAN_HELPERS
#define WGQ_OCEAN_HELPERS
#define WGQ_PI 3.14159265358979323846
#define WGQ_G 9.81
/* An ocean_spectrum's spectrum (docs/ocean.md): model 0 Phillips, 1 Pierson-Moskowitz,
 * 2 JONSWAP, 3 TMA; spreading 0 cos^2, 1 Mitsuyasu, 2 Hasselmann; angles in radians. */
typedef struct wgq_sea {
  int model, spreading;
  double wind_speed, wind_direction, fetch, depth, gamma, phillips_amplitude, phillips_small_wave;
  double swell_height, swell_period, swell_direction, swell_spread;
} wgq_sea;
static inline double wgq_tanh_over_k(double k, double depth) {
  double x = k * depth;
  if (!(x < 20.0)) return 1.0 / k;
  if (x < 1e-5) return depth * (1.0 - x * x / 3.0);
  return tanh(x) / k;
}
static inline double wgq_two_kd_over_sinh(double x) {
  double y;
  if (!(x < 20.0)) return 0.0;
  y = 2.0 * x;
  if (y < 1e-5) return 1.0 - y * y / 6.0;
  return y / sinh(y);
}
static inline double wgq_angular_frequency(double k, double depth) {
  if (!(k > 0.0)) return 0.0;
  return sqrt(WGQ_G * k * k * wgq_tanh_over_k(k, depth));
}
static inline double wgq_group_velocity(double k, double depth) {
  double c = sqrt(WGQ_G * wgq_tanh_over_k(k < 0.0 ? 0.0 : k, depth));
  if (!(k > 0.0)) c = wgq_finite(depth) ? sqrt(WGQ_G * depth) : HUGE_VAL;
  return 0.5 * c * (1.0 + wgq_two_kd_over_sinh(k * depth));
}
static inline double wgq_tma_depth_factor(double k, double depth) {
  double x = k * depth, t;
  if (!(x < 20.0)) return 1.0;
  t = x < 1e-5 ? x * (1.0 - x * x / 3.0) : tanh(x);
  return t * t / (1.0 + wgq_two_kd_over_sinh(x));
}
static inline double wgq_pm_peak_coefficient(void) { return pow(4.0 * 0.74 / 5.0, 0.25); }
static inline void wgq_jonswap_parameters(double u, double fetch, double* alpha, double* peak) {
  double chi, developed = pow(22.0 / (wgq_pm_peak_coefficient() / 1.026), 3.0);
  *alpha = 0.0;
  *peak = 0.0;
  if (!(u > 0.0)) return;
  chi = WGQ_G * fetch / (u * u);
  if (developed < chi) chi = developed;
  *alpha = 0.076 * pow(chi, -0.22);
  *peak = 22.0 * (WGQ_G / u) * pow(chi, -1.0 / 3.0);
}
static inline double wgq_pm_spectrum(double omega, double u) {
  double r;
  if (!(omega > 0.0) || !(u > 0.0)) return 0.0;
  r = WGQ_G / (1.026 * u * omega);
  return 0.0081 * WGQ_G * WGQ_G * pow(omega, -5.0) * exp(-0.74 * r * r * r * r);
}
static inline double wgq_jonswap_spectrum(double omega, double alpha, double peak, double gamma) {
  double x, sigma, r, x4;
  if (!(omega > 0.0) || !(alpha > 0.0) || !(peak > 0.0)) return 0.0;
  x = omega / peak;
  sigma = x <= 1.0 ? 0.07 : 0.09;
  r = exp(-(x - 1.0) * (x - 1.0) / (2.0 * sigma * sigma));
  x4 = x * x * x * x;
  return alpha * WGQ_G * WGQ_G * pow(omega, -5.0) * exp(-1.25 / x4) * pow(gamma, r);
}
static inline double wgq_swell_spectrum(double omega, double height, double peak) {
  double x, x4;
  if (!(omega > 0.0) || !(height > 0.0) || !(peak > 0.0)) return 0.0;
  x = peak / omega;
  x4 = x * x * x * x;
  return (5.0 / 16.0) * height * height * x4 / omega * exp(-1.25 * x4);
}
static inline double wgq_clamp_spread(double s) { return s < 0.0 ? 0.0 : 1000.0 < s ? 1000.0 : s; }
static inline double wgq_cos2s(double theta, double s) {
  double wrapped = theta - 2.0 * WGQ_PI * nearbyint(theta / (2.0 * WGQ_PI));
  double c = cos(0.5 * wrapped);
  /* lgamma sets signgam; its arguments here are positive, so every call writes the same sign. */
  double q = exp(lgamma(s + 1.0) - lgamma(s + 0.5)) / (2.0 * sqrt(WGQ_PI));
  return q * pow(c < 0.0 ? 0.0 : c, 2.0 * s);
}
static inline double wgq_spreading(int model, double theta, double omega, double peak, double u) {
  double c, x, s;
  if (model == 0) {
    c = cos(theta);
    return c * c / WGQ_PI;
  }
  x = omega / peak;
  if (model == 1) {
    s = 11.5 * pow(peak * u / WGQ_G, -2.5);
    s = x <= 1.0 ? s * pow(x, 5.0) : s * pow(x, -2.5);
  } else if (x < 1.05) {
    s = 6.97 * pow(x, 4.06);
  } else {
    s = 9.77 * pow(x, -2.33 - 1.45 * (u * peak / WGQ_G - 1.17));
  }
  return wgq_cos2s(theta, wgq_clamp_spread(s));
}
static inline double wgq_spectrum_peak(const wgq_sea* s) {
  double alpha, peak, lw;
  if (!(s->wind_speed > 0.0)) return 0.0;
  if (s->model == 0) {
    lw = s->wind_speed * s->wind_speed / WGQ_G;
    return wgq_angular_frequency(sqrt(2.0 / 3.0) / lw, s->depth);
  }
  if (s->model == 1) return wgq_pm_peak_coefficient() * WGQ_G / (1.026 * s->wind_speed);
  wgq_jonswap_parameters(s->wind_speed, s->fetch, &alpha, &peak);
  return peak;
}
static inline double wgq_wind_sea_spectrum(const wgq_sea* s, double k) {
  double omega = wgq_angular_frequency(k, s->depth), alpha, peak, kl, e;
  if (s->model == 0) {
    if (!(k > 0.0) || !(s->wind_speed > 0.0)) return 0.0;
    kl = k * s->wind_speed * s->wind_speed / WGQ_G;
    e = WGQ_PI * s->phillips_amplitude * exp(-1.0 / (kl * kl)) *
        exp(-k * k * s->phillips_small_wave * s->phillips_small_wave) / (k * k * k);
    return e / wgq_group_velocity(k, s->depth);
  }
  if (s->model == 1) return wgq_pm_spectrum(omega, s->wind_speed);
  wgq_jonswap_parameters(s->wind_speed, s->fetch, &alpha, &peak);
  e = wgq_jonswap_spectrum(omega, alpha, peak, s->gamma);
  return s->model == 3 ? e * wgq_tma_depth_factor(k, s->depth) : e;
}
/* F(kx, kz), m^4: the wind sea and the swell along their headings. */
static inline double wgq_directional_spectrum(const wgq_sea* s, double kx, double kz) {
  double k = hypot(kx, kz), wind = 0.0, swell = 0.0, f = 0.0, cg, heading;
  if (k > 0.0) {
    cg = wgq_group_velocity(k, s->depth);
    wind = wgq_wind_sea_spectrum(s, k) * cg;
    swell = wgq_swell_spectrum(wgq_angular_frequency(k, s->depth), s->swell_height, 2.0 * WGQ_PI / s->swell_period) * cg;
    if (s->model == 3) swell *= wgq_tma_depth_factor(k, s->depth);
  }
  heading = atan2(kz, kx);
  if (wind > 0.0)
    f += wind * wgq_spreading(s->spreading, heading - s->wind_direction, wgq_angular_frequency(k, s->depth),
                              wgq_spectrum_peak(s), s->wind_speed);
  if (swell > 0.0) f += swell * wgq_cos2s(heading - s->swell_direction, s->swell_spread);
  return f / k;
}
/* PCG's four-lane hash (Jarzynski and Olano 2020), modulo 2^32. */
static inline void wgq_pcg4d_mix(uint32_t v[4]) {
  v[0] += v[1] * v[3];
  v[1] += v[2] * v[0];
  v[2] += v[0] * v[1];
  v[3] += v[1] * v[2];
}
/* Two standard normal numbers for one bin: Box-Muller on the hash of (ix, iz, cascade, seed). */
static inline void wgq_bin_gaussians(uint32_t cascade, uint32_t ix, uint32_t iz, uint32_t seed, double* re, double* im) {
  uint32_t v[4];
  double r, a;
  int i;
  v[0] = ix; v[1] = iz; v[2] = cascade; v[3] = seed;
  for (i = 0; i < 4; ++i) v[i] = v[i] * 1664525u + 1013904223u;
  wgq_pcg4d_mix(v);
  for (i = 0; i < 4; ++i) v[i] ^= v[i] >> 16u;
  wgq_pcg4d_mix(v);
  r = sqrt(-2.0 * log(((double)v[0] + 1.0) / 4294967296.0));
  a = 2.0 * WGQ_PI * ((double)v[1] / 4294967296.0);
  *re = r * cos(a);
  *im = r * sin(a);
}
/* omega as a multiple of 2 pi / T, T = 2^16 s: the bins' phases are exact 32-bit turns. */
static inline uint32_t wgq_frequency_index(double omega) {
  double n = nearbyint(omega * 65536.0 / (2.0 * WGQ_PI));
  return (uint32_t)(4294967295.0 < n ? 4294967295.0 : n);
}
/* The fraction of the loop at time t in units of 2^-32 of a loop (0 for a time not finite). */
static inline uint32_t wgq_loop_fraction(double t) {
  double loops, x;
  if (!wgq_finite(t)) return 0u;
  loops = t / 65536.0;
  x = floor((loops - floor(loops)) * 4294967296.0);
  return (uint32_t)(4294967295.0 < x ? 4294967295.0 : x);
}
/* In place: a[j] = sum over m of a[m] e^(2 pi i j m / n), n a power of two, (re, im) pairs;
 * w holds e^(2 pi i j / n) for j < n / 2 (iterative radix-2, decimation in time). */
static inline void wgq_fft(double* a, int n, const double* w) {
  int i, j = 0, bit, len, s, k;
  for (i = 1; i < n; ++i) {
    for (bit = n >> 1; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) {
      double r = a[2 * i], m = a[2 * i + 1];
      a[2 * i] = a[2 * j]; a[2 * i + 1] = a[2 * j + 1];
      a[2 * j] = r; a[2 * j + 1] = m;
    }
  }
  for (len = 2; len <= n; len <<= 1) {
    const int half = len >> 1, step = n / len;
    for (s = 0; s < n; s += len)
      for (k = 0; k < half; ++k) {
        double* u = a + 2 * (s + k);
        double* v = u + 2 * half;
        const double wr = w[2 * k * step], wi = w[2 * k * step + 1];
        const double vr = v[0] * wr - v[1] * wi, vi = v[0] * wi + v[1] * wr;
        v[0] = u[0] - vr;
        v[1] = u[1] - vi;
        u[0] += vr;
        u[1] += vi;
      }
  }
}
/* The n x n transform of a (index iz n + ix): along x, then along z through `line`. */
static inline void wgq_fft2(double* a, int n, const double* w, double* line) {
  int r, c;
  for (r = 0; r < n; ++r) wgq_fft(a + 2 * n * r, n, w);
  for (c = 0; c < n; ++c) {
    for (r = 0; r < n; ++r) {
      line[2 * r] = a[2 * (r * n + c)];
      line[2 * r + 1] = a[2 * (r * n + c) + 1];
    }
    wgq_fft(line, n, w);
    for (r = 0; r < n; ++r) {
      a[2 * (r * n + c)] = line[2 * r];
      a[2 * (r * n + c) + 1] = line[2 * r + 1];
    }
  }
}
/* One cascade's maps at loop fraction tau: the evolved spectrum h~ and its time derivative,
 * then six transforms, each of two fields' spectra packed as a + i b (both Hermitian, so
 * a's field is the real part and b's the imaginary part); `maps` gets 11 doubles a texel. */
static inline void wgq_ocean_cascade(const double* h0, const uint32_t* frequency, int n, double tile, double lambda,
                                     uint32_t tau, const double* w, double* evolved, double* work, double* line,
                                     double* maps) {
  const double dk = 2.0 * WGQ_PI / tile;
  int ix, iz, pass;
  size_t i, count = (size_t)n * (size_t)n;
  for (iz = 0; iz < n; ++iz)
    for (ix = 0; ix < n; ++ix) {
      const size_t b = (size_t)iz * n + ix, m = (size_t)((n - iz) % n) * n + (size_t)((n - ix) % n);
      const double phase = 2.0 * WGQ_PI * ((double)(uint32_t)(frequency[b] * tau) / 4294967296.0);
      const double c = cos(phase), s = sin(phase), omega = frequency[b] * (2.0 * WGQ_PI / 65536.0);
      /* h0(k) e^(-i phase) and conj(h0(-k)) e^(i phase) */
      const double ar = h0[2 * b] * c + h0[2 * b + 1] * s, ai = h0[2 * b + 1] * c - h0[2 * b] * s;
      const double br = h0[2 * m] * c + h0[2 * m + 1] * s, bi = h0[2 * m] * s - h0[2 * m + 1] * c;
      evolved[4 * b] = ar + br;
      evolved[4 * b + 1] = ai + bi;
      evolved[4 * b + 2] = -omega * (bi - ai); /* i omega (b - a) */
      evolved[4 * b + 3] = omega * (br - ar);
    }
  for (pass = 0; pass < 6; ++pass) {
    for (iz = 0; iz < n; ++iz)
      for (ix = 0; ix < n; ++ix) {
        const size_t b = (size_t)iz * n + ix;
        const int sx = ix < n / 2 ? ix : ix - n, sz = iz < n / 2 ? iz : iz - n;
        const double kx = dk * sx, kz = dk * sz, k = hypot(kx, kz);
        const double ux = k > 0.0 ? kx / k : 0.0, uz = k > 0.0 ? kz / k : 0.0;
        const double hr = evolved[4 * b], hi = evolved[4 * b + 1], vr = evolved[4 * b + 2], vi = evolved[4 * b + 3];
        double ar, ai, br, bi;
        switch (pass) {
          case 0: ar = -hi * ux; ai = hr * ux; br = hr; bi = hi; break;               /* Dx, h */
          case 1: ar = -hi * uz; ai = hr * uz; br = -kx * uz * hr; bi = -kx * uz * hi; break; /* Dz, dDx/dz */
          case 2: ar = -hi * kx; ai = hr * kx; br = -hi * kz; bi = hr * kz; break;    /* dh/dx, dh/dz */
          case 3: ar = -kx * ux * hr; ai = -kx * ux * hi; br = -kz * uz * hr; bi = -kz * uz * hi; break; /* dDx/dx, dDz/dz */
          case 4: ar = -vi * ux; ai = vr * ux; br = vr; bi = vi; break;               /* d/dt of Dx, h */
          default: ar = -vi * uz; ai = vr * uz; br = 0.0; bi = 0.0; break;            /* d/dt of Dz */
        }
        work[2 * b] = ar - bi;
        work[2 * b + 1] = ai + br;
      }
    wgq_fft2(work, n, w, line);
    for (i = 0; i < count; ++i) {
      double* t = maps + 11 * i;
      const double a = work[2 * i], b = work[2 * i + 1];
      switch (pass) {
        case 0: t[0] = lambda * a; t[1] = b; break;
        case 1: t[2] = lambda * a; t[3] = lambda * b; break;
        case 2: t[4] = a; t[5] = b; break;
        case 3: t[6] = lambda * a; t[7] = lambda * b; break;
        case 4: t[8] = lambda * a; t[9] = b; break;
        default: t[10] = lambda * a; break;
      }
    }
  }
}
/* Map channels at the world point: the 4 x 4 texels around (x, z) of an n x n map of tile L
 * (texelsPerMetre n / L rounded to float, as the shader's literal), bicubic (Catmull-Rom) as
 * wg_ocean_map_cubic, added to out times weight. A point whose texel coordinate is not finite
 * adds nothing. */
static inline void wgq_cubic_weights(double t, double w[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = t2 - 0.5 * (t + t3);
  w[1] = 1.0 + 1.5 * t3 - 2.5 * t2;
  w[2] = 0.5 * t + 2.0 * t2 - 1.5 * t3;
  w[3] = 0.5 * (t3 - t2);
}
static inline void wgq_ocean_read(const double* maps, int n, double texelsPerMetre, double weight, double x, double z,
                                  double* out) {
  const double u = x * texelsPerMetre, v = z * texelsPerMetre;
  double bu, bv, wu, wv, wx[4], wz[4];
  int ax, az, i, j, f;
  if (!(wgq_finite(u) && wgq_finite(v))) return;
  bu = floor(u);
  bv = floor(v);
  wgq_cubic_weights(u - bu, wx);
  wgq_cubic_weights(v - bv, wz);
  wu = bu - n * floor(bu / n);
  wv = bv - n * floor(bv / n);
  ax = (wu >= 0.0 && wu < n ? (int)wu : 0) & (n - 1);
  az = (wv >= 0.0 && wv < n ? (int)wv : 0) & (n - 1);
  for (f = 0; f < 11; ++f) {
    double sum = 0.0;
    for (j = 0; j < 4; ++j) {
      const size_t row = (size_t)((az + j + n - 1) & (n - 1)) * n;
      double r = 0.0;
      for (i = 0; i < 4; ++i) r += wx[i] * maps[11 * (row + (size_t)((ax + i + n - 1) & (n - 1))) + f];
      sum += wz[j] * r;
    }
    out[f] += weight * sum;
  }
}
#endif
)";
}

std::string oceanCNumber(double x) { return numberLiteral(x, HeaderLanguage::C); }

// Where each cascade's texels begin in the state's flat arrays (cascade c's N_c^2 texels
// follow cascade c - 1's), the texel total, and the largest N (the scratch arrays' size).
struct QueryOceanLayout {
  std::vector<int> size;
  std::vector<size_t> first;       // texel offset of each cascade
  std::vector<size_t> firstTwiddle;  // offset of each cascade's N_c twiddle doubles
  size_t texels = 0, twiddles = 0;
  int largest = 0;
};
QueryOceanLayout queryOceanLayout(const ocean::OceanSettings& s) {
  QueryOceanLayout l;
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c) {
    const int n = ocean::cascadeResolution(s.cascades, c);
    l.size.push_back(n);
    l.first.push_back(l.texels);
    l.firstTwiddle.push_back(l.twiddles);
    l.texels += static_cast<size_t>(n) * n;
    l.twiddles += static_cast<size_t>(n);
    l.largest = std::max(l.largest, n);
  }
  return l;
}

}  // namespace

size_t queryOceanStateBytes(const ocean::OceanSettings& s) {
  const QueryOceanLayout l = queryOceanLayout(s);
  const size_t n = static_cast<size_t>(l.largest);
  // time, camera, fade; h0, frequency, maps over every cascade's texels; twiddles; evolved,
  // work, line at the largest N.
  return 8 * 4 + 8 + l.texels * (2 * 8 + 4 + kQueryOceanChannels * 8) + l.twiddles * 8 + n * n * 4 * 8 + n * n * 2 * 8 +
         2 * n * 8;
}

std::string queryOceanC(const std::string& g, const ocean::OceanSettings& s) {
  const QueryOceanLayout layout = queryOceanLayout(s);
  const int n = layout.largest;
  const size_t cascades = s.cascades.tileLengths.size();
  const std::string C = std::to_string(cascades), N2 = std::to_string(static_cast<size_t>(n) * n);
  const std::string T = std::to_string(layout.texels);
  auto list = [&](auto value) {
    std::string out;
    for (size_t c = 0; c < cascades; ++c) out += (c ? ", " : "") + value(c);
    return out;
  };
  std::string sizes;
  for (size_t c = 0; c < cascades; ++c) sizes += (c ? ", " : "") + std::to_string(layout.size[c]);
  // Each cascade's N, and where its texels and its twiddles begin in the flat arrays (the
  // twiddles' offsets only where the function reads them: no unused static in the text).
  auto layoutTables = [&](bool twiddles) {
    std::string t = "  /* each cascade's N, and where its texels" + std::string(twiddles ? " and twiddles" : "") +
                    " begin in the flat arrays */\n";
    t += "  static const int size[" + C + "] = {" + sizes + "};\n";
    t += "  static const size_t first[" + C + "] = {" + list([&](size_t c) { return std::to_string(layout.first[c]); }) + "};\n";
    if (twiddles)
      t += "  static const size_t firstTwiddle[" + C + "] = {" +
           list([&](size_t c) { return std::to_string(layout.firstTwiddle[c]); }) + "};\n";
    return t;
  };
  const auto bands = ocean::cascadeBands(s.cascades);
  const ocean::SpectrumSettings& p = s.spectrum;
  std::string h = oceanCHelpers();
  h += "\n/* The spectral ocean's state: fill it with " + g + "ocean_init, bring it to a time with\n";
  h += " * " + g + "ocean_update (which writes it), then query it from any number of threads (which only\n";
  h += " * read it). About " + std::to_string((queryOceanStateBytes(s) + (1u << 19)) >> 20) + " MiB (" + C +
       " cascades of " + sizes + " texels a side): give it static or heap storage, not the stack. */\n";
  h += "typedef struct " + g + "ocean {\n";
  h += "  double time;      /* the time of the maps, as update() was given it */\n";
  h += "  double camera[3]; /* where the readers' fade distances are measured from */\n";
  h += "  int fade;         /* 0 when update() was given no camera: every cascade at full weight */\n";
  h += "  /* per cascade c its N_c x N_c texels, one cascade after another (c's begin after c - 1's) */\n";
  h += "  double h0[" + T + " * 2];        /* h0(k), (re, im) at iz N_c + ix, metres */\n";
  h += "  uint32_t frequency[" + T + "];   /* omega = frequency 2 pi / 2^16 s */\n";
  h += "  double maps[" + T + " * 11];     /* per texel (jz N_c + jx): lDx, h, lDz, lDxz, hx, hz, lDxx, lDzz, and d/dt of lDx, h, lDz */\n";
  h += "  double twiddle[" + std::to_string(layout.twiddles) + "];  /* per cascade e^(2 pi i j / N_c), j < N_c / 2 */\n";
  h += "  double evolved[" + N2 + " * 4];\n  double work[" + N2 + " * 2];\n  double line[" +
       std::to_string(2 * n) + "];\n} " + g + "ocean;\n\n";

  h += "static inline void " + g + "ocean_update(" + g + "ocean* o, double t, const double camera[3]);\n\n";
  h += "/* Each cascade's initial amplitudes from the ocean_spectrum's options (the GPU's h0, bit for\n";
  h += " * bit), then the maps at t = 0 with no camera. */\n";
  h += "static inline void " + g + "ocean_init(" + g + "ocean* o) {\n";
  h += "  static const wgq_sea sea = {" + std::to_string(static_cast<int>(p.model)) + ", " +
       std::to_string(static_cast<int>(p.spreading)) + ", " + oceanCNumber(p.windSpeed) + ", " + oceanCNumber(p.windDirection) + ", " +
       oceanCNumber(p.fetch) + ", " + oceanCNumber(p.depth) + ", " + oceanCNumber(p.gamma) + ", " + oceanCNumber(p.phillipsAmplitude) + ", " +
       oceanCNumber(p.phillipsSmallWave) + ",\n                                " + oceanCNumber(p.swell.height) + ", " +
       oceanCNumber(p.swell.period) + ", " + oceanCNumber(p.swell.direction) + ", " + oceanCNumber(p.swell.spread) + "};\n";
  h += "  static const double tile[" + C + "] = {" + list([&](size_t c) { return oceanCNumber(s.cascades.tileLengths[c]); }) + "};\n";
  h += "  /* the wavenumbers |k| in [low, high) each cascade owns */\n";
  h += "  static const double low[" + C + "] = {" + list([&](size_t c) { return oceanCNumber(bands[c].low); }) + "};\n";
  h += "  static const double high[" + C + "] = {" + list([&](size_t c) { return oceanCNumber(bands[c].high); }) + "};\n";
  h += "  const uint32_t seed = " + std::to_string(s.cascades.seed) + "u;\n";
  h += layoutTables(true);
  h += "  int c, ix, iz, j;\n";
  h += "  for (c = 0; c < " + C + "; ++c) {\n";
  h += "    const double dk = 2.0 * WGQ_PI / tile[c];\n";
  h += "    const int n = size[c];\n";
  h += "    double* h0 = o->h0 + 2 * first[c];\n";
  h += "    double* w = o->twiddle + firstTwiddle[c];\n";
  h += "    uint32_t* frequency = o->frequency + first[c];\n";
  h += "    for (j = 0; j < n / 2; ++j) {\n";
  h += "      w[2 * j] = cos(2.0 * WGQ_PI * j / n);\n      w[2 * j + 1] = sin(2.0 * WGQ_PI * j / n);\n    }\n";
  h += "    for (iz = 0; iz < n; ++iz)\n      for (ix = 0; ix < n; ++ix) {\n";
  h += "        const size_t i = (size_t)iz * n + ix;\n";
  h += "        const int sx = ix < n / 2 ? ix : ix - n, sz = iz < n / 2 ? iz : iz - n;\n";
  h += "        const double kx = dk * sx, kz = dk * sz, k = hypot(kx, kz);\n";
  h += "        double variance, re, im;\n";
  h += "        frequency[i] = wgq_frequency_index(wgq_angular_frequency(k, sea.depth));\n";
  h += "        h0[2 * i] = h0[2 * i + 1] = 0.0;\n";
  h += "        /* the Nyquist row and column have no mirror; the mean is 0 */\n";
  h += "        if (ix == n / 2 || iz == n / 2 || !(k > 0.0) || k < low[c] || !(k < high[c])) continue;\n";
  h += "        variance = wgq_directional_spectrum(&sea, kx, kz) * dk * dk;\n";
  h += "        wgq_bin_gaussians((uint32_t)c, (uint32_t)sx, (uint32_t)sz, seed, &re, &im);\n";
  h += "        h0[2 * i] = re * (0.5 * sqrt(variance));\n";
  h += "        h0[2 * i + 1] = im * (0.5 * sqrt(variance));\n      }\n  }\n";
  h += "  " + g + "ocean_update(o, 0.0, NULL);\n}\n\n";

  h += "/* The maps at time t seen from `camera` (NULL: no fade, every cascade at full weight). The\n";
  h += " * only function that writes the state. */\n";
  h += "static inline void " + g + "ocean_update(" + g + "ocean* o, double t, const double camera[3]) {\n";
  h += "  static const double tile[" + C + "] = {" + list([&](size_t c) { return oceanCNumber(s.cascades.tileLengths[c]); }) + "};\n";
  h += layoutTables(true);
  h += "  const uint32_t tau = wgq_loop_fraction(t);\n  int c;\n";
  h += "  o->time = t;\n  o->fade = camera != NULL;\n";
  h += "  for (c = 0; c < 3; ++c) o->camera[c] = camera ? camera[c] : 0.0;\n";
  h += "  for (c = 0; c < " + C + "; ++c)\n";
  h += "    wgq_ocean_cascade(o->h0 + 2 * first[c], o->frequency + first[c], size[c], tile[c], " +
       oceanCNumber(s.cascades.choppiness) +
       ", tau, o->twiddle + firstTwiddle[c], o->evolved, o->work, o->line, o->maps + 11 * first[c]);\n}\n\n";

  h += "/* The cascades' map channels at the world point (x, z), cascade c weighted by w[c], summed. */\n";
  h += "static inline void " + g + "ocean_sample(const " + g + "ocean* o, double x, double z, const double w[" + C +
       "], double out[11]) {\n";
  h += "  /* N_c / L per cascade, rounded to float as the shader's literal */\n";
  h += "  static const double texelsPerMetre[" + C + "] = {" +
       list([&](size_t c) { return oceanCNumber(static_cast<float>(layout.size[c] / s.cascades.tileLengths[c])); }) + "};\n";
  h += layoutTables(false);
  h += "  int c;\n  for (c = 0; c < 11; ++c) out[c] = 0.0;\n";
  h += "  for (c = 0; c < " + C + "; ++c) wgq_ocean_read(o->maps + 11 * first[c], size[c], texelsPerMetre[c], w[c], x, z, out);\n}\n\n";
  return h;
}

}  // namespace wg
