#pragma once
// Frequency analysis: how often each op of a Program computes a new value. An op that
// depends only on parameters, time and per-draw builtins (camera, near/far, view and
// projection, the sun) is the same for every pixel of a draw: the stage pass asks which
// builtins vary over the surface (isPerDrawBuiltin), and --explain-frequency reports the
// per-draw work the fragment stage repeats per pixel. Read-only: it changes no Program.
#include <string_view>
#include <vector>

#include "core/program.h"

namespace wg {

// Ordered: a value's frequency is the highest of its inputs' and its own.
enum class Frequency : unsigned char {
  Constant,     // the same in every draw (a literal, or what folding left of one)
  PerDraw,      // parameters, time and the per-draw builtins only
  PerVertex,    // varies over the surface, computed only in the vertex stage (a varying carries it)
  PerFragment,  // varies over the surface and the fragment stage computes it
};
std::string_view frequencyName(Frequency f);  // "constant", "per-draw", "per-vertex", "per-fragment"

// Builtins whose value is one uniform for the whole draw (time, camera position, near/far,
// view, projection, sun direction); the rest vary over the surface.
bool isPerDrawBuiltin(Builtin b);

// Per op, its frequency. Sources that read only uniforms (the time and camera input nodes)
// are per-draw; every other source (textures, time phases, scene look-ups: the nodes do
// not declare what else their emit reads) counts as varying. Varying ops are per-vertex
// when only the vertex stage computes them, per-fragment otherwise, so PerVertex needs the
// stage pass to have run (before it, every varying op is PerFragment).
std::vector<Frequency> analyseFrequency(const Program& program);

// The frequency of a value read somewhere: a constant, a parameter (per-draw), a builtin
// (per-draw, or per-vertex for the mesh builtins and per-fragment for screen uv and
// fragment depth), or an op's output (its entry in `ops`).
Frequency frequencyOf(const ValueRef& ref, const std::vector<Frequency>& ops);

}  // namespace wg
