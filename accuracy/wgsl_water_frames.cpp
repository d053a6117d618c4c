#include "accuracy/wgsl_water_frames.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

#include "accuracy/base64_text.h"
#include "codegen/emit_wgsl.h"
#include "nodes/texture_source.h"
#include "runtime/pass_plan.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"
#include "runtime/scene_description.h"
#include "runtime/uniform_values.h"

namespace wg::accuracy {
namespace {

using rt::RuntimeError;

// How long the page may take to translate the scene's shaders and take a water, and to render
// one frame (SwiftShader compiles the graph's module and the scene's on the CPU).
constexpr int kWgslWaterSeconds = 120;
constexpr int kWgslFrameSeconds = 300;

// The runner's plan (clients/three planPasses' form) from the runtime's.
nlohmann::json runnerPlan(const rt::PassPlan& plan) {
  nlohmann::json passes = nlohmann::json::array(), targets = nlohmann::json::array();
  for (rt::PassKind p : plan.passes) passes.push_back(rt::passName(p));
  for (const rt::TargetSpec& t : plan.targets) {
    nlohmann::json color = nullptr;
    if (t.color == rt::ColorFormat::Rgba32f) color = "rgba32f";
    else if (t.color == rt::ColorFormat::Rgba16f) color = "rgba16f";
    else if (t.color != rt::ColorFormat::None)
      throw RuntimeError(RuntimeError::Kind::Manifest, "target " + t.name + ": a colour format the WebGPU runner does not render");
    targets.push_back({{"name", t.name}, {"pass", rt::passName(t.producedBy)}, {"sampler", t.sampler}, {"color", color},
                       {"depth", t.depth != rt::DepthFormat::None}, {"cube", t.cube}, {"width", t.width}, {"height", t.height}});
  }
  return {{"passes", std::move(passes)}, {"targets", std::move(targets)}};
}

nlohmann::json matrixJson(const glm::mat4& m) {
  nlohmann::json out = nlohmann::json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out.push_back(m[c][r]);  // column-major, as GL's
  return out;
}

// One uniform of the buffer: where it lies and what it holds (the Vulkan runtime's rules,
// runtime/vk_water_bindings.cpp: a parameter's default clamped into its range, or a builtin).
struct WgslBufferUniform {
  WgslUniformMember member;
  const ManifestUniform* uniform = nullptr;
  std::vector<float> value;  // a parameter's
};

class WgslWaterFrames : public WaterFrames {
 public:
  WgslWaterFrames(WebgpuSession& session, const CompileResult& result, const rt::ShaderSource& module,
                  const rt::RenderSettings& settings)
      : session_(session), what_(module.name), width_(settings.width), height_(settings.height) {
    const Manifest& manifest = result.manifest;
    // A spectral ocean: the runner simulates it (watergraph-webgpu-ocean.js) from the module the
    // compile writes for web targets (codegen/ocean_module_js.h).
    std::string oceanModule;
    if (!manifest.oceans.empty()) {
      for (const OutputFile& f : result.files)
        if (f.name == manifest.oceanModule) oceanModule = f.contents;
      if (oceanModule.empty())
        throw RuntimeError(RuntimeError::Kind::Manifest, "the graph's spectral ocean has no ocean module (compile it for a web target)");
    }
    rt::PlanOptions po;
    po.width = settings.width;
    po.height = settings.height;
    po.floatColor = settings.floatColor;
    po.environmentSize = settings.environmentSize;
    plan_ = rt::planPasses(manifest, po);
    size_t end = 0;
    for (const ManifestUniform& u : manifest.uniforms) {
      if (isSampler(u.type)) continue;
      WgslBufferUniform b;
      b.member = wgslUniformMember(end, u.type);
      end = b.member.offset + b.member.size;
      b.uniform = &u;
      if (u.parameter) {
        b.value.assign(u.parameter->defaultValue.begin(), u.parameter->defaultValue.end());
        rt::clampIntoRange(b.value, u.parameter->min ? static_cast<float>(*u.parameter->min) : -std::numeric_limits<float>::infinity(),
                           u.parameter->max ? static_cast<float>(*u.parameter->max) : std::numeric_limits<float>::infinity());
      } else if (rt::builtinUniformValue(u.builtin, u.angularFrequency, rt::FrameValues{}).empty()) {
        throw RuntimeError(RuntimeError::Kind::Manifest, "uniform " + u.name + " holds a builtin the runtime does not provide");
      }
      buffer_.push_back(std::move(b));
    }
    bufferSize_ = end == 0 ? 0 : wgslUniformBufferSize(end);
    session_.sendSceneOnce();
    const rt::Mesh grid = rt::buildWaterGrid(settings.waterGridQuads);
    nlohmann::json textures = nlohmann::json::array();
    const std::map<std::string, rt::TextureOrigin> origins = rt::textureOrigins(result);
    for (const TextureInfo& t : manifest.textures) {
      if (t.scene || t.ocean) continue;
      auto origin = origins.find(t.name);
      const std::string graphDir = origin == origins.end() ? result.program.directory : origin->second.graphDir;
      const std::string owner = origin == origins.end() ? t.name : origin->second.owner;
      std::string why;
      auto img = loadTexture(t.source, graphDir, &why);
      if (!img || img->width <= 0 || img->height <= 0 ||
          img->rgba.size() != static_cast<size_t>(img->width) * static_cast<size_t>(img->height) * 4) {
        if (why.empty()) why = "no image data";
        throw rt::TextureLoadError(owner + ": texture '" + t.source + "' cannot be loaded: " + why, t.source, why);
      }
      textures.push_back({{"name", t.name}, {"width", img->width}, {"height", img->height},
                          {"rgba", base64Text(img->rgba.data(), img->rgba.size())}});
    }
    id_ = session_.nextWaterId++;
    session_.request({{"kind", "water"},
                      {"id", id_},
                      {"manifest", manifest.toJson()},
                      {"wgsl", module.text},
                      {"plan", runnerPlan(plan_)},
                      {"grid",
                       {{"vertices", base64Text(grid.vertices.data(), grid.vertices.size() * sizeof(float))},
                        {"indices", base64Text(grid.indices.data(), grid.indices.size() * sizeof(unsigned))},
                        {"floatsPerVertex", grid.floatsPerVertex}}},
                      {"textures", std::move(textures)},
                      {"oceanModule", oceanModule}},
                     kWgslWaterSeconds, what_);
  }

  ~WgslWaterFrames() override {
    try {
      session_.request({{"kind", "drop"}, {"water", id_}}, kWgslWaterSeconds, what_);
    } catch (const std::exception&) {
      // The helper already failed: the next request reports it.
    }
  }

  void setView(const rt::Camera& camera, const rt::SceneOptions& scene) override {
    camera_ = camera;
    scene_ = scene;
  }

  rt::Image render() override {
    // As the runtime's renderers set them (runtime/renderer.cpp frameValues).
    rt::FrameValues f;
    f.camera = camera_;
    f.view = camera_.view();
    f.projection = camera_.projection(static_cast<float>(width_) / static_cast<float>(std::max(height_, 1)));
    f.viewProjection = f.projection * f.view;
    f.sun = rt::sunDirection(scene_);
    f.time = scene_.time;
    f.width = width_;
    f.height = height_;
    std::vector<std::uint32_t> words(bufferSize_ / 4, 0);
    for (const WgslBufferUniform& b : buffer_) writeMember(words, b, b.uniform->parameter ? b.value
                                                                     : rt::builtinUniformValue(b.uniform->builtin, b.uniform->angularFrequency, f));
    nlohmann::json job = {{"kind", "frame"},
                          {"water", id_},
                          {"uniforms", base64Text(words.data(), words.size() * 4)},
                          {"camera",
                           {{"view", matrixJson(f.view)},
                            {"projection", matrixJson(f.projection)},
                            {"position", {camera_.position.x, camera_.position.y, camera_.position.z}}}},
                          {"sun", {f.sun.x, f.sun.y, f.sun.z}},
                          {"time", f.time}};
    nlohmann::json reply = session_.request(job, kWgslFrameSeconds, what_);
    const nlohmann::json& frame = reply["frame"];
    std::optional<std::vector<std::uint8_t>> bytes;
    if (frame.is_string()) bytes = bytesOfBase64Text(frame.get<std::string>());
    const size_t floats = static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4;
    if (!bytes || bytes->size() != floats * 4)
      throw RuntimeError(RuntimeError::Kind::Driver, what_ + ": the WebGPU helper returned no " + std::to_string(width_) + "x" +
                                                          std::to_string(height_) + " RGBA32F frame");
    rt::Image img;
    img.width = width_;
    img.height = height_;
    img.rgba32f.resize(floats);
    // The runner's rows are GL's (row 0 at the bottom); an rt::Image's run top to bottom.
    const size_t row = static_cast<size_t>(width_) * 4;
    for (int y = 0; y < height_; ++y)
      std::memcpy(&img.rgba32f[static_cast<size_t>(y) * row], bytes->data() + static_cast<size_t>(height_ - 1 - y) * row * 4,
                  row * 4);
    return img;
  }

  // As the runner samples its targets (watergraph-webgpu-passes.js sampledNearest): depth,
  // the G-buffer and RGBA32F texel for texel.
  bool samplesNearest(SceneSampler s) const override {
    for (const rt::TargetSpec& t : plan_.targets)
      if (t.sampler == sceneSamplerRow(s).glslName) return rt::sampledNearest(t, /*floatLinear=*/false);
    return false;
  }

 private:
  // `value` at the member's offset in 32-bit words (a mat3's columns padded to 16 bytes, a
  // bool as a u32).
  static void writeMember(std::vector<std::uint32_t>& words, const WgslBufferUniform& b, const std::vector<float>& value) {
    const size_t at = b.member.offset / 4;
    auto f32 = [&](size_t word, float x) { words.at(word) = std::bit_cast<std::uint32_t>(x); };
    switch (b.member.type) {
      case Type::Int: words.at(at) = std::bit_cast<std::uint32_t>(static_cast<std::int32_t>(value.at(0))); return;
      case Type::Bool: words.at(at) = value.at(0) != 0 ? 1u : 0u; return;
      case Type::Mat3:
        for (size_t c = 0; c < 3; ++c)
          for (size_t r = 0; r < 3; ++r) f32(at + 4 * c + r, value.at(3 * c + r));
        return;
      default:
        for (size_t i = 0; i < b.member.size / 4; ++i) f32(at + i, value.at(i));
    }
  }

  WebgpuSession& session_;
  std::string what_;
  int width_, height_;
  rt::PassPlan plan_;
  std::vector<WgslBufferUniform> buffer_;
  size_t bufferSize_ = 0;
  int id_ = -1;
  rt::Camera camera_;
  rt::SceneOptions scene_;
};

}  // namespace

std::unique_ptr<WaterFrames> makeWgslWaterFrames(WebgpuSession& session, const CompileResult& result,
                                                 const rt::ShaderSource& module, const rt::RenderSettings& settings) {
  return std::make_unique<WgslWaterFrames>(session, result, module, settings);
}

}  // namespace wg::accuracy
