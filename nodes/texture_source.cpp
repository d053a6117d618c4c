#include "nodes/texture_source.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include <stb/stb_image.h>

#include "core/png_header.h"
#include "nodes/texture_sampling.h"

namespace wg {

Value TextureImage::sample(double u, double v) const {
  return sampleLevel(*this, u, v, TextureWrap::Repeat, TextureFilter::Linear, TextureColorSpace::Linear);
}

namespace {

// The largest PNG file read: twice the raw RGBA bytes of the largest texture allowed, room
// for a stored (uncompressed) image and its chunk overhead.
constexpr std::size_t kMaxPngFileBytes = std::size_t{2} * 4 * kMaxTextureSide * kMaxTextureSide;

// Reads the open file `fd` whole, up to kMaxPngFileBytes; "" or why not.
std::string readWhole(int fd, std::vector<unsigned char>* bytes) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return std::strerror(errno);
  if (!S_ISREG(st.st_mode)) return "it is not a regular file";
  if (static_cast<unsigned long long>(st.st_size) > kMaxPngFileBytes)
    return "the file has " + std::to_string(st.st_size) + " bytes; the limit is " + std::to_string(kMaxPngFileBytes);
  bytes->resize(static_cast<std::size_t>(st.st_size));
  std::size_t got = 0;
  while (got < bytes->size()) {
    ssize_t n = ::read(fd, bytes->data() + got, bytes->size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::strerror(errno);
    if (n == 0) break;  // shrank since fstat: decode what is there
    got += static_cast<std::size_t>(n);
  }
  bytes->resize(got);
  return "";
}

// Decodes the PNG that checkTextureSource resolved. The file is opened once, without
// following a link, and read whole; its header is checked again on those bytes (the file
// may have been replaced since it was checked), and every chunk must fit inside the file
// before the decoder sees it.
stbi_uc* decodePng(const TextureFile& file, int* w, int* h, std::string* error) {
  auto fail = [&](const std::string& why) -> stbi_uc* {
    if (error) *error = "cannot decode texture '" + file.realPath + "': " + why;
    return nullptr;
  };
  // O_NONBLOCK: a FIFO swapped in since the check must not hang the open; readWhole then
  // refuses anything but a regular file.
  int fd = ::open(file.realPath.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return fail(std::strerror(errno));
  std::vector<unsigned char> bytes;
  std::string why = readWhole(fd, &bytes);
  ::close(fd);
  PngSize size;
  if (why.empty()) why = readPngSize(bytes.data(), bytes.size(), &size);
  if (why.empty()) why = checkTextureSize(size.width, size.height);
  if (why.empty()) why = checkPngChunks(bytes.data(), bytes.size());
  if (!why.empty()) return fail(why);
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), w, h, &channels, 4);
  if (!pixels) return fail(stbi_failure_reason() ? stbi_failure_reason() : "unknown error");
  return pixels;
}

}  // namespace

std::optional<TextureImage> loadTexture(std::string_view source, const std::string& graphDir, std::string* error) {
  TextureFile file;
  std::string why = checkTextureSource(source, graphDir, &file);
  if (!why.empty()) {
    if (error) *error = why;
    return std::nullopt;
  }
  if (source.rfind(kBuiltinTexturePrefix, 0) == 0) return generateBuiltinTexture(source.substr(kBuiltinTexturePrefix.size()));
  int w = 0, h = 0;
  stbi_uc* pixels = decodePng(file, &w, &h, error);
  if (!pixels) return std::nullopt;
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

const std::vector<TextureImage>& TextureCache::mipChain(const std::string& source, const std::string& graphDir,
                                                        TextureColorSpace colorSpace) {
  std::string key = graphDir + "\n" + source + "\n" + std::string(colorSpaceName(colorSpace));
  auto it = chains_.find(key);
  if (it != chains_.end()) return *it->second;
  auto chain = std::make_unique<std::vector<TextureImage>>(buildMipChain(get(source, graphDir), colorSpace));
  return *(chains_[key] = std::move(chain));
}

}  // namespace wg
