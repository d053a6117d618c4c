#pragma once
// The types of the GLSL subset (codegen/glsl_subset.h) as the WGSL translator tracks them,
// their WGSL spelling, and WGSL's reserved words. Knowing every expression's type is what
// lets the translator make each GLSL implicit rule explicit: a scalar widened to a vector
// in min/max/clamp, a vector comparison reduced by all()/any(), a shift count made u32.
#include <string>
#include <string_view>

namespace wg::wgsl {

struct ValueType {
  // f: f32, i: i32, u: u32, b: bool, v: void, t: sampler2D, c: samplerCube
  char base = 'v';
  int size = 1;  // vector components (1: scalar); a matrix: its rows
  int cols = 0;  // a matrix: its columns; else 0
  bool isMatrix() const { return cols > 0; }
  bool isVector() const { return cols == 0 && size > 1; }
  bool isScalar() const { return cols == 0 && size == 1 && base != 'v' && !isSampler(); }
  bool isSampler() const { return base == 't' || base == 'c'; }
  bool operator==(const ValueType&) const = default;
};

// "vec3" -> {f, 3}; throws std::logic_error for a name outside the subset.
ValueType glslType(std::string_view name);
// {f, 3} -> "vec3<f32>"; samplers -> their texture type ("texture_2d<f32>", "texture_cube<f32>").
std::string wgslTypeName(const ValueType& t);
// The same shape with another component type (vec3 of f32 -> vec3 of u32).
ValueType withBase(ValueType t, char base);
// `name` when WGSL allows it as an identifier, else name + "_": keywords, reserved words
// and the built-in names the translator itself writes (select, atan2, textureSample ...).
std::string wgslSafeName(const std::string& name);

}  // namespace wg::wgsl
