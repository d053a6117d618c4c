#include "accuracy/readback.h"

#include <algorithm>
#include <stdexcept>

#include "accuracy/gpu_executor.h"
#include "runtime/preview.h"

namespace wg::accuracy {
namespace {

// Adds the `size` components of `value` as channels; returns the first.
int addChannels(ReadbackPlan& plan, TapChannel value, int size) {
  int first = static_cast<int>(plan.channels.size());
  for (int k = 0; k < size; ++k) {
    value.component = size == 1 ? -1 : k;
    plan.channels.push_back(value);
  }
  return first;
}

TapChannel tapOf(TapChannel::Kind kind, size_t index = 0) {
  TapChannel c;
  c.kind = kind;
  c.index = index;
  return c;
}

}  // namespace

std::string planReadback(const CompileResult& result, const ShaderPlan& shaders, ReadbackPlan* out) {
  ReadbackPlan plan;
  const PlannedStage* fs = shaders.stage(ShaderStage::Fragment);
  if (!fs || fs->colorStatement == std::string::npos) return "the fragment shader writes no colour in main()";
  // Deferred water draws its fragment shader over the whole screen and takes the surface
  // builtins from G-buffer locals of main() (codegen/plan_deferred.cpp) under the names
  // of the forward varyings, which it then does not declare.
  const bool deferred = shaders.kind == ShaderPlan::Kind::Deferred;
  TapChannel mark = tapOf(TapChannel::Kind::Constant);
  mark.constant = kWaterMark;
  plan.mask = addChannels(plan, mark, 1);
  if (tapHoldsFragDepth(shaders)) plan.fragDepth = addChannels(plan, tapOf(TapChannel::Kind::FragDepth), 1);
  size_t nodeVaryings = 0;
  for (size_t i = 0; i < shaders.varyings.size(); ++i) {
    const VaryingInfo& v = shaders.varyings[i];
    if (!tapHoldsVarying(shaders, i)) continue;
    int first = addChannels(plan, tapOf(TapChannel::Kind::Varying, i), componentCount(v.type));
    if (v.carries == "world_position") plan.worldPosition = first;
    else if (v.carries == "normal") plan.normal = first;
    else if (v.carries == "uv") plan.uv = first;
    else {
      plan.varyings.push_back(first);
      ++nodeVaryings;
    }
  }
  if (nodeVaryings != result.program.varyings.size()) return "the manifest's varyings do not match the program's";
  // The look-ups main() makes of one sampler (indices into fs->fetches), in its order.
  auto fetchesOf = [&](const std::string& name) {
    std::vector<size_t> at;
    for (size_t k = 0; k < fs->fetches.size(); ++k)
      if (fs->fetches[k].sampler == name) at.push_back(k);
    return at;
  };
  auto declared = [&](size_t texture) {
    return std::find(fs->textures.begin(), fs->textures.end(), texture) != fs->textures.end();
  };
  for (const auto& row : sceneSamplerTable()) {
    size_t texture = shaders.textures.size();
    for (size_t i = 0; i < shaders.textures.size(); ++i)
      if (shaders.textures[i].scene == row.id && declared(i)) texture = i;
    if (texture == shaders.textures.size()) continue;
    const std::string name(row.glslName);
    const std::vector<size_t> fetches = fetchesOf(name);
    const bool onlyInMain = !fs->handedOn.count(name);
    if (!row.environment) {
      // The G-buffer: the reference takes it as this pixel's surface builtins.
      bool atThisPixel = deferred && onlyInMain;
      for (size_t k : fetches) atThisPixel &= fs->fetches[k].atScreenUv;
      if (!atThisPixel)
        return "it reads the water G-buffer (" + name + ") other than at the pixel's own position";
      // A shader that reads the surface only inside a node (the underwater node's water
      // term) declares no surface locals: fetch the texel itself.
      if (row.id == SceneSampler::WaterSurface) {
        TapChannel texel = tapOf(TapChannel::Kind::TexelAtPixel, texture);
        if (plan.worldPosition < 0) plan.worldPosition = addChannels(plan, texel, 3);
        if (plan.fragDepth < 0) {
          texel.component = 3;
          plan.fragDepth = static_cast<int>(plan.channels.size());
          plan.channels.push_back(texel);
        }
      }
      continue;
    }
    int size = row.id == SceneSampler::SceneDepth ? 1 : 3;
    if (deferred && row.type == Type::Sampler2D) {
      // Read back whole: a texel per pixel, its first `size` components.
      TapChannel texel = tapOf(TapChannel::Kind::TexelAtPixel, texture);
      int first = static_cast<int>(plan.channels.size());
      for (int k = 0; k < size; ++k) {
        texel.component = k;
        plan.channels.push_back(texel);
      }
      plan.images.push_back({row.id, first, size});
      continue;
    }
    if (!onlyInMain)
      return "the fragment shader samples " + name +
             " inside a library function (several look-ups a pixel, where the reference has one value per texture)";
    for (size_t k : fetches) plan.lookups.push_back({row.id, addChannels(plan, tapOf(TapChannel::Kind::Fetch, k), size), size});
  }
  // Node textures sampled only in main() are read back too; one handed to a library
  // function is left to the reference's own sampling (nodes/texture_sampling.h).
  for (size_t i = 0; i < shaders.textures.size(); ++i) {
    const TextureInfo& t = shaders.textures[i];
    if (t.scene || !declared(i)) continue;
    const std::vector<size_t> fetches = fetchesOf(t.name);
    if (fetches.empty() || fs->handedOn.count(t.name)) continue;
    for (size_t k : fetches) plan.textureFetches.push_back({t.source, addChannels(plan, tapOf(TapChannel::Kind::Fetch, k), 4)});
  }
  *out = std::move(plan);
  return "";
}

std::vector<TapChannel> tapFrameChannels(const ReadbackPlan& plan, int frame) {
  std::vector<TapChannel> channels;
  for (size_t c = 3 * static_cast<size_t>(frame); c < plan.channels.size() && channels.size() < 3; ++c)
    channels.push_back(plan.channels[c]);
  return channels;
}

std::vector<rt::ShaderSource> tapShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders, Target target,
                                         const std::vector<TapChannel>& channels, int frame) {
  std::vector<rt::ShaderSource> out = water;
  for (auto& stage : out) {
    if (stage.stage != GL_FRAGMENT_SHADER) continue;
    stage.text = emitTapFragment(shaders, target, channels).text;
    stage.name += " (read-back " + std::to_string(frame) + ")";
  }
  return out;
}

std::vector<rt::ShaderSource> tapShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders, Target target,
                                         const ReadbackPlan& plan, int frame) {
  return tapShaders(water, shaders, target, tapFrameChannels(plan, frame), frame);
}

bool ReadbackImage::water(int px, int py, const ReadbackPlan& plan) const {
  if (px < 0 || py < 0 || px >= width || py >= height) return false;
  return at(px, py, plan.mask) == kWaterMark;
}

SceneImage ReadbackImage::sceneImage(const ReadbackPlan::Image& image, bool nearest) const {
  SceneImage out;
  out.width = width, out.height = height, out.channels = image.size, out.nearest = nearest;
  out.texels.resize(static_cast<size_t>(width) * height * image.size);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      for (int c = 0; c < image.size; ++c)
        out.texels[(static_cast<size_t>(j) * width + i) * image.size + c] = at(i, height - 1 - j, image.channel + c);
  return out;
}

bool ReadbackRenderer::samplesNearest(SceneSampler s) const { return renderers_.front()->samplesNearest(s); }

ReadbackRenderer::ReadbackRenderer(GpuExecutor& executor, const CompileResult& result,
                                   const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders, ReadbackPlan plan,
                                   const rt::RenderSettings& settings, const ShaderMutation& mutation)
    : plan_(std::move(plan)) {
  for (int f = 0; f < plan_.frames(); ++f) {
    std::vector<rt::ShaderSource> taps = executor.tapFrameShaders(water, shaders, tapFrameChannels(plan_, f), f);
    for (auto& stage : taps)
      if (stage.stage == GL_FRAGMENT_SHADER) mutateText(stage.text, mutation);
    renderers_.push_back(executor.waterFrames(result, taps, /*edited=*/true, settings));
  }
}

ReadbackRenderer::~ReadbackRenderer() = default;

ReadbackImage ReadbackRenderer::read(const rt::Camera& camera, const rt::SceneOptions& scene) {
  ReadbackImage img;
  img.channels = static_cast<int>(plan_.channels.size());
  for (size_t f = 0; f < renderers_.size(); ++f) {
    WaterFrames& r = *renderers_[f];
    r.setView(camera, scene);
    rt::Image frame = r.render();
    if (f == 0) {
      img.width = frame.width, img.height = frame.height;
      img.values.assign(static_cast<size_t>(img.width) * img.height * img.channels, 0.0f);
    }
    for (size_t p = 0; p < static_cast<size_t>(img.width) * img.height; ++p)
      for (int k = 0; k < 3; ++k) {
        size_t c = 3 * f + static_cast<size_t>(k);
        if (c < static_cast<size_t>(img.channels)) img.values[p * img.channels + c] = frame.rgba32f[p * 4 + k];
      }
  }
  return img;
}

}  // namespace wg::accuracy
