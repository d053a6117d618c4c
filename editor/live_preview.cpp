#include "editor/live_preview.h"

#include "codegen/texture_files.h"
#include "runtime/floating_buoys.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"

namespace wg::editor {
namespace {

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

bool LivePreview::rebuild(const Graph& graph, const Registry& registry, Diagnostics& diags, RebuildTimings* timings) {
  auto start = std::chrono::steady_clock::now();
  CompileOptions options;
  options.targets = {Target::Glsl330};  // the window's context is desktop GL 4.5 core
  auto result = compileGraph(graph, registry, options, diags);
  if (timings) timings->compileMs = msSince(start);
  if (!result) return false;
  start = std::chrono::steady_clock::now();
  try {
    auto renderer = std::make_unique<rt::Renderer>(result->manifest, rt::waterShaderSources(*result, Target::Glsl330),
                                                   settings_, false, rt::textureOrigins(*result), &cache_);
    retired_ = std::move(renderer_);
    renderer_ = std::move(renderer);
  } catch (const rt::TextureLoadError& e) {
    reportUnusableTexture(result->program, &graph, e.source(), e.why(), diags);  // at its option
    return false;
  } catch (const rt::RuntimeError& e) {
    // The driver or the runtime refused what glslang accepted: still an error of this graph.
    diags.error(DiagCode::RuntimeRejected, SourceRef{graph.file, 0, 0}, e.what());
    return false;
  }
  if (timings) timings->rendererMs = msSince(start);
  compiled_ = std::move(result);
  setSinceRebuild_.clear();
  return true;
}

bool LivePreview::setParameter(const std::string& name, const std::vector<double>& value) {
  if (!renderer_) return false;
  if (!renderer_->setParameter(name, std::vector<float>(value.begin(), value.end()))) return false;
  setSinceRebuild_[name] = value;
  return true;
}

std::vector<rt::FloatingPose> LivePreview::floatingBuoys(double time) const {
  if (!compiled_) return {};
  std::vector<Value> parameters;
  for (const auto& p : compiled_->program.parameters) {
    Value v = p.defaultValue;
    if (auto set = setSinceRebuild_.find(p.name); set != setSinceRebuild_.end())
      for (int i = 0; i < v.size() && i < static_cast<int>(set->second.size()); ++i) v[i] = set->second[static_cast<size_t>(i)];
    parameters.push_back(v);
  }
  return rt::floatingBuoys(compiled_->program, parameters, time);
}

double LivePreview::render(const rt::Camera& camera, const rt::SceneOptions& scene, const ViewTransform& view,
                           std::string* error) {
  if (!renderer_) return 0;
  renderer_->setCamera(camera);
  renderer_->setScene(scene);
  renderer_->setView(view);
  try {
    return renderer_->renderFrame();
  } catch (const rt::RuntimeError& e) {
    if (error) *error = e.what();
    retired_ = std::move(renderer_);
    return 0;
  }
}

unsigned LivePreview::texture() const { return renderer_ ? renderer_->frameTexture() : 0; }

rt::Image LivePreview::read() const { return renderer_ ? renderer_->readRgba8() : rt::Image{}; }

}  // namespace wg::editor
