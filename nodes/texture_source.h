#pragma once
// Textures that nodes sample: a PNG path relative to the graph file, or a built-in
// procedural texture ("builtin:water_normal") generated deterministically so graphs need
// no binary assets. The runtime uploads exactly these texels; the CPU reference samples
// them by GL's rules for the sampler state (nodes/texture_sampling.h), so both see the
// same data.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/sampler_state.h"
#include "core/texture_check.h"
#include "core/value.h"

namespace wg {

struct TextureImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // row 0 is v = 0 (GL's first row), 4 bytes per texel

  // Bilinear with wrap-around (GL_LINEAR, GL_REPEAT, no mipmaps), texel centres at
  // (i + 0.5) / size; returns vec4 in [0, 1]. The default SamplerState of
  // sampleTexture (nodes/texture_sampling.h), which does the work.
  Value sample(double u, double v) const;
  std::uint8_t at(int x, int y, int channel) const {
    return rgba[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4 + static_cast<size_t>(channel)];
  }
};

// Loads or generates; on failure returns nullopt and sets *error (e.g. a malformed PNG).
std::optional<TextureImage> loadTexture(std::string_view source, const std::string& graphDir, std::string* error);

// Generates a builtin texture (name without the prefix); nullopt for an unknown name.
std::optional<TextureImage> generateBuiltinTexture(std::string_view name);

// Loads each source once per process run of a tool (the CPU reference samples a lot).
class TextureCache {
 public:
  // Throws std::runtime_error with the loader's message when the source cannot be loaded.
  const TextureImage& get(const std::string& source, const std::string& graphDir);
  // Levels 1.. of the texture's mip chain as glGenerateMipmap builds it for that colour
  // space (buildMipChain, nodes/texture_sampling.h), built on first use.
  const std::vector<TextureImage>& mipChain(const std::string& source, const std::string& graphDir,
                                            TextureColorSpace colorSpace);

 private:
  std::map<std::string, std::unique_ptr<TextureImage>> images_;
  std::map<std::string, std::unique_ptr<std::vector<TextureImage>>> chains_;
};

}  // namespace wg
