#include "runtime/preview.h"

#include <algorithm>
#include <filesystem>

#include "runtime/runtime_error.h"
#include "runtime/median.h"

namespace wg::rt {

GlApi apiFor(Target target) {
  switch (target) {
    case Target::Glsl330: return GlApi::DesktopGl45;
    case Target::Es300: return GlApi::Es32;
    case Target::Vk450: break;
  }
  throw RuntimeError(RuntimeError::Kind::Manifest, "target vk450 is not run by the GL runtime (use glsl330 or es300)");
}

GLenum glShaderStage(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Vertex: return GL_VERTEX_SHADER;
    case ShaderStage::TessControl: return GL_TESS_CONTROL_SHADER;
    case ShaderStage::TessEvaluation: return GL_TESS_EVALUATION_SHADER;
    case ShaderStage::Fragment: return GL_FRAGMENT_SHADER;
  }
  return GL_FRAGMENT_SHADER;
}

std::vector<ShaderSource> waterShaderSources(const CompileResult& result, Target target) {
  std::string t(targetName(target));
  const ManifestTarget* files = result.manifest.target(t);
  if (!files) throw RuntimeError(RuntimeError::Kind::Manifest, "the graph was not compiled for " + t);
  std::vector<ShaderSource> out;
  for (const ManifestStageFile& f : files->files) {
    auto it = std::find_if(result.files.begin(), result.files.end(), [&](const OutputFile& o) { return o.name == f.file; });
    if (it == result.files.end())
      throw RuntimeError(RuntimeError::Kind::Manifest, "the manifest names " + f.file + " but the compile produced no such file");
    out.push_back({glShaderStage(f.stage), f.file, it->contents});
  }
  bool vert = false, frag = false;
  for (const auto& s : out) vert |= s.stage == GL_VERTEX_SHADER, frag |= s.stage == GL_FRAGMENT_SHADER;
  if (!vert || !frag)
    throw RuntimeError(RuntimeError::Kind::Manifest, "the " + t + " target lacks a vertex or fragment shader");
  return out;
}

std::map<std::string, TextureOrigin> textureOrigins(const CompileResult& result) {
  std::map<std::string, TextureOrigin> out;
  for (const auto& t : result.manifest.textures) {
    if (t.source.empty()) continue;  // a scene texture: a render target, not a file
    const std::string& source = t.source;
    for (const auto& op : result.program.ops) {
      if (!op.options().is_object()) continue;
      bool uses = false;
      for (const auto& [key, value] : op.options().items()) uses |= value.is_string() && value.get<std::string>() == source;
      if (!uses) continue;
      TextureOrigin o;
      // The manifest's source is relative to the top graph's folder, also for a texture a
      // subgraph in another folder names (the loader rewrote it), not to the op's file.
      o.graphDir = result.program.folder();
      o.owner = op.where.file.str() + ":" + std::to_string(op.where.line) + ":" + std::to_string(op.where.col) + ": node '" +
                op.nodeId + "'";
      out.emplace(source, o);
      break;
    }
  }
  return out;
}

double Preview::medianMs() const { return median(frameMs); }

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
    p.measure(renderer, settings, frames, warmup);
  }  // GL objects go before the context
  return p;
}

}  // namespace wg::rt
