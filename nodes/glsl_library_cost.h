#pragma once
// What one call of a library function (nodes/glsl/) costs, by the rules of
// core/glsl_operation_count.h, read from the library's own hand-written source: the
// operations of its body, a library function it calls counted through that function's
// body, once per call (a loop body counts once). The library is hand-written, not
// generated: the one whole text counted. What nodes emit is counted piece by piece as they
// build their values (GlslExpr::operations); no count reads a generated shader.
#include <map>
#include <mutex>
#include <string>
#include <string_view>

#include "nodes/glsl_library.h"

namespace wg {

class GlslCost {
 public:
  explicit GlslCost(const GlslLibrary& library = GlslLibrary::builtin()) : library_(library) {}
  // The operations of one call of library function `name` (0 for a name the library lacks).
  int ofFunction(std::string_view name);

 private:
  const GlslLibrary& library_;
  std::recursive_mutex mutex_;  // held through an item's count (it asks for the items it calls)
  std::map<std::string, int, std::less<>> functions_;  // memo: costs of library functions
};

// One call of `name` in the built-in library (thread-safe, computed once per item): the
// costs core's counts ask for (setLibraryCallCost), installed when this library is linked.
int builtinLibraryCallCost(std::string_view name);

}  // namespace wg
