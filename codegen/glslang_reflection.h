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

// One shader's bound interface as glslang lays it out: each uniform block's binding and size
// (by block name), each block member's byte offset, each texture's and sampler's binding,
// each varying's location (-1 where it has none). An independent check of a hand-made
// declaration table (the runtime's WebGPU forms, runtime/webgpu_shader_form.h).
struct ReflectedInterface {
  struct Block {
    int binding = -1, size = 0;
  };
  std::map<std::string, Block> blocks;
  std::map<std::string, int> memberOffsets;
  std::map<std::string, int> opaqueBindings;
  std::map<std::string, int> inputLocations, outputLocations;
};
std::optional<ReflectedInterface> reflectedInterface(Target target, const ShaderSource& shader,
                                                     std::vector<ShaderMessage>* errors = nullptr);

}  // namespace wg
