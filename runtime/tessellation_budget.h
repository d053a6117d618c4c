#pragma once
// The work a tessellated graph may ask of the runtime per draw. A graph's tessellation
// options are legal up to factor 64, and at factor 64 every one of the default water grid's
// 32,768 triangle patches becomes about 6,000 triangles: 200 million per draw, a render
// that did not finish in ten minutes on llvmpipe. The runtime bounds the triangles a
// tessellated draw can generate by drawing the water grid with fewer, larger patches when
// the grid and the graph's largest level would exceed the budget (docs/robustness.md).
#include <cstdint>

namespace wg::rt {

// Triangles one tessellated draw of the water may generate at most.
inline constexpr std::int64_t kMaxTessellatedTrianglesPerDraw = std::int64_t{1} << 20;  // 1,048,576

// The most triangles a grid of quadsPerSide² quads (two triangle patches each) generates
// with every level at `factor` (a triangle patch at level L is at most 1.5·L² triangles).
std::int64_t tessellatedTriangles(int quadsPerSide, double factor);

// The grid to draw: `requested` quads per side, or fewer (at least one) so that
// tessellatedTriangles stays within kMaxTessellatedTrianglesPerDraw.
int tessellatedGridQuads(int requested, double factor);

}  // namespace wg::rt
