// The spectral ocean's GPU cascade (runtime/ocean_gpu_cascade.h).
#include "runtime/ocean_gpu_cascade.h"

#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "runtime/ocean_gpu_passes.h"
#include "runtime/ocean_gpu_shaders.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

using namespace oceangpu;

}  // namespace

OceanGpuCascade::OceanGpuCascade(const ocean::OceanCascade& cascade, SceneShaderApi api, bool slopes, bool jacobian,
                                 bool filtered)
    : n_(cascade.resolution),
      slopes_(slopes || filtered),
      jacobian_(jacobian),
      tileLength_(cascade.tileLength),
      filtered_(filtered),
      levels_(filtered ? std::countr_zero(static_cast<unsigned>(cascade.resolution)) + 1 : 1) {
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
  for (int f = 0; f < fields; ++f) maps_[f] = floatTexture(n_, n_, GL_RGBA32F, f == 1 ? levels_ : 1);
  if (filtered_) {
    moments_ = floatTexture(n_, n_, GL_RGBA32F, levels_);
    mapTarget_ = targetOfLevel({&maps_[0], &maps_[1], &moments_}, 0, "map");
    levelTargets_.resize(static_cast<size_t>(levels_));
    for (int l = 1; l < levels_; ++l) levelTargets_[static_cast<size_t>(l)] = targetOfLevel({&maps_[1], &moments_}, l, "pyramid");
  } else {
    mapTarget_ = targetOf(maps_[0], slopes_ ? &maps_[1] : nullptr, "map");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  emptyVao_ = makeVertexArray();

  // The named programs the scene description carries for the web clients (one table).
  using S = OceanPassShader;
  auto link = [&](S shader) { return linkPass(api, oceanPassShaderName(shader), oceanPassFragment(api, shader)); };
  evolve_ = link(slopes_ ? S::Evolve : S::EvolveDisplacement);
  stockham_ = link(slopes_ ? S::Stockham : S::StockhamSingle);
  pack_ = link(filtered_ ? S::PackFiltered : slopes_ ? S::Pack : S::PackDisplacement);
  if (filtered_) downsample_ = link(S::Downsample);
  if (jacobian) {
    evolveJacobian_ = link(S::EvolveJacobian);
    stockhamSingle_ = slopes_ ? link(S::StockhamSingle) : Program();
    for (int s = 0; s < 2; ++s) jacobianTargets_[s] = targetOf(spectra_[s][0], nullptr, "spectrum");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  checkGl("creating the ocean's GPU cascade");
}

size_t OceanGpuCascade::textureBytes(int n, bool slopes, bool filtered) {
  const size_t texels = static_cast<size_t>(n) * static_cast<size_t>(n), fields = slopes || filtered ? 2 : 1;
  const size_t rgba32f = 16;
  size_t pyramid = 0;  // filtered: the slope map's levels below 0, and the moments map's all
  for (size_t size = static_cast<size_t>(n); filtered && size >= 1; size /= 2)
    pyramid += size * size * rgba32f * (size == static_cast<size_t>(n) ? 1 : 2);
  return texels * (rgba32f + 4)                // h0 (RGBA32F) and the frequencies (R32UI)
         + texels * rgba32f * fields * 2       // the spectra, ping and pong
         + texels * rgba32f * fields           // the maps
         + pyramid                             // the filtered pyramids
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
  if (filtered_) downsample();
  checkGl("the ocean's GPU passes");
}

// Level l of both pyramids from level l - 1: each texture shows level l - 1 alone (base and
// max level), so the pass samples one level and draws into another of the same texture
// without a feedback loop; afterwards every level is visible again for the water's reader.
void OceanGpuCascade::downsample() const {
  glUseProgram(downsample_.id());
  glUniform1i(location(downsample_, "u_slopes"), 0);
  glUniform1i(location(downsample_, "u_moments"), 1);
  const Texture* pyramids[2] = {&maps_[1], &moments_};
  for (int l = 1; l < levels_; ++l) {
    for (int unit = 0; unit < 2; ++unit) {
      bindTexture(unit, *pyramids[unit]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, l - 1);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, l - 1);
    }
    glViewport(0, 0, n_ >> l, n_ >> l);
    drawInto(levelTargets_[static_cast<size_t>(l)]);
  }
  for (int unit = 0; unit < 2; ++unit) {
    bindTexture(unit, *pyramids[unit]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels_ - 1);
  }
  glViewport(0, 0, n_, n_);
}

std::vector<float> OceanGpuCascade::readLevel(bool moments, int level) const {
  if (!filtered_ || level < 0 || level >= levels_) throw std::logic_error("this ocean cascade has no such pyramid level");
  const int size = n_ >> level;
  std::vector<float> out(static_cast<size_t>(size) * size * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, level == 0 ? mapTarget_.id() : levelTargets_[static_cast<size_t>(level)].id());
  glReadBuffer(level == 0 ? (moments ? GL_COLOR_ATTACHMENT2 : GL_COLOR_ATTACHMENT1)
                          : (moments ? GL_COLOR_ATTACHMENT1 : GL_COLOR_ATTACHMENT0));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, out.data());
  checkGl("reading the ocean's pyramid back");
  return out;
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
