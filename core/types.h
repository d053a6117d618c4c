#pragma once
// The value types a graph port can carry, and the one implicit conversion the format
// allows: a float splats to a float vector. Everything else is an explicit node.
#include <optional>
#include <string_view>

namespace wg {

enum class Type : unsigned char {
  Invalid,
  Float,
  Vec2,
  Vec3,
  Vec4,
  Int,
  Bool,
  Mat3,
  Mat4,
  Sampler2D,
  SamplerCube,
  // The spectral ocean an ocean_spectrum node describes (docs/ocean.md): a handle its
  // readers take, never a shader value; the CPU reference holds its identity in c[0].
  Ocean,
};

std::string_view typeName(Type t);
std::optional<Type> parseType(std::string_view name);

// Number of double components a value of this type holds (0 for samplers).
int componentCount(Type t);
// float, vec2, vec3, vec4.
bool isFloatScalarOrVector(Type t);
bool isSampler(Type t);
// A value that names something rather than holding numbers (the ocean).
bool isOpaque(Type t);
// vecN for N in 1..4 (1 gives float); Invalid otherwise.
Type floatVector(int components);
// from == to, or a float splatting to a float vector.
bool implicitlyConvertible(Type from, Type to);

}  // namespace wg
