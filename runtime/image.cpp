#include "runtime/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "codegen/output_files.h"
#include "core/file_read.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

void writePng(const std::string& path, const Image& img) {
  if (img.rgba8.size() != static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 4 || img.width <= 0)
    throw RuntimeError(RuntimeError::Kind::Io, "cannot write " + path + ": no 8-bit image to write");
  namespace fs = std::filesystem;
  fs::path target(path);
  fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!dir.empty() && !fs::exists(dir, ec)) fs::create_directories(dir, ec);
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, img.width, img.height, 4, img.rgba8.data(), img.width * 4))
    throw RuntimeError(RuntimeError::Kind::Io, "cannot write " + path + ": PNG encoding failed");
  // Written as every output file is (codegen/output_files.h): a temporary beside it, then a
  // rename; an existing FIFO, device, folder or read-only file is refused, not replaced.
  Diagnostics diags;
  if (!writeFileAtomically(path, png, diags)) {
    std::string why = diags.all().empty() ? "cannot write" : diags.all().front().message;
    throw RuntimeError(RuntimeError::Kind::Io, path + ": " + why);
  }
}

Image readPng(const std::string& path) {
  // One open, one read (core/file_read.h), then decoded from memory.
  FileReadRule rule;
  rule.maxBytes = std::size_t{1} << 30;
  FileReadFailure failure;
  auto file = readFileChecked(path, rule, &failure);
  if (!file) throw RuntimeError(RuntimeError::Kind::Io, "cannot read " + path + ": " + failure.why());
  if (file->bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
    throw RuntimeError(RuntimeError::Kind::Io, "cannot read " + path + ": too large");
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(file->bytes.data()),
                                              static_cast<int>(file->bytes.size()), &w, &h, &n, 4);
  if (!data) {
    const char* why = stbi_failure_reason();
    throw RuntimeError(RuntimeError::Kind::Io, "cannot read " + path + ": " + (why ? why : "unknown error"));
  }
  Image img;
  img.width = w;
  img.height = h;
  img.rgba8.assign(data, data + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  stbi_image_free(data);
  return img;
}

double psnrRgb8(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.rgba8.size() != b.rgba8.size() || a.rgba8.empty())
    throw std::invalid_argument("psnr: images differ in size");
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.rgba8.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) {
      double d = static_cast<double>(a.rgba8[i + c]) - static_cast<double>(b.rgba8[i + c]);
      sum += d * d;
      ++n;
    }
  double mse = sum / static_cast<double>(n);
  if (mse == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

double lumaVariance(const Image& img, int x0, int y0, int x1, int y1) {
  double s = 0, s2 = 0;
  size_t n = 0;
  for (int y = std::max(y0, 0); y < std::min(y1, img.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, img.width); ++x) {
      size_t i = (static_cast<size_t>(y) * static_cast<size_t>(img.width) + static_cast<size_t>(x)) * 4;
      double l = 0.2126 * img.rgba8[i] + 0.7152 * img.rgba8[i + 1] + 0.0722 * img.rgba8[i + 2];
      s += l;
      s2 += l * l;
      ++n;
    }
  if (n == 0) return 0;
  double m = s / static_cast<double>(n);
  return s2 / static_cast<double>(n) - m * m;
}

size_t countNonFinite(const Image& img) {
  size_t bad = 0;
  for (float v : img.rgba32f) bad += !std::isfinite(v);
  return bad;
}

}  // namespace wg::rt
