#include "core/value.h"

#include <cmath>

#include "core/number_format.h"

namespace wg {

Value Value::scalar(double x) {
  Value v;
  v.type = Type::Float;
  v.c[0] = x;
  return v;
}

Value Value::vector(std::initializer_list<double> xs) {
  Value v;
  v.type = floatVector(static_cast<int>(xs.size()));
  int i = 0;
  for (double x : xs) v.c[static_cast<size_t>(i++)] = x;
  return v;
}

Value Value::ofType(Type t, double fill) {
  Value v;
  v.type = t;
  for (int i = 0; i < componentCount(t); ++i) v.c[static_cast<size_t>(i)] = fill;
  return v;
}

Value Value::convertedTo(Type to) const {
  if (type == to || type != Type::Float) return *this;
  return ofType(to, c[0]);
}

bool Value::allFinite() const {
  for (int i = 0; i < size(); ++i)
    if (!std::isfinite(c[static_cast<size_t>(i)])) return false;
  return true;
}

bool Value::operator==(const Value& other) const {
  if (type != other.type) return false;
  for (int i = 0; i < size(); ++i)
    if (c[static_cast<size_t>(i)] != other.c[static_cast<size_t>(i)]) return false;
  return true;
}

std::string Value::toString() const {
  if (size() == 1) return formatNumber(c[0]);
  std::string s(typeName(type));
  s += '(';
  for (int i = 0; i < size(); ++i) {
    if (i) s += ", ";
    s += formatNumber(c[static_cast<size_t>(i)]);
  }
  s += ')';
  return s;
}

}  // namespace wg
