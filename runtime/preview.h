#pragma once
// One call from a compiled graph to pixels: makes the EGL context for the target's API,
// builds the Renderer, renders `frames` frames and reads the last one back. Used by
// `watergraph render`, the tests and (later) the accuracy tools.
#include <map>
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "runtime/egl_context.h"
#include "runtime/renderer.h"

namespace wg::rt {

// glsl330 runs on desktop OpenGL 4.5 core, es300 on OpenGL ES 3.2. vk450 is not run here
// (RuntimeError Kind::Manifest).
GlApi apiFor(Target target);

// GL_VERTEX_SHADER, GL_TESS_CONTROL_SHADER, ... for a stage.
GLenum glShaderStage(ShaderStage stage);

// The shader files of `target` named by the manifest's "targets" entry, with their texts
// from the compile result. Throws RuntimeError(Kind::Manifest) when one is missing.
std::vector<ShaderSource> waterShaderSources(const CompileResult& result, Target target);

// For each node texture in the manifest: the folder of the graph file that names it and the
// node, for loading and for errors.
std::map<std::string, TextureOrigin> textureOrigins(const CompileResult& result);

struct Preview {
  Image image;                  // the last frame: rgba8, or rgba32f with settings.floatColor
  PassPlan plan;                // the passes that ran and the targets planned
  int targetCount = 0;          // render targets created
  size_t targetBytes = 0;       // their memory, as the driver reports the textures
  std::vector<double> frameMs;  // CPU time around each frame and its glFinish
  double warmupMs = 0;          // the untimed first frame (driver shader compiles), if any
  std::string renderer;         // GL_RENDERER
  std::string version;          // GL_VERSION

  double medianMs() const;

  // Renders `frames` frames (after an untimed one with `warmup`) with a GL or Vulkan
  // renderer and keeps the last image, the plan and the targets it created.
  template <class AnyRenderer>
  void measure(AnyRenderer& r, const RenderSettings& settings, int frames, bool warmup) {
    if (warmup) warmupMs = r.renderFrame();
    for (int i = 0; i < (frames > 1 ? frames : 1); ++i) frameMs.push_back(r.renderFrame());
    image = settings.floatColor ? r.readRgba32f() : r.readRgba8();
    plan = r.plan();
    targetCount = r.createdTargetCount();
    targetBytes = r.createdTargetBytes();
  }
};

// Throws RuntimeError (see runtime_error.h for the kinds). With `warmup`, one frame is
// rendered first and kept out of frameMs: llvmpipe compiles shaders at the first draw.
Preview renderPreview(const CompileResult& result, Target target, const RenderSettings& settings, int frames = 1,
                      bool warmup = false);

}  // namespace wg::rt
