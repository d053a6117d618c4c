#include "nodes/texture_source.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/png_decode.h"
#include "nodes/texture_sampling.h"

namespace wg {

Value TextureImage::sample(double u, double v) const {
  return sampleLevel(*this, u, v, TextureWrap::Repeat, TextureFilter::Linear, TextureColorSpace::Linear);
}

std::optional<TextureImage> loadTexture(std::string_view source, const std::string& graphDir, std::string* error) {
  TextureFile file;
  std::string why = checkTextureSource(source, graphDir, &file);
  if (!why.empty()) {
    if (error) *error = why;
    return std::nullopt;
  }
  if (source.rfind(kBuiltinTexturePrefix, 0) == 0) return generateBuiltinTexture(source.substr(kBuiltinTexturePrefix.size()));
  DecodedPng png;
  if (!decodePng(file.realPath, &png, &why)) {
    if (error) *error = "cannot decode texture '" + file.realPath + "': " + why;
    return std::nullopt;
  }
  TextureImage img;
  img.width = png.width;
  img.height = png.height;
  img.rgba = std::move(png.rgba);
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

const std::vector<TextureImage>& TextureCache::mipChain(const std::string& source, const std::string& graphDir,
                                                        TextureColorSpace colorSpace) {
  std::string key = graphDir + "\n" + source + "\n" + std::string(colorSpaceName(colorSpace));
  auto it = chains_.find(key);
  if (it != chains_.end()) return *it->second;
  auto chain = std::make_unique<std::vector<TextureImage>>(buildMipChain(get(source, graphDir), colorSpace));
  return *(chains_[key] = std::move(chain));
}

}  // namespace wg
