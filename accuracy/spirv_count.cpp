#include "accuracy/spirv_count.h"

#include <spirv-tools/optimizer.hpp>

namespace wg::accuracy {

std::vector<uint32_t> spirvWords(const std::string& bytes) {
  std::vector<uint32_t> words(bytes.size() / 4);
  for (size_t i = 0; i < words.size(); ++i)
    for (int b = 0; b < 4; ++b) words[i] |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[i * 4 + static_cast<size_t>(b)])) << (8 * b);
  return words;
}

int optimisedInstructionCount(const std::vector<uint32_t>& words) {
  spvtools::Optimizer opt(SPV_ENV_VULKAN_1_0);
  opt.RegisterPerformancePasses();
  std::vector<uint32_t> out;
  if (!opt.Run(words.data(), words.size(), &out)) return -1;
  int count = 0;
  for (size_t i = 5; i < out.size();) {  // after the 5-word header
    uint32_t n = out[i] >> 16;
    if (n == 0) return -1;
    ++count;
    i += n;
  }
  return count;
}

}  // namespace wg::accuracy
