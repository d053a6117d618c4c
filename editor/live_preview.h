#pragma once
// A compiled graph running in the Renderer, replaced only by one that compiled and linked:
// a graph with errors leaves the last good preview on screen and hands back the errors.
// The GL context (the editor's window) must be current.
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "core/diagnostic.h"
#include "core/graph.h"
#include "runtime/gpu_cache.h"
#include "runtime/renderer.h"

namespace wg::editor {

struct RebuildTimings {
  double compileMs = 0;   // resolve, passes, GLSL, glslang
  double rendererMs = 0;  // GL: linking the programs, creating targets
};

class LivePreview {
 public:
  explicit LivePreview(rt::RenderSettings settings) : settings_(std::move(settings)) {}

  // Compiles `graph` for glsl330 and builds a Renderer for it. On success the new
  // Renderer replaces the old one and true is returned; on any error `diags` says why and
  // the old Renderer (if any) stays.
  bool rebuild(const Graph& graph, const Registry& registry, Diagnostics& diags, RebuildTimings* timings = nullptr);
  // A new value for a parameter uniform; false when only a recompile can show it.
  bool setParameter(const std::string& name, const std::vector<double>& value);

  bool ready() const { return renderer_ != nullptr; }
  // Renders one frame with this camera and scene; returns its milliseconds. A GL error
  // while rendering leaves the preview empty and is returned in *error.
  // `view` is the output transform the frame is shown through.
  double render(const rt::Camera& camera, const rt::SceneOptions& scene, const ViewTransform& view,
                std::string* error = nullptr);
  // A replaced Renderer lives until the end of the frame: the UI's draw data, built
  // before the rebuild, still names its texture.
  void endFrame() { retired_.reset(); }
  unsigned texture() const;  // the GL texture of the last frame (rows bottom-up)
  rt::Image read() const;
  const rt::RenderSettings& settings() const { return settings_; }
  const CompileResult* compiled() const { return compiled_ ? &*compiled_ : nullptr; }
  // The built-in scene's buoys floating at time t on this graph's water, with the parameter
  // values the preview shows (the compile's, and those set since; runtime/floating_buoys.h).
  std::vector<rt::FloatingPose> floatingBuoys(double time) const;

 private:
  rt::RenderSettings settings_;
  // Programs and node textures kept across rebuilds: an edit that changes no shader text
  // (a parameter default, a colour) reuses the linked and JIT-compiled programs.
  rt::GpuCache cache_;
  std::unique_ptr<rt::Renderer> renderer_, retired_;
  std::optional<CompileResult> compiled_;
  std::map<std::string, std::vector<double>> setSinceRebuild_;  // setParameter's values
};

}  // namespace wg::editor
