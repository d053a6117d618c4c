// The spectral ocean's GPU cascade (runtime/ocean_gpu_cascade.h).
#include "runtime/ocean_gpu_cascade.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "runtime/ocean_gpu_passes.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

using namespace oceangpu;

// Each bin's phase is the 32-bit product n tau (uint arithmetic wraps modulo 2^32, as the
// reference's does); its top 24 bits become a float exactly, so the only rounding is the
// product by 2 pi / 2^24 and the sine and cosine.
constexpr const char* kEvolve = R"glsl(
uniform highp sampler2D u_h0;
uniform highp usampler2D u_frequency;
uniform uint u_tau;
uniform float u_dk;
uniform int u_n;
layout(location = 0) out vec4 o_a;
#if WG_OCEAN_SLOPES && !WG_OCEAN_JACOBIAN_ONLY
layout(location = 1) out vec4 o_b;
#endif

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 timesI(vec2 a) { return vec2(-a.y, a.x); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 h0 = texelFetch(u_h0, p, 0);  // h0(k) and conj(h0(-k))
  uint turns = texelFetch(u_frequency, p, 0).r * u_tau;
  float phase = float(turns >> 8u) * (6.283185307179586 / 16777216.0);
  vec2 turn = vec2(cos(phase), sin(phase));
  vec2 h = cmul(h0.xy, vec2(turn.x, -turn.y)) + cmul(h0.zw, turn);
  ivec2 m = ivec2(p.x < u_n / 2 ? p.x : p.x - u_n, p.y < u_n / 2 ? p.y : p.y - u_n);
  vec2 k = vec2(m) * u_dk;
  float kl = length(k);
  vec2 unit = kl > 0.0 ? k / kl : vec2(0.0);
  vec2 ih = timesI(h);
  vec2 dx = unit.x * ih, dz = unit.y * ih;          // i k/|k| h
  vec2 sx = k.x * ih, sz = k.y * ih;                // i k h
  vec2 dxx = -k.x * unit.x * h, dzz = -k.y * unit.y * h, dxz = -k.x * unit.y * h;
#if WG_OCEAN_JACOBIAN_ONLY
  // The second texture alone, in the first output: the fields the foam's J needs.
  o_a = vec4(sz + timesI(dxx), dzz + timesI(dxz));
#else
  o_a = vec4(h + timesI(dx), dz + timesI(sx));
#if WG_OCEAN_SLOPES
  o_b = vec4(sz + timesI(dxx), dzz + timesI(dxz));
#endif
#endif
}
)glsl";

// One radix-2 Stockham stage of the inverse DFT (sum of x_k exp(+2 pi i k j / N)) along x
// or z, for sub-transforms of length Ns: output i takes inputs j and j + N/2 with
// j = (i / 2Ns) Ns + i mod Ns, and the twiddle exp(2 pi i (i mod Ns) / 2Ns), negated for
// the second half of each block. After log2 N stages the result is in natural order.
constexpr const char* kStockham = R"glsl(
uniform highp sampler2D u_a;
uniform highp sampler2D u_twiddle;
uniform int u_ns;
uniform int u_n;
uniform int u_vertical;
layout(location = 0) out vec4 o_a;
#if WG_OCEAN_SLOPES
uniform highp sampler2D u_b;
layout(location = 1) out vec4 o_b;
#endif

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = u_vertical == 1 ? p.y : p.x;
  int r = i % u_ns;
  int j = (i / (2 * u_ns)) * u_ns + r;
  ivec2 first = u_vertical == 1 ? ivec2(p.x, j) : ivec2(j, p.y);
  ivec2 second = u_vertical == 1 ? ivec2(p.x, j + u_n / 2) : ivec2(j + u_n / 2, p.y);
  vec2 w = texelFetch(u_twiddle, ivec2(r * (u_n / (2 * u_ns)), 0), 0).xy;
  if ((i / u_ns) % 2 == 1) w = -w;
  vec4 a0 = texelFetch(u_a, first, 0), a1 = texelFetch(u_a, second, 0);
  o_a = vec4(a0.xy + cmul(w, a1.xy), a0.zw + cmul(w, a1.zw));
#if WG_OCEAN_SLOPES
  vec4 b0 = texelFetch(u_b, first, 0), b1 = texelFetch(u_b, second, 0);
  o_b = vec4(b0.xy + cmul(w, b1.xy), b0.zw + cmul(w, b1.zw));
#endif
}
)glsl";

constexpr const char* kPack = R"glsl(
uniform highp sampler2D u_a;
uniform float u_lambda;
layout(location = 0) out vec4 o_displacement;
#if WG_OCEAN_SLOPES
uniform highp sampler2D u_b;
layout(location = 1) out vec4 o_slopes;
#endif

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(u_a, p, 0);
  float h = a.x, dx = a.y, dz = a.z;
#if WG_OCEAN_SLOPES
  vec4 b = texelFetch(u_b, p, 0);
  float sx = a.w, sz = b.x, dxx = b.y, dzz = b.z, dxz = b.w;
  // The derivatives of the displacement, not J: J of several cascades is J of their sums,
  // which a sum of per-cascade Js is not.
  o_displacement = vec4(u_lambda * dx, h, u_lambda * dz, u_lambda * dxz);
  o_slopes = vec4(sx, sz, u_lambda * dxx, u_lambda * dzz);
#else
  // Nothing reads the slopes, so nothing reads w either (wg_ocean_normal and
  // wg_ocean_jacobian take both maps).
  o_displacement = vec4(u_lambda * dx, h, u_lambda * dz, 0.0);
#endif
}
)glsl";

}  // namespace

OceanGpuCascade::OceanGpuCascade(const ocean::OceanCascade& cascade, SceneShaderApi api, bool slopes, bool jacobian)
    : n_(cascade.resolution), slopes_(slopes), jacobian_(jacobian), tileLength_(cascade.tileLength) {
  const size_t count = static_cast<size_t>(n_) * n_;
  std::vector<float> h0(count * 4);
  for (int iz = 0; iz < n_; ++iz)
    for (int ix = 0; ix < n_; ++ix) {
      size_t i = static_cast<size_t>(iz) * n_ + ix;
      size_t mirror = static_cast<size_t>((n_ - iz) % n_) * n_ + static_cast<size_t>((n_ - ix) % n_);
      std::complex<double> a = cascade.h0[i], b = std::conj(cascade.h0[mirror]);
      h0[i * 4 + 0] = static_cast<float>(a.real());
      h0[i * 4 + 1] = static_cast<float>(a.imag());
      h0[i * 4 + 2] = static_cast<float>(b.real());
      h0[i * 4 + 3] = static_cast<float>(b.imag());
    }
  h0_ = floatTexture(n_, n_, GL_RGBA32F);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n_, n_, GL_RGBA, GL_FLOAT, h0.data());
  frequency_ = floatTexture(n_, n_, GL_R32UI);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n_, n_, GL_RED_INTEGER, GL_UNSIGNED_INT, cascade.frequency.data());
  // Twiddles exp(2 pi i m / N), m < N/2, computed in double and rounded once.
  std::vector<float> twiddle(static_cast<size_t>(n_));
  for (int m = 0; m < n_ / 2; ++m) {
    double angle = 2.0 * ocean::kPi * m / n_;
    twiddle[static_cast<size_t>(m) * 2] = static_cast<float>(std::cos(angle));
    twiddle[static_cast<size_t>(m) * 2 + 1] = static_cast<float>(std::sin(angle));
  }
  twiddle_ = floatTexture(n_ / 2, 1, GL_RG32F);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n_ / 2, 1, GL_RG, GL_FLOAT, twiddle.data());
  const int fields = slopes_ ? 2 : 1;
  for (int s = 0; s < 2; ++s) {
    for (int f = 0; f < fields; ++f) spectra_[s][f] = floatTexture(n_, n_, GL_RGBA32F);
    spectraTargets_[s] = targetOf(spectra_[s][0], slopes_ ? &spectra_[s][1] : nullptr, "spectrum");
  }
  for (int f = 0; f < fields; ++f) maps_[f] = floatTexture(n_, n_, GL_RGBA32F);
  mapTarget_ = targetOf(maps_[0], slopes_ ? &maps_[1] : nullptr, "map");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  emptyVao_ = makeVertexArray();

  auto link = [&](const char* name, const char* body, bool slopes, bool jacobianOnly = false) {
    return linkPass(api, name,
                    std::string("#define WG_OCEAN_SLOPES ") + (slopes ? "1" : "0") + "\n#define WG_OCEAN_JACOBIAN_ONLY " +
                        (jacobianOnly ? "1" : "0") + "\n",
                    body);
  };
  evolve_ = link("ocean_evolve", kEvolve, slopes_);
  stockham_ = link("ocean_stockham", kStockham, slopes_);
  pack_ = link("ocean_pack", kPack, slopes_);
  if (jacobian) {
    evolveJacobian_ = link("ocean_evolve_jacobian", kEvolve, false, true);
    stockhamSingle_ = slopes_ ? link("ocean_stockham_single", kStockham, false) : Program();
    for (int s = 0; s < 2; ++s) jacobianTargets_[s] = targetOf(spectra_[s][0], nullptr, "spectrum");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  checkGl("creating the ocean's GPU cascade");
}

size_t OceanGpuCascade::textureBytes(int n, bool slopes) {
  const size_t texels = static_cast<size_t>(n) * static_cast<size_t>(n), fields = slopes ? 2 : 1;
  const size_t rgba32f = 16;
  return texels * (rgba32f + 4)                // h0 (RGBA32F) and the frequencies (R32UI)
         + texels * rgba32f * fields * 2       // the spectra, ping and pong
         + texels * rgba32f * fields           // the maps
         + static_cast<size_t>(n / 2) * 8;     // the twiddles (RG32F)
}

void OceanGpuCascade::drawInto(const Framebuffer& target) const {
  glBindFramebuffer(GL_FRAMEBUFFER, target.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void OceanGpuCascade::beginPasses() const {
  glViewport(0, 0, n_, n_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(emptyVao_.id());
}

void OceanGpuCascade::evolve(const Program& program, double time, const Framebuffer& target) const {
  glUseProgram(program.id());
  bindTexture(0, h0_);
  bindTexture(1, frequency_);
  glUniform1i(location(program, "u_h0"), 0);
  glUniform1i(location(program, "u_frequency"), 1);
  glUniform1ui(location(program, "u_tau"), ocean::loopFraction(time));
  glUniform1f(location(program, "u_dk"), static_cast<float>(2.0 * ocean::kPi / tileLength_));
  glUniform1i(location(program, "u_n"), n_);
  drawInto(target);
}

int OceanGpuCascade::transform(const Program& stockham, bool both, const Framebuffer (&targets)[2]) const {
  glUseProgram(stockham.id());
  glUniform1i(location(stockham, "u_a"), 0);
  glUniform1i(location(stockham, "u_b"), 1);
  glUniform1i(location(stockham, "u_twiddle"), 2);
  glUniform1i(location(stockham, "u_n"), n_);
  bindTexture(2, twiddle_);
  int current = 0;
  for (int vertical = 0; vertical < 2; ++vertical)
    for (int ns = 1; ns < n_; ns *= 2) {
      bindTexture(0, spectra_[current][0]);
      if (both) bindTexture(1, spectra_[current][1]);
      glUniform1i(location(stockham, "u_ns"), ns);
      glUniform1i(location(stockham, "u_vertical"), vertical);
      drawInto(targets[1 - current]);
      current = 1 - current;
    }
  return current;
}

const Texture& OceanGpuCascade::jacobianFields(double time) {
  if (!jacobian_) throw std::logic_error("this ocean cascade was not made to compute its Jacobian's fields alone");
  beginPasses();
  evolve(evolveJacobian_, time, jacobianTargets_[0]);
  const int current = transform(slopes_ ? stockhamSingle_ : stockham_, false, jacobianTargets_);
  checkGl("the ocean's Jacobian passes");
  return spectra_[current][0];
}

void OceanGpuCascade::update(double time, double choppiness) {
  beginPasses();

  evolve(evolve_, time, spectraTargets_[0]);

  const int current = transform(stockham_, slopes_, spectraTargets_);

  glUseProgram(pack_.id());
  bindTexture(0, spectra_[current][0]);
  if (slopes_) bindTexture(1, spectra_[current][1]);
  glUniform1i(location(pack_, "u_a"), 0);
  glUniform1i(location(pack_, "u_b"), 1);
  glUniform1f(location(pack_, "u_lambda"), static_cast<float>(choppiness));
  drawInto(mapTarget_);
  checkGl("the ocean's GPU passes");
}

std::vector<float> OceanGpuCascade::readMap(int which) const {
  if (which == 1 && !slopes_) throw std::logic_error("this ocean cascade computes no slope map");
  std::vector<float> out(static_cast<size_t>(n_) * n_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, mapTarget_.id());
  glReadBuffer(which == 0 ? GL_COLOR_ATTACHMENT0 : GL_COLOR_ATTACHMENT1);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, n_, n_, GL_RGBA, GL_FLOAT, out.data());
  checkGl("reading the ocean's map back");
  return out;
}

}  // namespace wg::rt
