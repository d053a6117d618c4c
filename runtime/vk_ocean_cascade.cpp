// One cascade of the spectral ocean on Vulkan (runtime/vk_ocean_cascade.h).
#include "runtime/vk_ocean_cascade.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace wg::rt {
namespace {

using oceangpu::OceanPass;

}  // namespace

VkOceanCascade::VkOceanCascade(VkOceanPasses& passes, const ocean::OceanCascade& cascade, bool slopes, bool jacobian,
                               bool filtered)
    : context_(passes.context()),
      n_(cascade.resolution),
      slopes_(slopes || filtered),
      tileLength_(cascade.tileLength),
      filtered_(filtered),
      levels_(filtered ? std::countr_zero(static_cast<unsigned>(cascade.resolution)) + 1 : 1) {
  // h0(k) and conj(h0(-k)) per texel, rounded once from double, as the GL runtime uploads them.
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
  h0_ = makeOceanImage(context_, n_, n_, VK_FORMAT_R32G32B32A32_SFLOAT);
  uploadTexels(context_, h0_, h0.data());
  frequency_ = makeOceanImage(context_, n_, n_, VK_FORMAT_R32_UINT);
  uploadTexels(context_, frequency_, cascade.frequency.data());
  // Twiddles exp(2 pi i m / N), m < N/2, computed in double and rounded once.
  std::vector<float> twiddle(static_cast<size_t>(n_));
  for (int m = 0; m < n_ / 2; ++m) {
    double angle = 2.0 * ocean::kPi * m / n_;
    twiddle[static_cast<size_t>(m) * 2] = static_cast<float>(std::cos(angle));
    twiddle[static_cast<size_t>(m) * 2 + 1] = static_cast<float>(std::sin(angle));
  }
  twiddle_ = makeOceanImage(context_, n_ / 2, 1, VK_FORMAT_R32G32_SFLOAT);
  uploadTexels(context_, twiddle_, twiddle.data());
  const int fields = slopes_ ? 2 : 1;
  for (int s = 0; s < 2; ++s)
    for (int f = 0; f < fields; ++f) spectra_[s][f] = makeOceanImage(context_, n_, n_, VK_FORMAT_R32G32B32A32_SFLOAT);
  // The maps start readable: a water pass may bind them before the first update records.
  context_.submit([&](VkCommandBuffer cmd) {
    for (int f = 0; f < fields; ++f) {
      maps_[f] = makeOceanImage(context_, n_, n_, VK_FORMAT_R32G32B32A32_SFLOAT, f == 1 ? static_cast<uint32_t>(levels_) : 1);
      maps_[f].transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
    if (filtered_) {
      moments_ = makeOceanImage(context_, n_, n_, VK_FORMAT_R32G32B32A32_SFLOAT, static_cast<uint32_t>(levels_));
      moments_.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
  });
  evolve_ = &passes.get(OceanPass::Evolve, {slopes_, false});
  stockham_ = &passes.get(OceanPass::Stockham, {slopes_, false});
  pack_ = &passes.get(OceanPass::Pack, {slopes_, false, filtered_});
  if (filtered_) downsample_ = &passes.get(OceanPass::Downsample);
  if (jacobian) {
    evolveJacobian_ = &passes.get(OceanPass::Evolve, {false, true});
    stockhamSingle_ = &passes.get(OceanPass::Stockham, {false, false});
  }
}

void VkOceanCascade::evolve(VkCommandBuffer cmd, VkOceanPass& pass, double time, const std::vector<VkImageOwner*>& outputs) {
  pass.record(cmd, {&h0_, &frequency_},
              {oceanConstantWord(ocean::loopFraction(time)), oceanConstantWord(static_cast<float>(2.0 * ocean::kPi / tileLength_)),
               oceanConstantWord(static_cast<int32_t>(n_))},
              outputs);
}

int VkOceanCascade::transform(VkCommandBuffer cmd, VkOceanPass& stockham, bool both) {
  int current = 0;
  for (int vertical = 0; vertical < 2; ++vertical)
    for (int ns = 1; ns < n_; ns *= 2) {
      const int next = 1 - current;
      std::vector<VkImageOwner*> inputs = {&spectra_[current][0], &twiddle_}, outputs = {&spectra_[next][0]};
      if (both) {
        inputs.push_back(&spectra_[current][1]);
        outputs.push_back(&spectra_[next][1]);
      }
      stockham.record(cmd, inputs,
                      {oceanConstantWord(static_cast<int32_t>(ns)), oceanConstantWord(static_cast<int32_t>(n_)),
                       oceanConstantWord(static_cast<int32_t>(vertical))},
                      outputs);
      current = next;
    }
  return current;
}

VkImageOwner& VkOceanCascade::recordJacobianFields(VkCommandBuffer cmd, double time) {
  if (!evolveJacobian_) throw std::logic_error("this ocean cascade was not made to compute its Jacobian's fields alone");
  evolve(cmd, *evolveJacobian_, time, {&spectra_[0][0]});
  return spectra_[transform(cmd, *stockhamSingle_, false)][0];
}

void VkOceanCascade::record(VkCommandBuffer cmd, double time, double choppiness) {
  std::vector<VkImageOwner*> spectra = {&spectra_[0][0]};
  if (slopes_) spectra.push_back(&spectra_[0][1]);
  evolve(cmd, *evolve_, time, spectra);
  const int current = transform(cmd, *stockham_, slopes_);
  std::vector<VkImageOwner*> inputs = {&spectra_[current][0]}, maps = {&maps_[0]};
  if (slopes_) {
    inputs.push_back(&spectra_[current][1]);
    maps.push_back(&maps_[1]);
  }
  if (filtered_) maps.push_back(&moments_);
  pack_->record(cmd, inputs, {oceanConstantWord(static_cast<float>(choppiness))}, maps);
  if (filtered_) {
    // Level l of both pyramids from level l - 1 of the same images (one view per level), in
    // GENERAL layout, which both sampling and drawing allow; a barrier between levels.
    maps_[1].transition(cmd, VK_IMAGE_LAYOUT_GENERAL);
    moments_.transition(cmd, VK_IMAGE_LAYOUT_GENERAL);
    for (int l = 1; l < levels_; ++l) {
      const uint32_t above = static_cast<uint32_t>(l - 1), level = static_cast<uint32_t>(l), size = static_cast<uint32_t>(n_ >> l);
      downsample_->recordLevels(cmd, {maps_[1].levelView(above), moments_.levelView(above)},
                                {maps_[1].levelView(level), moments_.levelView(level)}, {size, size});
      VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      b.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
      b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 1, &b,
                           0, nullptr, 0, nullptr);
    }
  }
  for (VkImageOwner* map : maps) map->transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

VkImageOwner& VkOceanCascade::momentsMap() {
  if (!filtered_) throw std::logic_error("this ocean cascade computes no moments map");
  return moments_;
}

VkImageOwner& VkOceanCascade::slopeMap() {
  if (!slopes_) throw std::logic_error("this ocean cascade computes no slope map");
  return maps_[1];
}

namespace {

std::vector<float> oceanMapFloats(VkContext& context, VkImageOwner& image, uint32_t level = 0) {
  std::vector<unsigned char> bytes = readBack(context, image, level);
  std::vector<float> out(bytes.size() / sizeof(float));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
  return out;
}

}  // namespace

std::vector<float> VkOceanCascade::readDisplacement() { return oceanMapFloats(context_, maps_[0]); }
std::vector<float> VkOceanCascade::readSlopes() { return oceanMapFloats(context_, slopeMap()); }
std::vector<float> VkOceanCascade::readLevel(bool moments, int level) {
  if (!filtered_ || level < 0 || level >= levels_) throw std::logic_error("this ocean cascade has no such pyramid level");
  return oceanMapFloats(context_, moments ? moments_ : maps_[1], static_cast<uint32_t>(level));
}

}  // namespace wg::rt
