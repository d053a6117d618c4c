#include "core/png_decode.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <sys/stat.h>

#include <stb/stb_image.h>

#include "core/file_read.h"
#include "core/png_header.h"
#include "core/texture_check.h"

namespace wg {
namespace {

// The largest PNG file read: twice the raw RGBA bytes of the largest texture allowed, room
// for a stored (uncompressed) image and its chunk overhead.
constexpr std::size_t kMaxPngFileBytes = std::size_t{2} * 4 * kMaxTextureSide * kMaxTextureSide;

}  // namespace

// The file is opened once and read whole from that descriptor, which must still be the file
// checked (its real path is `realPath`: a file or folder swapped for a link since is refused,
// core/file_read.h); its header is checked again on those bytes (the file may have been
// replaced since it was checked), and every chunk must fit inside the file and carry a
// correct CRC before the decoder sees it.
bool decodePng(const std::string& realPath, DecodedPng* out, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  FileReadRule rule;
  rule.maxBytes = kMaxPngFileBytes;
  rule.mustResolveTo = realPath;
  FileReadFailure failure;
  auto text = readFileChecked(realPath, rule, &failure);
  if (!text) {
    if (failure.kind == FileReadFailure::Kind::TooLarge)
      return fail("the file is larger than the limit of " + std::to_string(kMaxPngFileBytes) + " bytes");
    if (failure.kind == FileReadFailure::Kind::Outside)
      return fail("the file changed since it was checked (it is no longer " + realPath + ")");
    return fail(failure.why());
  }
  const std::string& raw = text->bytes;
  const auto* bytes = reinterpret_cast<const unsigned char*>(raw.data());
  PngSize size;
  std::string why = readPngSize(bytes, raw.size(), &size);
  if (why.empty()) why = checkTextureSize(size.width, size.height);
  if (why.empty()) why = checkPngChunks(bytes, raw.size());
  if (!why.empty()) return fail(why);
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes, static_cast<int>(raw.size()), &w, &h, &channels, 4);
  if (!pixels) return fail(stbi_failure_reason() ? stbi_failure_reason() : "unknown error");
  out->width = w;
  out->height = h;
  const std::size_t row = static_cast<std::size_t>(w) * 4;
  out->rgba.resize(row * static_cast<std::size_t>(h));
  // PNG rows run top to bottom; GL's first row is v = 0, the bottom of the picture.
  for (int y = 0; y < h; ++y)
    std::copy_n(pixels + static_cast<std::size_t>(h - 1 - y) * row, row, out->rgba.begin() + static_cast<long>(static_cast<std::size_t>(y) * row));
  stbi_image_free(pixels);
  return true;
}

std::string checkPngDecodes(const std::string& realPath) {
  // The file's identity and both times: a copy that keeps the modification time (cp -p,
  // tar) still has another inode or change time. Only files that decoded are remembered: a
  // failure may be passing (too many open files) and is decoded again next time.
  auto identity = [](const std::string& path, std::vector<long long>* key) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return false;
    *key = {static_cast<long long>(st.st_dev),        static_cast<long long>(st.st_ino),
            static_cast<long long>(st.st_size),       static_cast<long long>(st.st_mtim.tv_sec),
            static_cast<long long>(st.st_mtim.tv_nsec), static_cast<long long>(st.st_ctim.tv_sec),
            static_cast<long long>(st.st_ctim.tv_nsec)};
    return true;
  };
  std::vector<long long> before;
  if (!identity(realPath, &before)) return std::strerror(errno);
  static std::mutex mutex;
  static std::set<std::pair<std::string, std::vector<long long>>> decoded;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (decoded.count({realPath, before})) return "";
  }
  DecodedPng image;
  std::string why;
  if (!decodePng(realPath, &image, &why)) return why;
  std::vector<long long> after;
  // Replaced while it was read: what was decoded is not known to be that file.
  if (!identity(realPath, &after) || after != before) return "";
  std::lock_guard<std::mutex> lock(mutex);
  if (decoded.size() >= 256) decoded.clear();  // a long editor session: forget, do not grow
  decoded.emplace(realPath, std::move(before));
  return "";
}

}  // namespace wg
