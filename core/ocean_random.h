#pragma once
// Counter-based Gaussian numbers for the spectral ocean's initial amplitudes: each
// wavenumber bin's pair is a pure function of (cascade, ix, iz, seed), so any
// implementation that follows these integer steps (C++, GLSL 330 `uint`, JavaScript with
// Math.imul) draws the same uniforms, in any order and in parallel, with no generator state.
//
// The hash is PCG's four-lane variant (Jarzynski and Olano, "Hash Functions for GPU
// Rendering", JCGT 2020): a linear congruential step on each lane, then lanes mixing each
// other by multiplication, a xor-shift, and the mixing again. All arithmetic is modulo 2^32.
#include <array>
#include <cstdint>

namespace wg::ocean {

std::array<std::uint32_t, 4> pcg4d(std::array<std::uint32_t, 4> v);

// Two independent standard normal numbers for one bin (Box-Muller in double on the hash's
// first two lanes: u1 = (lane0 + 1) / 2^32 in (0, 1], u2 = lane1 / 2^32 in [0, 1)).
struct GaussianPair {
  double real = 0, imag = 0;
};
GaussianPair binGaussians(std::uint32_t cascade, std::uint32_t ix, std::uint32_t iz, std::uint32_t seed);

}  // namespace wg::ocean
