#pragma once
// One number format for every place a number is written (graph files, manifests, docs,
// messages), so output is byte-identical run to run and across machines.
#include <string>

namespace wg {

// Shortest decimal that reads back to the same double ("0.1", "2", "1e+20"; -0 is "-0.0").
std::string formatNumber(double x);
// Shortest decimal that reads back to the same float32, always with a '.' or exponent,
// so it is a valid GLSL float literal ("0.1", "2.0", "1e+20").
std::string formatGlslFloat(double x);

}  // namespace wg
