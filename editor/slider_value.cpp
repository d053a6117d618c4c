#include "editor/slider_value.h"

#include <charconv>
#include <cmath>

namespace wg::editor {

double decimalOfFloat(float shown) {
  if (!std::isfinite(shown)) return shown;
  char buf[64];
  auto written = std::to_chars(buf, buf + sizeof buf, shown);  // shortest round trip for float
  double value = shown;
  std::from_chars(buf, written.ptr, value);
  return value;
}

std::vector<double> valuesFromWidget(const std::vector<double>& before, const std::vector<float>& shown) {
  std::vector<double> out;
  out.reserve(shown.size());
  for (size_t i = 0; i < shown.size(); ++i) {
    bool unchanged = before.size() == shown.size() && static_cast<float>(before[i]) == shown[i];
    out.push_back(unchanged ? before[i] : decimalOfFloat(shown[i]));
  }
  return out;
}

}  // namespace wg::editor
