#pragma once
// Where the water's vertex stage puts a point, in double: the ops the vertex position and
// normal outputs read, evaluated by their node evals (the CPU backend) at the undisplaced
// water point (x0, 0, z0) and time t. What the query targets generate as C and JavaScript
// (codegen/query_header.h), here in process: the runtime floats its buoys with it
// (runtime/floating_buoys.h).
#include <vector>

#include "core/program.h"

namespace wg {

struct WaterSurfacePoint {
  double position[3];  // the displaced point (x0, 0, z0 where nothing displaces it)
  double normal[3];    // the vertex stage's normal output, (0, 1, 0) where it has none
};

class TextureCache;

// The vertex stage of `program` (after the compiler's passes) at (x0, 0, z0), time t, with
// `parameters` by index (the program's own count; a host's values, already clamped). A
// node texture the vertex stage samples is read through `textures` (null: a cache for this
// call alone; pass one to read the files once over many points), from program.directory.
WaterSurfacePoint waterSurfaceAt(const Program& program, const std::vector<Value>& parameters, double x0, double z0,
                                 double t, TextureCache* textures = nullptr);

}  // namespace wg
