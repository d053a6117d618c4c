#pragma once
// The std140 layout of the vk450 uniform block (shader_interface.h: WgUniforms, set 0,
// binding 0): every non-opaque uniform of the plan, in declaration order. The manifest
// lists each member's offset so an engine fills the block without a reflection library,
// and the Vulkan runtime writes the block from the same function.
#include <cstddef>
#include <vector>

#include "core/types.h"

namespace wg {

struct BlockMember {
  size_t offset = 0;  // bytes from the start of the block
  size_t size = 0;    // bytes the value occupies (a mat3: three 16-byte columns, 48)
};

// std140 (GLSL 4.50 section 7.6.2.2): scalars align to 4, vec2 to 8, vec3 and vec4 to 16;
// a matrix is an array of column vectors, each column aligned and padded to 16. Samplers
// get no member (size 0). Throws std::logic_error for a type a block cannot hold.
BlockMember std140Member(size_t offsetSoFar, Type type);
// One member per type, in order; samplers get {offsetSoFar, 0}.
std::vector<BlockMember> std140Layout(const std::vector<Type>& types);
// The block's size: the end of its last member rounded up to 16 (0 for no members).
size_t std140BlockSize(const std::vector<BlockMember>& members);

}  // namespace wg
