// The WebGPU side of GpuExecutor (gpu_executor.h): the probe plan's WGSL module
// (codegen/emit_wgsl.h emitWgslProbe) run in headless Chromium's WebGPU by
// clients/webgpu/probe_server.mjs, one Chromium for every probe of the executor. As on GL and
// Vulkan, each case is one pixel of an RGBA32F target drawn by a full-screen triangle
// restricted to it; here the case's uniforms are written at the module's WGSL offsets
// (wgslUniformLayout), each scene texture is a 1x1 RGBA32F texture holding the case's texel
// (nearest), a node texture is uploaded as the runtime uploads it, and the pixels come back as
// their float32 bit patterns (NaN and Inf included). Spectral ocean maps and mipmapped node
// textures are not in this runner (Kind::Manifest).
#include <bit>
#include <cstdint>

#include "accuracy/gpu_executor.h"
#include "accuracy/json_line_process.h"
#include "accuracy/probe_gpu.h"
#include "codegen/compile_wgsl.h"
#include "codegen/emit_wgsl.h"
#include "nodes/texture_source.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

using rt::RuntimeError;

// How long Chromium may take to start and hand out an adapter, and to run one probe shader
// over its cases (SwiftShader compiles the library's functions on the CPU).
constexpr int kWebgpuStartSeconds = 120;
constexpr int kWebgpuProbeSeconds = 300;

std::string base64OfTexels(const std::vector<std::uint8_t>& bytes) {
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = std::uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= std::uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= bytes[i + 2];
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

// One uniform's value at its offset in the buffer's 32-bit words (WGSL's uniform layout:
// a mat3's columns padded to 16 bytes, a bool as a u32).
void writeWgslUniform(std::vector<std::uint32_t>& words, const WgslUniformMember& m, const Value& v) {
  const size_t at = m.offset / 4;
  auto f32 = [&](size_t word, double x) { words.at(word) = std::bit_cast<std::uint32_t>(static_cast<float>(x)); };
  switch (m.type) {
    case Type::Int: words.at(at) = std::bit_cast<std::uint32_t>(static_cast<std::int32_t>(v.c[0])); return;
    case Type::Bool: words.at(at) = v.c[0] != 0 ? 1u : 0u; return;
    case Type::Mat3:
      for (size_t c = 0; c < 3; ++c)
        for (size_t r = 0; r < 3; ++r) f32(at + 4 * c + r, v.c[3 * c + r]);
      return;
    default:
      for (size_t i = 0; i < m.size / 4; ++i) f32(at + i, v.c[i]);
  }
}

class WgslExecutor : public GpuExecutor {
 public:
  explicit WgslExecutor(const WebgpuTools& tools) {
    try {
      helper_ = std::make_unique<JsonLineProcess>(
          std::vector<std::string>{tools.node, tools.clientDir + "/probe_server.mjs", "--chromium", tools.chromium});
      nlohmann::json ready = helper_->receive(kWebgpuStartSeconds);
      if (ready.contains("skipped"))
        throw RuntimeError(RuntimeError::Kind::Environment, "WebGPU is not available: " + ready["skipped"].get<std::string>());
      device_ = ready.value("device", std::string("WebGPU"));
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const RuntimeError*>(&e)) throw;
      throw RuntimeError(RuntimeError::Kind::Environment, std::string("the WebGPU helper did not start: ") + e.what());
    }
  }
  Target target() const override { return Target::Es300; }
  std::string targetLabel() const override { return kWgslTargetName; }
  std::string deviceName() const override { return device_; }

  std::optional<EmitResult> probeShader(const Program& program, const std::string& sourceName, Diagnostics& diags) override {
    try {
      return emitWgslProbe(program, sourceName);
    } catch (const WgslRefused& r) {
      reportWgslMessage(program, std::vector<int>{r.op}, 1, "no WGSL form (--target wgsl): " + r.message,
                        DiagCode::WgslRefused, diags);
      return std::nullopt;
    }
  }

  std::vector<std::array<float, 4>> runProbe(const EmitResult& shader, const Program& program,
                                             const std::vector<ProbeCase>& cases, const std::string& what) override {
    if (cases.empty()) return {};
    if (shader.shaders.size() != 1) throw RuntimeError(RuntimeError::Kind::Manifest, what + ": not a WGSL probe module");
    const std::vector<WgslUniformMember> layout = wgslUniformLayout(shader.uniforms);
    const size_t bufferSize = layout.empty() ? 0 : wgslUniformBufferSize(layout.back().offset + layout.back().size);
    nlohmann::json request = {{"what", what}, {"wgsl", shader.shaders.front().text}, {"uniformSize", bufferSize}};
    nlohmann::json textures = nlohmann::json::array();
    std::vector<size_t> sceneTextures;
    for (size_t k = 0; k < shader.textures.size(); ++k) {
      const TextureInfo& t = shader.textures[k];
      nlohmann::json entry = {{"binding", wgslTextureBinding(k)}, {"cube", t.type == Type::SamplerCube}};
      if (t.ocean)
        throw RuntimeError(RuntimeError::Kind::Manifest,
                           what + ": the WebGPU probe has no spectral ocean simulation (its maps come from the runtime's)");
      if (t.scene) {
        entry["kind"] = "scene";
        sceneTextures.push_back(k);
      } else {
        if (t.sampler.filter == TextureFilter::Mipmapped)
          throw RuntimeError(RuntimeError::Kind::Manifest, what + ": texture '" + t.source +
                                                               "' is mipmapped, which the WebGPU probe does not sample");
        std::string why;
        auto img = loadTexture(t.source, program.directory, &why);
        if (!img || img->width <= 0 || img->height <= 0)
          throw RuntimeError(RuntimeError::Kind::Manifest, "texture '" + t.source + "' cannot be loaded: " + why);
        entry["kind"] = "file";
        entry["width"] = img->width;
        entry["height"] = img->height;
        entry["rgba"] = base64OfTexels(img->rgba);
        entry["wrap"] = std::string(wrapName(t.sampler.wrap));
        entry["filter"] = std::string(filterName(t.sampler.filter));
        entry["srgb"] = t.sampler.colorSpace == TextureColorSpace::Srgb;
      }
      textures.push_back(std::move(entry));
    }
    request["textures"] = std::move(textures);
    nlohmann::json runs = nlohmann::json::array();
    for (size_t i = 0; i < cases.size(); ++i) {
      std::vector<std::uint32_t> words(bufferSize / 4, 0);
      size_t member = 0;
      for (const UniformInfo& u : shader.uniforms) {
        if (isSampler(u.type)) continue;
        writeWgslUniform(words, layout.at(member++), probeUniformValue(u, program, cases[i], i));
      }
      nlohmann::json texels = nlohmann::json::array();
      for (size_t k : sceneTextures) {
        std::array<float, 4> texel = sceneSamplerRow(*shader.textures[k].scene).caseTexel(cases[i].env);
        nlohmann::json bits = nlohmann::json::array();
        for (float f : texel) bits.push_back(std::bit_cast<std::uint32_t>(f));
        texels.push_back(std::move(bits));
      }
      runs.push_back({{"uniforms", words}, {"texels", std::move(texels)}});
    }
    request["cases"] = std::move(runs);
    nlohmann::json reply;
    try {
      helper_->send(request);
      reply = helper_->receive(kWebgpuProbeSeconds);
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const RuntimeError*>(&e)) throw;
      throw RuntimeError(RuntimeError::Kind::Environment, what + ": the WebGPU helper failed: " + e.what());
    }
    if (reply.contains("error")) throw RuntimeError(RuntimeError::Kind::Driver, what + ": " + reply["error"].get<std::string>());
    const nlohmann::json& pixels = reply.at("pixels");
    if (!pixels.is_array() || pixels.size() != 4 * cases.size())
      throw RuntimeError(RuntimeError::Kind::Driver, what + ": the WebGPU helper returned " + std::to_string(pixels.size()) +
                                                         " values for " + std::to_string(cases.size()) + " cases");
    std::vector<std::array<float, 4>> out(cases.size());
    for (size_t i = 0; i < cases.size(); ++i)
      for (size_t ch = 0; ch < 4; ++ch) out[i][ch] = std::bit_cast<float>(pixels[4 * i + ch].get<std::uint32_t>());
    return out;
  }

  std::unique_ptr<WaterFrames> waterFrames(const CompileResult&, const std::vector<rt::ShaderSource>&, bool,
                                           const rt::RenderSettings&) override {
    throw RuntimeError(RuntimeError::Kind::Manifest, "the WebGPU executor runs probes; it renders no water frames");
  }

 private:
  std::unique_ptr<JsonLineProcess> helper_;
  std::string device_;
};

}  // namespace

std::unique_ptr<GpuExecutor> makeWgslExecutor(const WebgpuTools& tools) { return std::make_unique<WgslExecutor>(tools); }

}  // namespace wg::accuracy
