#include "nodes/glsl_library_cost.h"

#include "core/glsl_operation_count.h"

namespace wg {
namespace {

// Inside a library item: a library function it calls costs that function's body.
int itemCallCost(std::string_view name, const void* context) {
  if (!name.starts_with("wg_")) return isFreeGlslCall(name) ? 0 : 1;
  return static_cast<GlslCost*>(const_cast<void*>(context))->ofFunction(name);
}

// Core's counts price library calls through this from the start (GlslLibrary::builtin()
// refers to this file, so every program that plans shaders links it).
[[maybe_unused]] const bool kLibraryCostsInstalled = (setLibraryCallCost(&builtinLibraryCallCost), true);

}  // namespace

int GlslCost::ofFunction(std::string_view name) {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  if (auto it = functions_.find(name); it != functions_.end()) return it->second;
  functions_.emplace(std::string(name), 0);  // GLSL has no recursion; this only keeps a malformed library finite
  int cost = 0;
  for (const auto& item : library_.items())
    if (item.name == name) {
      // The body only: the signature "float wg_f(float x)" would read as a call of itself.
      size_t open = item.text.find('{');
      GlslOperationScan scan;
      if (open != std::string::npos)
        cost = countGlslOperations(std::string_view(item.text).substr(open), scan, itemCallCost, this);
      break;
    }
  functions_[std::string(name)] = cost;
  return cost;
}

int builtinLibraryCallCost(std::string_view name) {
  static GlslCost cost;
  return cost.ofFunction(name);
}

}  // namespace wg
