#pragma once
// The CPU side of the noise library (nodes/glsl/hash.glsl, value_noise.glsl, fbm.glsl,
// voronoi.glsl): the same PCG3D integer hash in uint32_t, so hashed values are bit-identical
// to the GPU's, and the noise built on it in double precision following GLSL semantics.
// Shared by the noise, caustics and foam nodes and their tests.
#include <array>
#include <cstdint>

namespace wg::nodes::noise {

using U3 = std::array<std::uint32_t, 3>;

// floor(x) clamped into the int range, as int32 reinterpreted as uint32 (wg_hash_cell_*).
// NaN maps to 0 (the GPU's result for NaN is unspecified but finite).
std::uint32_t cellOf(double x);
// PCG3D (Jarzynski and Olano 2020), arithmetic modulo 2^32.
U3 pcg3d(U3 v);
// The top 24 bits as a float in [0, 1): exactly representable in float32.
double unitOf(std::uint32_t h);
// Three hashed values in [0, 1) for the cell of (x, y, z); a 2D cell is (x, y, 0).
std::array<double, 3> hash2(double x, double y);
std::array<double, 3> hash3(double x, double y, double z);

double valueNoise2(double x, double y);
double valueNoise3(double x, double y, double z);
// Lattice repeating every mask + 1 cells (a power of two).
double valueNoiseTiled2(double x, double y, std::uint32_t mask);
double fbm2(double x, double y, int octaves, double lacunarity, double gain);
double fbm3(double x, double y, double z, int octaves, double lacunarity, double gain);

struct VoronoiResult {
  double f1 = 0, f2 = 0;
  double cellX = 0, cellY = 0;
};
// full: 3x3 search, else the 2x2 block on p's side. phase in [0, 2 pi) when animated.
VoronoiResult voronoi(double x, double y, double jitter, double phase, bool animated, bool full);

inline constexpr double kTau = 6.283185307179586;

}  // namespace wg::nodes::noise
