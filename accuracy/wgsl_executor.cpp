// The WebGPU side of GpuExecutor (gpu_executor.h): the probe plan's WGSL module
// (codegen/emit_wgsl.h emitWgslProbe) run in headless Chromium's WebGPU by
// clients/webgpu/executor_server.mjs, one Chromium for every probe and check of the executor
// (accuracy/webgpu_session.h); check's frames are accuracy/wgsl_water_frames.h. As on GL and
// Vulkan, each case is one pixel of an RGBA32F target drawn by a full-screen triangle
// restricted to it; here the case's uniforms are written at the module's WGSL offsets
// (wgslUniformLayout), each scene texture is a 1x1 RGBA32F texture holding the case's texel
// (nearest), a node texture is uploaded as the runtime uploads it, and the pixels come back as
// their float32 bit patterns (NaN and Inf included); a mipmapped node texture with its full
// chain (clients/webgpu/watergraph-webgpu-mipmaps.js); the spectral oceans' maps from the page's
// own simulation (clients/webgpu/watergraph-webgpu-ocean.js, the runner's) at each case's time.
#include <bit>
#include <cstdint>

#include "accuracy/gpu_executor.h"
#include "accuracy/base64_text.h"
#include "accuracy/webgpu_session.h"
#include "accuracy/wgsl_water_frames.h"
#include "accuracy/probe_gpu.h"
#include "codegen/compile_wgsl.h"
#include "codegen/emit_wgsl.h"
#include "codegen/ocean_module_js.h"
#include "codegen/manifest.h"
#include "codegen/readback_taps.h"
#include "nodes/texture_source.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

using rt::RuntimeError;

// How long one probe shader may take over its cases (SwiftShader compiles the library's
// functions on the CPU).
constexpr int kWebgpuProbeSeconds = 300;

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

// What the page needs to simulate the oceans a probe module reads
// (clients/webgpu/watergraph-webgpu-probe.js): a manifest of the probe's oceans and ocean
// maps, written by the manifest's own writer, and the ocean module a compile writes for web
// targets.
nlohmann::json probeOcean(const EmitResult& shader, const Program& program) {
  Manifest m;
  m.graph = program.graphName.empty() ? "probe" : program.graphName;
  m.oceans = shader.oceans;
  for (const TextureInfo& t : shader.textures)
    if (t.ocean) m.textures.push_back(t);
  return {{"manifest", m.toJson()}, {"module", oceanModuleJs(m.graph, program, shader.oceans)}};
}

class WgslExecutor : public GpuExecutor {
 public:
  explicit WgslExecutor(const WebgpuTools& tools) : session_(tools) {}
  Target target() const override { return Target::Es300; }
  std::string targetLabel() const override { return kWgslTargetName; }
  std::string deviceName() const override { return session_.device(); }

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
    // An ocean map is bound by its name in the job's ocean manifest.
    const nlohmann::json ocean = shader.oceans.empty() ? nlohmann::json() : probeOcean(shader, program);
    for (size_t k = 0; k < shader.textures.size(); ++k) {
      const TextureInfo& t = shader.textures[k];
      nlohmann::json entry = {{"binding", wgslTextureBinding(k)}, {"cube", t.type == Type::SamplerCube}};
      if (t.ocean) {
        entry["kind"] = "ocean";
        entry["name"] = t.name;
      } else if (t.scene) {
        entry["kind"] = "scene";
        sceneTextures.push_back(k);
      } else {
        std::string why;
        auto img = loadTexture(t.source, program.directory, &why);
        if (!img || img->width <= 0 || img->height <= 0)
          throw RuntimeError(RuntimeError::Kind::Manifest, "texture '" + t.source + "' cannot be loaded: " + why);
        entry["kind"] = "file";
        entry["width"] = img->width;
        entry["height"] = img->height;
        entry["rgba"] = base64Text(img->rgba.data(), img->rgba.size());
        entry["wrap"] = std::string(wrapName(t.sampler.wrap));
        entry["filter"] = std::string(filterName(t.sampler.filter));
        entry["srgb"] = t.sampler.colorSpace == TextureColorSpace::Srgb;
      }
      textures.push_back(std::move(entry));
    }
    request["textures"] = std::move(textures);
    if (!shader.oceans.empty()) {
      session_.sendSceneOnce();  // the simulation runs the description's pass shaders
      request["ocean"] = ocean;
    }
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
      runs.push_back({{"uniforms", words}, {"texels", std::move(texels)}, {"time", cases[i].env.time[0]}});
    }
    request["cases"] = std::move(runs);
    nlohmann::json reply = session_.request(request, kWebgpuProbeSeconds, what);
    const nlohmann::json& pixels = reply.at("pixels");
    if (!pixels.is_array() || pixels.size() != 4 * cases.size())
      throw RuntimeError(RuntimeError::Kind::Driver, what + ": the WebGPU helper returned " + std::to_string(pixels.size()) +
                                                         " values for " + std::to_string(cases.size()) + " cases");
    std::vector<std::array<float, 4>> out(cases.size());
    for (size_t i = 0; i < cases.size(); ++i)
      for (size_t ch = 0; ch < 4; ++ch) out[i][ch] = std::bit_cast<float>(pixels[4 * i + ch].get<std::uint32_t>());
    return out;
  }

  // check: the compile's WGSL module (compiled with CompileOptions::wgsl) as one source.
  std::vector<rt::ShaderSource> waterShaders(const CompileResult& result) override {
    std::string file;
    for (const ManifestTarget& t : result.manifest.targets)
      if (t.name == kWgslTargetName && !t.files.empty()) file = t.files.front().file;
    for (const OutputFile& f : result.files)
      if (f.name == file) return {{GL_FRAGMENT_SHADER, f.name, f.contents}};
    throw RuntimeError(RuntimeError::Kind::Manifest, "the graph was compiled without the wgsl target (CompileOptions::wgsl)");
  }

  // A tap frame: the plan's WGSL module with the tap fragment stage (codegen/readback_taps.h).
  std::vector<rt::ShaderSource> tapFrameShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders,
                                                const std::vector<TapChannel>& channels, int frame) override {
    try {
      return {{GL_FRAGMENT_SHADER, water.at(0).name + " (read-back " + std::to_string(frame) + ")",
               emitTapModuleWgsl(shaders, channels)}};
    } catch (const WgslRefused& r) {
      throw RuntimeError(RuntimeError::Kind::Manifest, "the read-back frame has no WGSL form: " + r.message);
    }
  }

  std::unique_ptr<WaterFrames> waterFrames(const CompileResult& result, const std::vector<rt::ShaderSource>& water, bool,
                                           const rt::RenderSettings& settings) override {
    if (water.size() != 1) throw RuntimeError(RuntimeError::Kind::Manifest, "the wgsl water is one module");
    return makeWgslWaterFrames(session_, result, water.front(), settings);
  }

 private:
  WebgpuSession session_;
};

}  // namespace

std::unique_ptr<GpuExecutor> makeWgslExecutor(const WebgpuTools& tools) { return std::make_unique<WgslExecutor>(tools); }

}  // namespace wg::accuracy
