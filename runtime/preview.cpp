#include "runtime/preview.h"

#include <algorithm>
#include <filesystem>

#include "runtime/runtime_error.h"

namespace wg::rt {

GlApi apiFor(Target target) {
  switch (target) {
    case Target::Glsl330: return GlApi::DesktopGl45;
    case Target::Es300: return GlApi::Es32;
    case Target::Vk450: break;
  }
  throw RuntimeError(RuntimeError::Kind::Manifest, "target vk450 is not run by the GL runtime (use glsl330 or es300)");
}

std::vector<ShaderSource> waterShaderSources(const CompileResult& result, Target target) {
  std::string t(targetName(target));
  const auto& targets = result.manifest.value("targets", nlohmann::json::object());
  if (!targets.contains(t)) throw RuntimeError(RuntimeError::Kind::Manifest, "the graph was not compiled for " + t);
  const auto& files = targets.at(t);
  struct StageKey {
    const char* key;
    GLenum stage;
  };
  std::vector<ShaderSource> out;
  for (StageKey k : {StageKey{"vert", GL_VERTEX_SHADER}, StageKey{"tesc", GL_TESS_CONTROL_SHADER},
                     StageKey{"tese", GL_TESS_EVALUATION_SHADER}, StageKey{"frag", GL_FRAGMENT_SHADER}}) {
    if (!files.contains(k.key)) continue;
    std::string name = files.at(k.key).get<std::string>();
    auto it = std::find_if(result.files.begin(), result.files.end(), [&](const OutputFile& f) { return f.name == name; });
    if (it == result.files.end())
      throw RuntimeError(RuntimeError::Kind::Manifest, "the manifest names " + name + " but the compile produced no such file");
    out.push_back({k.stage, name, it->contents});
  }
  bool vert = false, frag = false;
  for (const auto& s : out) vert |= s.stage == GL_VERTEX_SHADER, frag |= s.stage == GL_FRAGMENT_SHADER;
  if (!vert || !frag)
    throw RuntimeError(RuntimeError::Kind::Manifest, "the " + t + " target lacks a vertex or fragment shader");
  return out;
}

std::map<std::string, TextureOrigin> textureOrigins(const CompileResult& result) {
  std::map<std::string, TextureOrigin> out;
  const auto& textures = result.manifest.value("textures", nlohmann::json::array());
  for (const auto& t : textures) {
    if (!t.contains("source")) continue;
    std::string source = t.value("source", "");
    for (const auto& op : result.program.ops) {
      if (!op.options.is_object()) continue;
      bool uses = false;
      for (const auto& [key, value] : op.options.items()) uses |= value.is_string() && value.get<std::string>() == source;
      if (!uses) continue;
      TextureOrigin o;
      std::filesystem::path file(op.where.file.str());
      o.graphDir = file.has_parent_path() ? file.parent_path().string() : ".";
      o.owner = op.where.file.str() + ":" + std::to_string(op.where.line) + ":" + std::to_string(op.where.col) + ": node '" +
                op.nodeId + "'";
      out.emplace(source, o);
      break;
    }
  }
  return out;
}

double Preview::medianMs() const {
  if (frameMs.empty()) return 0;
  std::vector<double> v = frameMs;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Preview renderPreview(const CompileResult& result, Target target, const RenderSettings& settings, int frames,
                      bool warmup) {
  GlApi api = apiFor(target);
  std::vector<ShaderSource> shaders = waterShaderSources(result, target);
  auto context = EglContext::create(api);
  Preview p;
  p.renderer = context->renderer();
  p.version = context->version();
  {
    Renderer renderer(result.manifest, std::move(shaders), settings, context->isEs(), textureOrigins(result));
    if (warmup) p.warmupMs = renderer.renderFrame();
    for (int i = 0; i < std::max(frames, 1); ++i) p.frameMs.push_back(renderer.renderFrame());
    p.image = settings.floatColor ? renderer.readRgba32f() : renderer.readRgba8();
    p.plan = renderer.plan();
    p.targetCount = renderer.createdTargetCount();
    p.targetBytes = renderer.createdTargetBytes();
  }  // GL objects go before the context
  return p;
}

}  // namespace wg::rt
