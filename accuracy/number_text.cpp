#include "accuracy/number_text.h"

#include <cmath>
#include <cstdio>

namespace wg::accuracy {

std::string significantDigits(double x, int digits) {
  if (std::isnan(x)) return "nan";  // glibc prints "-nan" for a NaN with its sign bit set
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

}  // namespace wg::accuracy
