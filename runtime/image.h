#pragma once
// Images on disk and compared: PNG writing (atomic: a temporary file renamed into place)
// and reading through stb, and the PSNR / variance measures the tests use.
#include <cstdint>
#include <string>
#include <vector>

#include "runtime/renderer.h"

namespace wg::rt {

// Writes img.rgba8 as an RGBA PNG. Throws RuntimeError(Kind::Io) naming the path; on
// failure no file (and no temporary) is left behind.
void writePng(const std::string& path, const Image& img);
// Reads an 8-bit RGBA PNG; throws RuntimeError(Kind::Io) naming the path.
Image readPng(const std::string& path);

// Peak signal-to-noise ratio over R, G and B of two same-sized 8-bit images, in dB
// (infinity when identical). Throws std::invalid_argument on a size mismatch.
double psnrRgb8(const Image& a, const Image& b);
// Variance of the luminance (0..255 scale) in the pixel rectangle [x0,x1) x [y0,y1).
double lumaVariance(const Image& img, int x0, int y0, int x1, int y1);
// Number of non-finite float components in img.rgba32f.
size_t countNonFinite(const Image& img);

}  // namespace wg::rt
