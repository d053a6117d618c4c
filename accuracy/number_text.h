#pragma once
// Numbers in the accuracy tools' reports and data files: a fixed count of significant
// digits (printf's %g), "nan", "inf" and "-inf" spelled the same on every libc.
#include <string>

namespace wg::accuracy {

std::string significantDigits(double x, int digits);

}  // namespace wg::accuracy
