#pragma once
// A rough, static cost of GLSL code: the operations it asks the GPU for, counted from the
// text. Binary and comparison operators, selects (?:) and calls of GLSL built-in functions
// (texture look-ups included) count 1 each; constructors, swizzles, unary signs and
// assignments count 0; a call of a library function (wg_*) counts what its body counts,
// once per call (a loop body counts once). It ignores vector width and the relative
// price of operations: a figure for ranking and for "is it more than a uniform read"
// (which costs 0), not a measurement.
#include <map>
#include <string>
#include <string_view>

#include "nodes/glsl_library.h"

namespace wg {

class GlslCost {
 public:
  explicit GlslCost(const GlslLibrary& library = GlslLibrary::builtin()) : library_(library) {}
  // The operations of `code` (statements or expressions; comments are skipped).
  int of(std::string_view code);
  // The operations of one call of library function `name` (0 for a name the library lacks).
  int ofFunction(const std::string& name);

 private:
  const GlslLibrary& library_;
  std::map<std::string, int, std::less<>> functions_;  // memo: costs of library functions
};

}  // namespace wg
