#include "nodes/texture_source.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <stb/stb_image.h>

namespace wg {

Value TextureImage::sample(double u, double v) const {
  Value out = Value::ofType(Type::Vec4);
  if (width <= 0 || height <= 0) return out;
  double x = u * width - 0.5, y = v * height - 0.5;
  // A non-finite coordinate reads from the origin rather than feeding NaN into an index.
  if (!std::isfinite(x)) x = 0;
  if (!std::isfinite(y)) y = 0;
  double fx = std::floor(x), fy = std::floor(y);
  double tx = x - fx, ty = y - fy;
  // Wrap in double: a coordinate of 1e31 texels has no integer type to go through.
  auto wrap = [](double i, int n) {
    double m = std::fmod(i, static_cast<double>(n));
    if (m < 0) m += n;
    int k = static_cast<int>(m);
    return k >= n ? 0 : k;
  };
  int x0 = wrap(fx, width), x1 = wrap(fx + 1, width);
  int y0 = wrap(fy, height), y1 = wrap(fy + 1, height);
  for (int c = 0; c < 4; ++c) {
    double a = at(x0, y0, c) / 255.0, b = at(x1, y0, c) / 255.0;
    double d = at(x0, y1, c) / 255.0, e = at(x1, y1, c) / 255.0;
    double top = a + (b - a) * tx, bottom = d + (e - d) * tx;
    out[c] = top + (bottom - top) * ty;
  }
  return out;
}

std::optional<TextureImage> loadTexture(std::string_view source, const std::string& graphDir, std::string* error) {
  std::string why = checkTextureSource(source, graphDir);
  if (!why.empty()) {
    if (error) *error = why;
    return std::nullopt;
  }
  if (source.rfind(kBuiltinTexturePrefix, 0) == 0) return generateBuiltinTexture(source.substr(kBuiltinTexturePrefix.size()));
  std::string path = (std::filesystem::path(graphDir.empty() ? "." : graphDir) / std::string(source)).string();
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!pixels) {
    if (error) *error = "cannot decode texture '" + path + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error");
    return std::nullopt;
  }
  TextureImage img;
  img.width = w;
  img.height = h;
  img.rgba.resize(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  // PNG rows run top to bottom; GL's first row is v = 0, the bottom of the picture.
  for (int y = 0; y < h; ++y)
    std::copy_n(pixels + static_cast<size_t>(h - 1 - y) * static_cast<size_t>(w) * 4, static_cast<size_t>(w) * 4,
                img.rgba.begin() + static_cast<long>(static_cast<size_t>(y) * static_cast<size_t>(w) * 4));
  stbi_image_free(pixels);
  return img;
}

const TextureImage& TextureCache::get(const std::string& source, const std::string& graphDir) {
  std::string key = graphDir + "\n" + source;
  auto it = images_.find(key);
  if (it != images_.end()) return *it->second;
  std::string error;
  auto img = loadTexture(source, graphDir, &error);
  if (!img) throw std::runtime_error(error);
  auto& slot = images_[key];
  slot = std::make_unique<TextureImage>(std::move(*img));
  return *slot;
}

}  // namespace wg
