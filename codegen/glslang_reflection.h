#pragma once
// What glslang's reflection says about a linked program, for tests that check the
// compiler's own bookkeeping against glslang (defined in glslang_validate.cpp, beside the
// compile-and-link it reuses).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "codegen/glslang_validate.h"

namespace wg {

// glslang's byte offset of every uniform-block member the program declares (read or not),
// by name: an independent check of the std140 offsets the manifest lists for vk450.
std::optional<std::map<std::string, int>> uniformBlockOffsets(Target target, const std::vector<ShaderSource>& shaders);

}  // namespace wg
