#include "codegen/uniform_block_layout.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wg {
namespace {

struct Std140Shape {
  size_t alignment, size;
};

Std140Shape shapeOf(Type type) {
  switch (type) {
    case Type::Float:
    case Type::Int:
    case Type::Bool: return {4, 4};
    case Type::Vec2: return {8, 8};
    case Type::Vec3: return {16, 12};
    case Type::Vec4: return {16, 16};
    case Type::Mat3: return {16, 3 * 16};  // three vec3 columns, each padded to a vec4
    case Type::Mat4: return {16, 4 * 16};
    default: break;
  }
  throw std::logic_error("std140: type " + std::string(typeName(type)) + " cannot be a uniform block member");
}

size_t alignUp(size_t x, size_t a) { return (x + a - 1) / a * a; }

}  // namespace

BlockMember std140Member(size_t offsetSoFar, Type type) {
  if (isSampler(type)) return {offsetSoFar, 0};
  Std140Shape s = shapeOf(type);
  return {alignUp(offsetSoFar, s.alignment), s.size};
}

std::vector<BlockMember> std140Layout(const std::vector<Type>& types) {
  std::vector<BlockMember> out;
  size_t end = 0;
  for (Type t : types) {
    out.push_back(std140Member(end, t));
    end = out.back().offset + out.back().size;
  }
  return out;
}

size_t std140BlockSize(const std::vector<BlockMember>& members) {
  size_t end = 0;
  for (const auto& m : members) end = std::max(end, m.offset + m.size);
  return alignUp(end, 16);
}

}  // namespace wg
