// The spectral ocean of a surface query, JavaScript form (codegen/query_ocean.h): the C
// form's arithmetic in the same order, with 32-bit unsigned integer steps by Math.imul and
// `>>> 0`, and lgamma (which JavaScript lacks) by Lanczos' series.
#include <algorithm>
#include <string>

#include "codegen/query_ocean.h"

namespace wg {

const char* queryOceanJsHelpers() {
  return R"(const WGQ_PI = 3.141592653589793, WGQ_G = 9.81;
const hypot = Math.hypot;
// ln Gamma(x) for x >= 0.5 (Lanczos, g = 7, n = 9): within ~1e-15 relative of C's lgamma for
// the spreading exponents an ocean_spectrum allows.
const WGQ_LANCZOS = [0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
  -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6, 1.5056327351493116e-7];
const wgq_lgamma = (x) => {
  const y = x - 1.0, t = y + 7.5;
  let a = WGQ_LANCZOS[0];
  for (let i = 1; i < 9; ++i) a += WGQ_LANCZOS[i] / (y + i);
  return 0.5 * log(2.0 * WGQ_PI) + (y + 0.5) * log(t) - t + log(a);
};
const wgq_tanh_over_k = (k, depth) => {
  const x = k * depth;
  if (!(x < 20.0)) return 1.0 / k;
  if (x < 1e-5) return depth * (1.0 - (x * x) / 3.0);
  return tanh(x) / k;
};
const wgq_two_kd_over_sinh = (x) => {
  if (!(x < 20.0)) return 0.0;
  const y = 2.0 * x;
  if (y < 1e-5) return 1.0 - (y * y) / 6.0;
  return y / sinh(y);
};
const wgq_angular_frequency = (k, depth) => (k > 0.0 ? sqrt(WGQ_G * k * k * wgq_tanh_over_k(k, depth)) : 0.0);
const wgq_group_velocity = (k, depth) => {
  let c = sqrt(WGQ_G * wgq_tanh_over_k(k < 0.0 ? 0.0 : k, depth));
  if (!(k > 0.0)) c = wgq_finite(depth) ? sqrt(WGQ_G * depth) : Infinity;
  return 0.5 * c * (1.0 + wgq_two_kd_over_sinh(k * depth));
};
const wgq_tma_depth_factor = (k, depth) => {
  const x = k * depth;
  if (!(x < 20.0)) return 1.0;
  const t = x < 1e-5 ? x * (1.0 - (x * x) / 3.0) : tanh(x);
  return (t * t) / (1.0 + wgq_two_kd_over_sinh(x));
};
const wgq_pm_peak_coefficient = () => pow((4.0 * 0.74) / 5.0, 0.25);
const wgq_jonswap_parameters = (u, fetch) => {
  const developed = pow(22.0 / (wgq_pm_peak_coefficient() / 1.026), 3.0);
  if (!(u > 0.0)) return [0.0, 0.0];
  let chi = (WGQ_G * fetch) / (u * u);
  if (developed < chi) chi = developed;
  return [0.076 * pow(chi, -0.22), 22.0 * (WGQ_G / u) * pow(chi, -1.0 / 3.0)];
};
const wgq_pm_spectrum = (omega, u) => {
  if (!(omega > 0.0) || !(u > 0.0)) return 0.0;
  const r = WGQ_G / (1.026 * u * omega);
  return 0.0081 * WGQ_G * WGQ_G * pow(omega, -5.0) * exp(-0.74 * r * r * r * r);
};
const wgq_jonswap_spectrum = (omega, alpha, peak, gamma) => {
  if (!(omega > 0.0) || !(alpha > 0.0) || !(peak > 0.0)) return 0.0;
  const x = omega / peak;
  const sigma = x <= 1.0 ? 0.07 : 0.09;
  const r = exp((-(x - 1.0) * (x - 1.0)) / (2.0 * sigma * sigma));
  const x4 = x * x * x * x;
  return alpha * WGQ_G * WGQ_G * pow(omega, -5.0) * exp(-1.25 / x4) * pow(gamma, r);
};
const wgq_swell_spectrum = (omega, height, peak) => {
  if (!(omega > 0.0) || !(height > 0.0) || !(peak > 0.0)) return 0.0;
  const x = peak / omega;
  const x4 = x * x * x * x;
  return (((5.0 / 16.0) * height * height * x4) / omega) * exp(-1.25 * x4);
};
const wgq_clamp_spread = (s) => (s < 0.0 ? 0.0 : 1000.0 < s ? 1000.0 : s);
const wgq_cos2s = (theta, s) => {
  const wrapped = theta - 2.0 * WGQ_PI * nearbyint(theta / (2.0 * WGQ_PI));
  const c = cos(0.5 * wrapped);
  const q = exp(wgq_lgamma(s + 1.0) - wgq_lgamma(s + 0.5)) / (2.0 * sqrt(WGQ_PI));
  return q * pow(c < 0.0 ? 0.0 : c, 2.0 * s);
};
const wgq_spreading = (model, theta, omega, peak, u) => {
  if (model === 0) {
    const c = cos(theta);
    return (c * c) / WGQ_PI;
  }
  const x = omega / peak;
  let s;
  if (model === 1) {
    s = 11.5 * pow((peak * u) / WGQ_G, -2.5);
    s = x <= 1.0 ? s * pow(x, 5.0) : s * pow(x, -2.5);
  } else if (x < 1.05) {
    s = 6.97 * pow(x, 4.06);
  } else {
    s = 9.77 * pow(x, -2.33 - 1.45 * ((u * peak) / WGQ_G - 1.17));
  }
  return wgq_cos2s(theta, wgq_clamp_spread(s));
};
const wgq_spectrum_peak = (s) => {
  if (!(s.wind_speed > 0.0)) return 0.0;
  if (s.model === 0) {
    const lw = (s.wind_speed * s.wind_speed) / WGQ_G;
    return wgq_angular_frequency(sqrt(2.0 / 3.0) / lw, s.depth);
  }
  if (s.model === 1) return (wgq_pm_peak_coefficient() * WGQ_G) / (1.026 * s.wind_speed);
  return wgq_jonswap_parameters(s.wind_speed, s.fetch)[1];
};
const wgq_wind_sea_spectrum = (s, k) => {
  const omega = wgq_angular_frequency(k, s.depth);
  if (s.model === 0) {
    if (!(k > 0.0) || !(s.wind_speed > 0.0)) return 0.0;
    const kl = (k * s.wind_speed * s.wind_speed) / WGQ_G;
    const e = (WGQ_PI * s.phillips_amplitude * exp(-1.0 / (kl * kl)) *
               exp(-k * k * s.phillips_small_wave * s.phillips_small_wave)) / (k * k * k);
    return e / wgq_group_velocity(k, s.depth);
  }
  if (s.model === 1) return wgq_pm_spectrum(omega, s.wind_speed);
  const [alpha, peak] = wgq_jonswap_parameters(s.wind_speed, s.fetch);
  const e = wgq_jonswap_spectrum(omega, alpha, peak, s.gamma);
  return s.model === 3 ? e * wgq_tma_depth_factor(k, s.depth) : e;
};
const wgq_directional_spectrum = (s, kx, kz) => {
  const k = hypot(kx, kz);
  let wind = 0.0, swell = 0.0, f = 0.0;
  if (k > 0.0) {
    const cg = wgq_group_velocity(k, s.depth);
    wind = wgq_wind_sea_spectrum(s, k) * cg;
    swell = wgq_swell_spectrum(wgq_angular_frequency(k, s.depth), s.swell_height, (2.0 * WGQ_PI) / s.swell_period) * cg;
    if (s.model === 3) swell *= wgq_tma_depth_factor(k, s.depth);
  }
  const heading = atan2(kz, kx);
  if (wind > 0.0)
    f += wind * wgq_spreading(s.spreading, heading - s.wind_direction, wgq_angular_frequency(k, s.depth),
                              wgq_spectrum_peak(s), s.wind_speed);
  if (swell > 0.0) f += swell * wgq_cos2s(heading - s.swell_direction, s.swell_spread);
  return f / k;
};
const wgq_pcg4d_mix = (v) => {
  v[0] = (v[0] + Math.imul(v[1], v[3])) >>> 0;
  v[1] = (v[1] + Math.imul(v[2], v[0])) >>> 0;
  v[2] = (v[2] + Math.imul(v[0], v[1])) >>> 0;
  v[3] = (v[3] + Math.imul(v[1], v[2])) >>> 0;
};
const wgq_bin_gaussians = (cascade, ix, iz, seed) => {
  const v = [ix >>> 0, iz >>> 0, cascade >>> 0, seed >>> 0];
  for (let i = 0; i < 4; ++i) v[i] = (Math.imul(v[i], 1664525) + 1013904223) >>> 0;
  wgq_pcg4d_mix(v);
  for (let i = 0; i < 4; ++i) v[i] = (v[i] ^ (v[i] >>> 16)) >>> 0;
  wgq_pcg4d_mix(v);
  const r = sqrt(-2.0 * log((v[0] + 1.0) / 4294967296.0));
  const a = 2.0 * WGQ_PI * (v[1] / 4294967296.0);
  return [r * cos(a), r * sin(a)];
};
const wgq_frequency_index = (omega) => {
  const n = nearbyint((omega * 65536.0) / (2.0 * WGQ_PI));
  return 4294967295.0 < n ? 4294967295 : n;
};
const wgq_loop_fraction = (t) => {
  if (!wgq_finite(t)) return 0;
  const loops = t / 65536.0;
  const x = floor((loops - floor(loops)) * 4294967296.0);
  return 4294967295.0 < x ? 4294967295 : x;
};
const wgq_fft = (a, offset, n, w) => {
  for (let i = 1, j = 0; i < n; ++i) {
    let bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) {
      const p = offset + 2 * i, q = offset + 2 * j;
      const r = a[p], m = a[p + 1];
      a[p] = a[q]; a[p + 1] = a[q + 1];
      a[q] = r; a[q + 1] = m;
    }
  }
  for (let len = 2; len <= n; len <<= 1) {
    const half = len >> 1, step = n / len;
    for (let s = 0; s < n; s += len)
      for (let k = 0; k < half; ++k) {
        const u = offset + 2 * (s + k), v = u + 2 * half;
        const wr = w[2 * k * step], wi = w[2 * k * step + 1];
        const vr = a[v] * wr - a[v + 1] * wi, vi = a[v] * wi + a[v + 1] * wr;
        a[v] = a[u] - vr;
        a[v + 1] = a[u + 1] - vi;
        a[u] += vr;
        a[u + 1] += vi;
      }
  }
};
const wgq_fft2 = (a, n, w, line) => {
  for (let r = 0; r < n; ++r) wgq_fft(a, 2 * n * r, n, w);
  for (let c = 0; c < n; ++c) {
    for (let r = 0; r < n; ++r) {
      line[2 * r] = a[2 * (r * n + c)];
      line[2 * r + 1] = a[2 * (r * n + c) + 1];
    }
    wgq_fft(line, 0, n, w);
    for (let r = 0; r < n; ++r) {
      a[2 * (r * n + c)] = line[2 * r];
      a[2 * (r * n + c) + 1] = line[2 * r + 1];
    }
  }
};
const wgq_ocean_cascade = (h0, frequency, n, tile, lambda, tau, w, evolved, work, line, maps) => {
  const dk = (2.0 * WGQ_PI) / tile, count = n * n;
  for (let iz = 0; iz < n; ++iz)
    for (let ix = 0; ix < n; ++ix) {
      const b = iz * n + ix, m = ((n - iz) % n) * n + ((n - ix) % n);
      const phase = 2.0 * WGQ_PI * ((Math.imul(frequency[b], tau) >>> 0) / 4294967296.0);
      const c = cos(phase), s = sin(phase), omega = frequency[b] * ((2.0 * WGQ_PI) / 65536.0);
      const ar = h0[2 * b] * c + h0[2 * b + 1] * s, ai = h0[2 * b + 1] * c - h0[2 * b] * s;
      const br = h0[2 * m] * c + h0[2 * m + 1] * s, bi = h0[2 * m] * s - h0[2 * m + 1] * c;
      evolved[4 * b] = ar + br;
      evolved[4 * b + 1] = ai + bi;
      evolved[4 * b + 2] = -omega * (bi - ai);
      evolved[4 * b + 3] = omega * (br - ar);
    }
  for (let pass = 0; pass < 6; ++pass) {
    for (let iz = 0; iz < n; ++iz)
      for (let ix = 0; ix < n; ++ix) {
        const b = iz * n + ix;
        const sx = ix < n / 2 ? ix : ix - n, sz = iz < n / 2 ? iz : iz - n;
        const kx = dk * sx, kz = dk * sz, k = hypot(kx, kz);
        const ux = k > 0.0 ? kx / k : 0.0, uz = k > 0.0 ? kz / k : 0.0;
        const hr = evolved[4 * b], hi = evolved[4 * b + 1], vr = evolved[4 * b + 2], vi = evolved[4 * b + 3];
        let ar, ai, br, bi;
        switch (pass) {
          case 0: ar = -hi * ux; ai = hr * ux; br = hr; bi = hi; break;
          case 1: ar = -hi * uz; ai = hr * uz; br = -kx * uz * hr; bi = -kx * uz * hi; break;
          case 2: ar = -hi * kx; ai = hr * kx; br = -hi * kz; bi = hr * kz; break;
          case 3: ar = -kx * ux * hr; ai = -kx * ux * hi; br = -kz * uz * hr; bi = -kz * uz * hi; break;
          case 4: ar = -vi * ux; ai = vr * ux; br = vr; bi = vi; break;
          default: ar = -vi * uz; ai = vr * uz; br = 0.0; bi = 0.0; break;
        }
        work[2 * b] = ar - bi;
        work[2 * b + 1] = ai + br;
      }
    wgq_fft2(work, n, w, line);
    for (let i = 0; i < count; ++i) {
      const t = 11 * i, a = work[2 * i], b = work[2 * i + 1];
      switch (pass) {
        case 0: maps[t] = lambda * a; maps[t + 1] = b; break;
        case 1: maps[t + 2] = lambda * a; maps[t + 3] = lambda * b; break;
        case 2: maps[t + 4] = a; maps[t + 5] = b; break;
        case 3: maps[t + 6] = lambda * a; maps[t + 7] = lambda * b; break;
        case 4: maps[t + 8] = lambda * a; maps[t + 9] = b; break;
        default: maps[t + 10] = lambda * a; break;
      }
    }
  }
};
// Catmull-Rom's weights for the fraction t, as wg_ocean_map_cubic's; the read is bicubic
// between the 4 x 4 texels around the point, as the vertex shader reads.
const wgq_cubic_weights = (t) => {
  const t2 = t * t, t3 = t2 * t;
  return [t2 - 0.5 * (t + t3), 1.0 + 1.5 * t3 - 2.5 * t2, 0.5 * t + 2.0 * t2 - 1.5 * t3, 0.5 * (t3 - t2)];
};
const wgq_ocean_read = (maps, n, texelsPerMetre, weight, x, z, out) => {
  const u = x * texelsPerMetre, v = z * texelsPerMetre;
  if (!(wgq_finite(u) && wgq_finite(v))) return;
  const bu = floor(u), bv = floor(v);
  const wx = wgq_cubic_weights(u - bu), wz = wgq_cubic_weights(v - bv);
  const wu = bu - n * floor(bu / n), wv = bv - n * floor(bv / n);
  const ax = (wu >= 0.0 && wu < n ? wu : 0) & (n - 1), az = (wv >= 0.0 && wv < n ? wv : 0) & (n - 1);
  for (let f = 0; f < 11; ++f) {
    let sum = 0.0;
    for (let j = 0; j < 4; ++j) {
      const row = ((az + j + n - 1) & (n - 1)) * n;
      let r = 0.0;
      for (let i = 0; i < 4; ++i) r += wx[i] * maps[11 * (row + ((ax + i + n - 1) & (n - 1))) + f];
      sum += wz[j] * r;
    }
    out[f] += weight * sum;
  }
};
)";
}

namespace {

std::string oceanJsNumber(double x) { return numberLiteral(x, HeaderLanguage::JavaScript); }

}  // namespace

std::string queryOceanSpectraJs(const std::string& name, const ocean::OceanSettings& s) {
  const size_t cascades = s.cascades.tileLengths.size();
  auto list = [&](auto value) {
    std::string out;
    for (size_t c = 0; c < cascades; ++c) out += (c ? ", " : "") + value(c);
    return "[" + out + "]";
  };
  const auto bands = ocean::cascadeBands(s.cascades);
  const ocean::SpectrumSettings& p = s.spectrum;
  std::string m;
  m += "// Each cascade's initial amplitudes h0 (re, im a bin) and frequency indices, drawn from the\n";
  m += "// ocean_spectrum's options with its counter-based Gaussian numbers.\n";
  m += "function " + name + "() {\n";
  m += "  const sea = {model: " + std::to_string(static_cast<int>(p.model)) +
       ", spreading: " + std::to_string(static_cast<int>(p.spreading)) + ", wind_speed: " + oceanJsNumber(p.windSpeed) +
       ", wind_direction: " + oceanJsNumber(p.windDirection) + ", fetch: " + oceanJsNumber(p.fetch) + ", depth: " + oceanJsNumber(p.depth) +
       ",\n    gamma: " + oceanJsNumber(p.gamma) + ", phillips_amplitude: " + oceanJsNumber(p.phillipsAmplitude) +
       ", phillips_small_wave: " + oceanJsNumber(p.phillipsSmallWave) + ", swell_height: " + oceanJsNumber(p.swell.height) +
       ", swell_period: " + oceanJsNumber(p.swell.period) + ",\n    swell_direction: " + oceanJsNumber(p.swell.direction) +
       ", swell_spread: " + oceanJsNumber(p.swell.spread) + "};\n";
  m += "  const tile = " + list([&](size_t c) { return oceanJsNumber(s.cascades.tileLengths[c]); }) + ";\n";
  m += "  const low = " + list([&](size_t c) { return oceanJsNumber(bands[c].low); }) + ";\n";
  m += "  const high = " + list([&](size_t c) { return oceanJsNumber(bands[c].high); }) + ";\n";
  m += "  const size = " + list([&](size_t c) { return std::to_string(ocean::cascadeResolution(s.cascades, c)); }) + ";\n";
  m += "  const seed = " + std::to_string(s.cascades.seed) + ";\n";
  m += "  const spectra = {h0: [], frequency: []};\n";
  m += "  for (let c = 0; c < " + std::to_string(cascades) + "; ++c) {\n";
  m += "    const dk = (2.0 * WGQ_PI) / tile[c], n = size[c];\n";
  m += "    const h0 = new Float64Array(n * n * 2), frequency = new Uint32Array(n * n);\n";
  m += "    for (let iz = 0; iz < n; ++iz)\n      for (let ix = 0; ix < n; ++ix) {\n";
  m += "        const i = iz * n + ix;\n";
  m += "        const sx = ix < n / 2 ? ix : ix - n, sz = iz < n / 2 ? iz : iz - n;\n";
  m += "        const kx = dk * sx, kz = dk * sz, k = hypot(kx, kz);\n";
  m += "        frequency[i] = wgq_frequency_index(wgq_angular_frequency(k, sea.depth));\n";
  m += "        if (ix === n / 2 || iz === n / 2 || !(k > 0.0) || k < low[c] || !(k < high[c])) continue;\n";
  m += "        const variance = wgq_directional_spectrum(sea, kx, kz) * dk * dk;\n";
  m += "        const [re, im] = wgq_bin_gaussians(c, sx, sz, seed);\n";
  m += "        h0[2 * i] = re * (0.5 * sqrt(variance));\n        h0[2 * i + 1] = im * (0.5 * sqrt(variance));\n      }\n";
  m += "    spectra.h0.push(h0);\n    spectra.frequency.push(frequency);\n  }\n";
  m += "  return spectra;\n}\n\n";
  return m;
}

std::string queryOceanJs(const std::string& g, const ocean::OceanSettings& s) {
  const size_t cascades = s.cascades.tileLengths.size();
  auto size = [&](size_t c) { return ocean::cascadeResolution(s.cascades, c); };
  int largest = 0;  // the scratch arrays' N: each cascade uses the first N^2 of them
  for (size_t c = 0; c < cascades; ++c) largest = std::max(largest, size(c));
  const std::string C = std::to_string(cascades), N = std::to_string(largest);
  auto list = [&](auto value) {
    std::string out;
    for (size_t c = 0; c < cascades; ++c) out += (c ? ", " : "") + value(c);
    return "[" + out + "]";
  };
  std::string m = queryOceanJsHelpers();
  m += "\nconst " + g + "ocean_tile = " + list([&](size_t c) { return oceanJsNumber(s.cascades.tileLengths[c]); }) + ";\n";
  m += "const " + g + "ocean_size = " + list([&](size_t c) { return std::to_string(size(c)); }) + ";\n\n";
  m += queryOceanSpectraJs(g + "ocean_spectra", s);
  m += "// A new ocean state (or `o` filled): each cascade's initial amplitudes from the ocean_spectrum's\n";
  m += "// options, then the maps at t = 0 with no camera. Its arrays: h0, frequency, maps and twiddles per\n";
  m += "// cascade (maps: 11 numbers a texel, as the C header's), each on the cascade's own N x N grid.\n";
  m += "export function " + g + "ocean_init(o = Object.create(null)) {\n";
  m += "  const n = " + N + ", spectra = " + g + "ocean_spectra();\n";
  m += "  o.time = 0.0;\n  o.camera = [0.0, 0.0, 0.0];\n  o.fade = 0;\n";
  m += "  o.h0 = spectra.h0;\n  o.frequency = spectra.frequency;\n  o.maps = [];\n  o.twiddle = [];\n";
  m += "  o.evolved = new Float64Array(n * n * 4);\n";
  m += "  o.work = new Float64Array(n * n * 2);\n  o.line = new Float64Array(2 * n);\n";
  m += "  for (let c = 0; c < " + C + "; ++c) {\n";
  m += "    const nc = " + g + "ocean_size[c], w = new Float64Array(nc);\n";
  m += "    for (let j = 0; j < nc / 2; ++j) {\n";
  m += "      w[2 * j] = cos((2.0 * WGQ_PI * j) / nc);\n      w[2 * j + 1] = sin((2.0 * WGQ_PI * j) / nc);\n    }\n";
  m += "    o.twiddle.push(w);\n    o.maps.push(new Float64Array(nc * nc * 11));\n  }\n";
  m += "  " + g + "ocean_update(o, 0.0, null);\n  return o;\n}\n\n";

  m += "// The maps at time t seen from `camera` (null: no fade, every cascade at full weight).\n";
  m += "export function " + g + "ocean_update(o, t, camera) {\n";
  m += "  const tau = wgq_loop_fraction(t);\n";
  m += "  o.time = t;\n  o.fade = camera ? 1 : 0;\n";
  m += "  for (let c = 0; c < 3; ++c) o.camera[c] = camera ? camera[c] : 0.0;\n";
  m += "  for (let c = 0; c < " + C + "; ++c)\n";
  m += "    wgq_ocean_cascade(o.h0[c], o.frequency[c], " + g + "ocean_size[c], " + g + "ocean_tile[c], " +
       oceanJsNumber(s.cascades.choppiness) + ", tau, o.twiddle[c], o.evolved, o.work, o.line, o.maps[c]);\n}\n\n";

  m += "// The cascades' map channels at the world point (x, z), cascade c weighted by w[c], summed.\n";
  m += "export function " + g + "ocean_sample(o, x, z, w, out) {\n";
  m += "  const texelsPerMetre = " +
       list([&](size_t c) { return oceanJsNumber(static_cast<float>(size(c) / s.cascades.tileLengths[c])); }) + ";\n";
  m += "  for (let c = 0; c < 11; ++c) out[c] = 0.0;\n";
  m += "  for (let c = 0; c < " + C + "; ++c) wgq_ocean_read(o.maps[c], " + g +
       "ocean_size[c], texelsPerMetre[c], w[c], x, z, out);\n}\n\n";
  return m;
}

}  // namespace wg
