#include "core/number_format.h"

#include <charconv>
#include <cmath>

namespace wg {

std::string formatNumber(double x) {
  // -0 keeps its sign as "-0.0": a JSON reader takes "-0" for the integer 0, and 1 / -0 is
  // -inf where 1 / 0 is +inf, so fmt must not turn one into the other.
  if (x == 0.0) return std::signbit(x) ? "-0.0" : "0";
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string formatGlslFloat(double x) {
  float f = static_cast<float>(x);
  // -0.0 keeps its sign: 1.0 / -0.0 is -inf, and a shader must compute what the graph says.
  if (f == 0.0f) return std::signbit(f) ? "-0.0" : "0.0";
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, f);
  std::string s(buf, res.ptr);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

}  // namespace wg
