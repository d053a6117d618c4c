#include "core/types.h"

#include <array>
#include <utility>

namespace wg {
namespace {
struct TypeInfo {
  Type type;
  std::string_view name;
  int components;
};
constexpr std::array<TypeInfo, 11> kTypes = {{
    {Type::Float, "float", 1},
    {Type::Vec2, "vec2", 2},
    {Type::Vec3, "vec3", 3},
    {Type::Vec4, "vec4", 4},
    {Type::Int, "int", 1},
    {Type::Bool, "bool", 1},
    {Type::Mat3, "mat3", 9},
    {Type::Mat4, "mat4", 16},
    {Type::Sampler2D, "sampler2D", 0},
    {Type::SamplerCube, "samplerCube", 0},
    {Type::Ocean, "ocean", 1},
}};
}  // namespace

std::string_view typeName(Type t) {
  for (const auto& info : kTypes)
    if (info.type == t) return info.name;
  return "invalid";
}

std::optional<Type> parseType(std::string_view name) {
  for (const auto& info : kTypes)
    if (info.name == name) return info.type;
  return std::nullopt;
}

int componentCount(Type t) {
  for (const auto& info : kTypes)
    if (info.type == t) return info.components;
  return 0;
}

bool isFloatScalarOrVector(Type t) {
  return t == Type::Float || t == Type::Vec2 || t == Type::Vec3 || t == Type::Vec4;
}

bool isSampler(Type t) { return t == Type::Sampler2D || t == Type::SamplerCube; }

bool isOpaque(Type t) { return t == Type::Ocean; }

Type floatVector(int components) {
  switch (components) {
    case 1: return Type::Float;
    case 2: return Type::Vec2;
    case 3: return Type::Vec3;
    case 4: return Type::Vec4;
    default: return Type::Invalid;
  }
}

bool implicitlyConvertible(Type from, Type to) {
  if (from == to) return true;
  return from == Type::Float && (to == Type::Vec2 || to == Type::Vec3 || to == Type::Vec4);
}

}  // namespace wg
