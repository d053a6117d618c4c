#include "core/color_space.h"

#include <algorithm>
#include <cmath>

namespace wg {

double srgbToLinear(double c) {
  const double a = std::fabs(c);
  double v = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
  v = std::min(v, a <= 1.0 ? 1.0 : 0x1p127);  // [0, 1] stays in [0, 1]; past it the GLSL's cap
  return c < 0 ? -v : v;
}

Value srgbToLinear(const Value& c) {
  Value out = c;
  const int n = componentCount(c.type);
  for (int i = 0; i < (n == 4 ? 3 : n); ++i) out[i] = srgbToLinear(c[i]);
  return out;
}

double linearToSrgb(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

}  // namespace wg
