#pragma once
// A typed constant in double precision: literals, parameter defaults, folded results and
// the values the CPU reference computes.
#include <array>
#include <initializer_list>
#include <string>

#include "core/types.h"

namespace wg {

struct Value {
  Type type = Type::Invalid;
  std::array<double, 16> c{};

  static Value scalar(double x);
  static Value vector(std::initializer_list<double> xs);  // 1..4 components -> float..vec4
  static Value ofType(Type t, double fill = 0.0);

  int size() const { return componentCount(type); }
  double operator[](int i) const { return c[static_cast<size_t>(i)]; }
  double& operator[](int i) { return c[static_cast<size_t>(i)]; }

  // Splats a float to `to`; returns *this unchanged when already of that type.
  Value convertedTo(Type to) const;
  bool allFinite() const;
  bool operator==(const Value& other) const;
  // "0.5" or "vec3(1, 0, 0)" for messages and docs.
  std::string toString() const;
};

}  // namespace wg
