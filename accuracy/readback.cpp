#include "accuracy/readback.h"

#include <cctype>
#include <stdexcept>

#include "accuracy/gpu_executor.h"
#include "codegen/shader_interface.h"
#include "runtime/preview.h"

namespace wg::accuracy {
namespace {

// Adds the components of a GLSL expression of `size` floats as channels; returns the first.
int addChannels(ReadbackPlan& plan, const std::string& expr, int size) {
  static const char* const kComponents[] = {".x", ".y", ".z", ".w"};
  int first = static_cast<int>(plan.channels.size());
  for (int k = 0; k < size; ++k) plan.channels.push_back(size == 1 ? expr : "(" + expr + ")" + kComponents[k]);
  return first;
}

// The end of the call whose '(' is at `open`: the index just past its ')', or npos.
size_t callEnd(const std::string& text, size_t open) {
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    else if (text[i] == ')' && --depth == 0) return i + 1;
  }
  return std::string::npos;
}

// Where main()'s body begins and where its colour statement is.
struct MainBody {
  size_t begin = std::string::npos, colorLine = std::string::npos;
};
MainBody findMain(const std::string& text) {
  MainBody m;
  m.begin = text.find("void main()");
  if (m.begin == std::string::npos) return m;
  std::string color = std::string("\n  ") + iface::kColorOutput + " = ";
  size_t at = text.rfind(color);
  if (at != std::string::npos && at > m.begin) m.colorLine = at + 1;
  return m;
}

// How a fragment shader uses a sampler: every mention outside comments, and the
// texture() calls main() makes with it (their text).
struct SamplerUse {
  size_t uses = 0;
  std::vector<std::string> fetches;
};
SamplerUse samplerUse(const std::string& text, const MainBody& main, const std::string& name) {
  SamplerUse use;
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    char next = at + name.size() < text.size() ? text[at + name.size()] : '\0';
    if (std::isalnum(static_cast<unsigned char>(next)) || next == '_') continue;  // a longer name
    size_t lineStart = text.rfind('\n', at);
    size_t comment = text.find("//", lineStart == std::string::npos ? 0 : lineStart);
    if (comment < at) continue;  // named in a comment
    ++use.uses;
  }
  std::string call = "texture(" + name + ", ";
  for (size_t at = text.find(call, main.begin); at != std::string::npos && at < main.colorLine; at = text.find(call, at + 1)) {
    size_t end = callEnd(text, at + 7);
    if (end == std::string::npos) break;  // unbalanced: counted as a use only, so not read back
    use.fetches.push_back(text.substr(at, end - at));
  }
  return use;
}

}  // namespace

std::string planReadback(const CompileResult& result, const std::string& text, ReadbackPlan* out) {
  ReadbackPlan plan;
  MainBody main = findMain(text);
  if (main.colorLine == std::string::npos) return "the fragment shader writes no colour in main()";
  // Deferred water draws its fragment shader over the whole screen and takes the surface
  // builtins from G-buffer locals of main() (codegen/plan_deferred.cpp) under the names
  // of the forward varyings, which it then does not declare.
  const bool deferred = result.manifest.lists(RenderPass::DeferredWater);
  auto declaredLocal = [&](const std::string& name) {
    return text.find(" " + name + " = ", main.begin) < main.colorLine;
  };
  plan.mask = addChannels(plan, "-3.0", 1);  // kWaterMark
  if (!deferred) plan.fragDepth = addChannels(plan, "gl_FragCoord.z", 1);
  else if (declaredLocal("b_water_surface")) plan.fragDepth = addChannels(plan, "b_water_surface.w", 1);
  const auto& varyings = result.manifest.varyings;
  size_t nodeVaryings = 0;
  for (const auto& v : varyings) {
    int size = componentCount(v.type);
    if (deferred && !declaredLocal(v.name)) continue;
    if (v.carries == "world_position") plan.worldPosition = addChannels(plan, v.name, size);
    else if (v.carries == "normal") plan.normal = addChannels(plan, v.name, size);
    else if (v.carries == "uv") plan.uv = addChannels(plan, v.name, size);
    else {
      plan.varyings.push_back(addChannels(plan, v.name, size));
      ++nodeVaryings;
    }
  }
  if (nodeVaryings != result.program.varyings.size()) return "the manifest's varyings do not match the program's";
  for (const auto& row : sceneSamplerTable()) {
    std::string name(row.glslName);
    SamplerUse use = samplerUse(text, main, name);
    if (use.uses == 0) continue;
    // The declaration is the one other use: anything more is a library function sampling it.
    const bool onlyInMain = use.uses == use.fetches.size() + 1;
    if (!row.environment) {
      // The G-buffer: the reference takes it as this pixel's surface builtins.
      bool atThisPixel = deferred && onlyInMain;
      for (const auto& call : use.fetches) atThisPixel &= call == "texture(" + name + ", b_screen_uv)";
      if (!atThisPixel)
        return "it reads the water G-buffer (" + name + ") other than at the pixel's own position";
      // A shader that reads the surface only inside a node (the underwater node's water
      // term) declares no surface locals: fetch the texel itself.
      if (row.id == SceneSampler::WaterSurface) {
        const std::string texel = "texelFetch(" + name + ", ivec2(gl_FragCoord.xy), 0)";
        if (plan.worldPosition < 0) plan.worldPosition = addChannels(plan, texel + ".xyz", 3);
        if (plan.fragDepth < 0) plan.fragDepth = addChannels(plan, texel + ".w", 1);
      }
      continue;
    }
    int size = row.id == SceneSampler::SceneDepth ? 1 : 3;
    if (deferred && row.type == Type::Sampler2D) {
      static const char* const kSwizzle[] = {"", ".r", "", ".rgb"};
      plan.images.push_back(
          {row.id, addChannels(plan, "texelFetch(" + name + ", ivec2(gl_FragCoord.xy), 0)" + kSwizzle[size], size), size});
      continue;
    }
    if (!onlyInMain)
      return "the fragment shader samples " + name +
             " inside a library function (several look-ups a pixel, where the reference has one value per texture)";
    for (const auto& call : use.fetches) plan.lookups.push_back({row.id, addChannels(plan, call, size), size});
  }
  // Node textures sampled only in main() are read back too; one a library function
  // samples is left to the reference's own sampling (nodes/texture_sampling.h).
  for (const auto& t : result.manifest.textures) {
    if (t.scene) continue;
    SamplerUse use = samplerUse(text, main, t.name);
    if (use.fetches.empty() || use.uses != use.fetches.size() + 1) continue;
    for (const auto& call : use.fetches) plan.textureFetches.push_back({t.source, addChannels(plan, call, 4)});
  }
  *out = std::move(plan);
  return "";
}

std::vector<rt::ShaderSource> tapShaders(const std::vector<rt::ShaderSource>& water, const ReadbackPlan& plan, int frame) {
  std::vector<rt::ShaderSource> out = water;
  for (auto& stage : out) {
    if (stage.stage != GL_FRAGMENT_SHADER) continue;
    MainBody main = findMain(stage.text);
    if (main.colorLine == std::string::npos) throw std::logic_error("tapShaders: no colour statement in main()");
    std::string value;
    for (int k = 0; k < 3; ++k) {
      size_t c = static_cast<size_t>(3 * frame + k);
      value += (c < plan.channels.size() ? "float(" + plan.channels[c] + ")" : std::string("0.0")) + ", ";
    }
    size_t end = stage.text.find('\n', main.colorLine);
    stage.text.replace(main.colorLine, end - main.colorLine,
                       std::string("  ") + iface::kColorOutput + " = vec4(" + value + "1.0);");
    stage.name += " (read-back " + std::to_string(frame) + ")";
  }
  return out;
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
                                   const std::vector<rt::ShaderSource>& water, ReadbackPlan plan,
                                   const rt::RenderSettings& settings)
    : plan_(std::move(plan)) {
  for (int f = 0; f < plan_.frames(); ++f)
    renderers_.push_back(executor.waterFrames(result, tapShaders(water, plan_, f), /*edited=*/true, settings));
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
