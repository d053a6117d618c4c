#include "core/scene_image.h"

#include <algorithm>
#include <cmath>

namespace wg {
namespace {

int clampIndex(double i, int size) { return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(size - 1))); }

}  // namespace

Value SceneImage::sample(double u, double v) const {
  if (!std::isfinite(u)) u = 0;
  if (!std::isfinite(v)) v = 0;
  Value out = channels == 1 ? Value::scalar(0) : Value::ofType(Type::Vec3);
  if (nearest) {
    int i = clampIndex(std::floor(u * width), width), j = clampIndex(std::floor(v * height), height);
    for (int c = 0; c < channels; ++c) out[c] = texel(i, j, c);
    return out;
  }
  // Texels floor(x - 0.5) and the next, blended by the fraction; each index clamped.
  double x = u * width - 0.5, y = v * height - 0.5;
  double fx = std::floor(x), fy = std::floor(y);
  double a = x - fx, b = y - fy;
  int i0 = clampIndex(fx, width), i1 = clampIndex(fx + 1, width);
  int j0 = clampIndex(fy, height), j1 = clampIndex(fy + 1, height);
  for (int c = 0; c < channels; ++c) {
    double bottom = (1 - a) * texel(i0, j0, c) + a * texel(i1, j0, c);
    double top = (1 - a) * texel(i0, j1, c) + a * texel(i1, j1, c);
    out[c] = (1 - b) * bottom + b * top;
  }
  return out;
}

}  // namespace wg
