#include "nodes/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/color_space.h"

namespace wg {

namespace {

const std::array<double, 256>& srgbTable() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) t[static_cast<size_t>(i)] = srgbToLinear(i / 255.0);
    return t;
  }();
  return table;
}

// The wrapped index of integer texel coordinate `i` (a double: a coordinate of 1e31
// texels has no integer type to go through) on a side of `n` texels.
int wrapIndex(double i, int n, TextureWrap wrap) {
  const double size = n;
  auto mod = [](double a, double m) {
    double r = std::fmod(a, m);
    return r < 0 ? r + m : r;
  };
  double w = 0;
  switch (wrap) {
    case TextureWrap::Repeat: w = mod(i, size); break;
    case TextureWrap::Clamp: w = std::clamp(i, 0.0, size - 1); break;
    case TextureWrap::Mirror: {
      double a = mod(i, 2 * size) - size;
      w = (size - 1) - (a >= 0 ? a : -(1 + a));
      break;
    }
  }
  // `i` is an integer, so fmod and the sums are exact; the clamp only guards the cast.
  int k = static_cast<int>(w);
  return std::clamp(k, 0, n - 1);
}

double component(const TextureImage& img, int x, int y, int c, TextureColorSpace space) {
  return decodeTexel(img.at(x, y, c), c == 3 ? TextureColorSpace::Linear : space);
}

TextureImage halve(const TextureImage& src, TextureColorSpace space) {
  TextureImage dst;
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  dst.rgba.resize(static_cast<size_t>(dst.width) * static_cast<size_t>(dst.height) * 4);
  for (int j = 0; j < dst.height; ++j)
    for (int i = 0; i < dst.width; ++i) {
      // The destination texel's centre on the source level, bilinear and clamped there.
      double u = (i + 0.5) / dst.width, v = (j + 0.5) / dst.height;
      Value s = sampleLevel(src, u, v, TextureWrap::Clamp, TextureFilter::Linear, space);
      for (int c = 0; c < 4; ++c)
        dst.rgba[(static_cast<size_t>(j) * static_cast<size_t>(dst.width) + static_cast<size_t>(i)) * 4 +
                 static_cast<size_t>(c)] = encodeTexel(s[c], c == 3 ? TextureColorSpace::Linear : space);
    }
  return dst;
}

}  // namespace

double decodeTexel(std::uint8_t byte, TextureColorSpace space) {
  return space == TextureColorSpace::Srgb ? srgbTable()[byte] : byte / 255.0;
}

std::uint8_t encodeTexel(double linear, TextureColorSpace space) {
  double x = std::clamp(linear, 0.0, 1.0);
  if (space == TextureColorSpace::Srgb) x = linearToSrgb(x);
  return static_cast<std::uint8_t>(std::clamp(std::floor(x * 255.0 + 0.5), 0.0, 255.0));
}

Value sampleLevel(const TextureImage& level, double u, double v, TextureWrap wrap, TextureFilter filter,
                  TextureColorSpace space) {
  Value out = Value::ofType(Type::Vec4);
  if (level.width <= 0 || level.height <= 0) return out;
  if (filter == TextureFilter::Nearest) {
    double x = u * level.width, y = v * level.height;
    if (!std::isfinite(x)) x = 0;
    if (!std::isfinite(y)) y = 0;
    int i = wrapIndex(std::floor(x), level.width, wrap), j = wrapIndex(std::floor(y), level.height, wrap);
    for (int c = 0; c < 4; ++c) out[c] = component(level, i, j, c, space);
    return out;
  }
  double x = u * level.width - 0.5, y = v * level.height - 0.5;
  if (!std::isfinite(x)) x = 0;
  if (!std::isfinite(y)) y = 0;
  double fx = std::floor(x), fy = std::floor(y);
  double tx = x - fx, ty = y - fy;
  int x0 = wrapIndex(fx, level.width, wrap), x1 = wrapIndex(fx + 1, level.width, wrap);
  int y0 = wrapIndex(fy, level.height, wrap), y1 = wrapIndex(fy + 1, level.height, wrap);
  for (int c = 0; c < 4; ++c) {
    double a = component(level, x0, y0, c, space), b = component(level, x1, y0, c, space);
    double d = component(level, x0, y1, c, space), e = component(level, x1, y1, c, space);
    double top = a + (b - a) * tx, bottom = d + (e - d) * tx;
    out[c] = top + (bottom - top) * ty;
  }
  return out;
}

std::vector<TextureImage> buildMipChain(const TextureImage& base, TextureColorSpace space) {
  std::vector<TextureImage> chain;
  const TextureImage* prev = &base;
  while (prev->width > 1 || prev->height > 1) {
    chain.push_back(halve(*prev, space));
    prev = &chain.back();
  }
  return chain;
}

double levelOfDetail(const TextureImage& base, const UvGradient& g) {
  double w = base.width, h = base.height;
  double rho = std::max({std::abs(g.dudx) * w, std::abs(g.dvdx) * h, std::abs(g.dudy) * w, std::abs(g.dvdy) * h});
  return std::log2(rho);
}

Value sampleTexture(const TextureImage& base, const std::vector<TextureImage>* chain, double u, double v,
                    const SamplerState& sampler, const UvGradient& gradient) {
  if (sampler.filter != TextureFilter::Mipmapped)
    return sampleLevel(base, u, v, sampler.wrap, sampler.filter, sampler.colorSpace);
  double lambda = levelOfDetail(base, gradient);
  // Magnification (and a NaN gradient, which selects no level): level 0.
  if (!(lambda > 0)) return sampleLevel(base, u, v, sampler.wrap, TextureFilter::Linear, sampler.colorSpace);
  if (!chain) throw std::logic_error("a mipmapped look-up above level 0 needs the texture's mip chain");
  const double q = static_cast<double>(chain->size());
  auto level = [&](size_t d) -> const TextureImage& { return d == 0 ? base : (*chain)[d - 1]; };
  if (lambda >= q)
    return sampleLevel(level(chain->size()), u, v, sampler.wrap, TextureFilter::Linear, sampler.colorSpace);
  double d1 = std::floor(lambda), f = lambda - d1;
  Value a = sampleLevel(level(static_cast<size_t>(d1)), u, v, sampler.wrap, TextureFilter::Linear, sampler.colorSpace);
  Value b = sampleLevel(level(static_cast<size_t>(d1) + 1), u, v, sampler.wrap, TextureFilter::Linear, sampler.colorSpace);
  Value out = Value::ofType(Type::Vec4);
  for (int c = 0; c < 4; ++c) out[c] = a[c] + (b[c] - a[c]) * f;
  return out;
}

double filterUncertainty(const TextureImage& base, double u, double v, const SamplerState& sampler) {
  if (sampler.filter == TextureFilter::Nearest || base.width <= 0 || base.height <= 0) return 0.0;
  // Nearest look-ups half a texel either side read the texels a bilinear look-up blends.
  const double du = 0.5 / base.width, dv = 0.5 / base.height;
  std::array<double, 4> lo{INFINITY, INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY, -INFINITY};
  for (double su : {-du, du})
    for (double sv : {-dv, dv}) {
      Value t = sampleLevel(base, u + su, v + sv, sampler.wrap, TextureFilter::Nearest, sampler.colorSpace);
      for (size_t c = 0; c < 4; ++c) lo[c] = std::min(lo[c], t[static_cast<int>(c)]), hi[c] = std::max(hi[c], t[static_cast<int>(c)]);
    }
  double spread = 0;
  for (size_t c = 0; c < 4; ++c) spread = std::max(spread, hi[c] - lo[c]);
  return std::ldexp(spread, -7) + std::ldexp(1.0, -9);
}

}  // namespace wg
