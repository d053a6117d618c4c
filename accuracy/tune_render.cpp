#include "accuracy/tune_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <time.h>

#include "accuracy/spirv_count.h"
#include "accuracy/tune_knobs.h"
#include "codegen/compile.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/memory_budget.h"
#include "runtime/ocean_simulation.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime/median.h"

namespace wg::accuracy {

struct GlTuneMeasurements::Entry {
  CompileResult compiled;
  std::unique_ptr<rt::Renderer> renderer;
  int spirv = 0;
};

namespace {

using rt::median;

// The interval between the timed frames of a configuration: an animation at 60 frames a second.
constexpr double kTimedFrameInterval = 1.0 / 60.0;

std::string diagText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.all()) s += "\n  " + formatText(x);
  return s;
}

// CPU time of the whole process, llvmpipe's rasterizer threads included: what a frame
// costs, unlike wall time, does not grow when other programs share the cores.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

std::string key(const std::optional<TuneConfig>& config) {
  if (!config) return "as written";
  std::string s;
  for (int l : *config) s += std::to_string(l) + ",";
  return s;
}

}  // namespace

GlTuneMeasurements::GlTuneMeasurements(const Graph& graph, std::vector<TuneKnob> knobs, TuneSweep sweep)
    : graph_(graph), knobs_(std::move(knobs)), sweep_(std::move(sweep)) {
  context_ = rt::EglContext::create(rt::apiFor(sweep_.target));
  TuneConfig exact;
  for (const auto& k : knobs_) exact.push_back(static_cast<int>(k.levels.size()) - 1);
  std::unique_ptr<Entry> ref = make(exact);
  if (sweep_.cameras.empty()) {
    sweep_.cameras = {"above", "grazing", "topdown"};
    // The view from below only where the graph draws it (the deferred underwater pass).
    if (ref->compiled.manifest.lists(RenderPass::DeferredWater)) sweep_.cameras.push_back("underwater");
  }
  for (const auto& cam : sweep_.cameras) {
    auto camera = rt::cameraPreset(cam);
    if (!camera) throw std::runtime_error("unknown camera '" + cam + "'");
    for (double t : sweep_.times) {
      View v;
      char label[96];
      std::snprintf(label, sizeof label, "%s t=%g", cam.c_str(), t);
      v.label = label;
      v.camera = *camera;
      v.scene.time = static_cast<float>(t);
      views_.push_back(v);
      labels_.push_back(label);
    }
  }
  for (const auto& v : views_) {
    ref->renderer->setCamera(v.camera);
    ref->renderer->setScene(v.scene);
    ref->renderer->renderFrame();
    reference_.push_back(ref->renderer->readRgba32f().rgba32f);
  }
}

GlTuneMeasurements::~GlTuneMeasurements() { cache_.clear(); }  // GL objects before the context

std::string GlTuneMeasurements::renderer() const { return context_->renderer(); }

std::unique_ptr<GlTuneMeasurements::Entry> GlTuneMeasurements::make(const std::optional<TuneConfig>& config) {
  Graph g = config ? withKnobLevels(graph_, knobs_, *config) : graph_;
  Diagnostics diags;
  CompileOptions options;
  options.targets = {sweep_.target, Target::Vk450};
  // The reference and the graph as written are compiled with their presets checked (the
  // configuration nullopt is the graph as written); the knob configurations are variants.
  options.checkPresets = !config;
  auto compiled = compileGraph(g, defaultRegistry(), options, diags);
  if (!compiled)
    throw std::runtime_error((config ? configText(knobs_, *config) : std::string("the graph as written")) +
                             " does not compile:" + diagText(diags));
  auto e = std::make_unique<Entry>();
  for (const auto& f : compiled->files)
    if (f.name.size() > 15 && f.name.compare(f.name.size() - 15, 15, ".vk450.frag.spv") == 0)
      e->spirv = optimisedInstructionCount(spirvWords(f.contents));
  e->compiled = std::move(*compiled);
  rt::RenderSettings rs;
  rs.width = sweep_.width;
  rs.height = sweep_.height;
  rs.floatColor = true;
  if (!referenceMemory_) {
    // The first renderer (the reference): what any tune holds at once, estimated before a
    // target is made (docs/robustness.md): the reference's renderer, its frames (RGBA32F,
    // one per camera and time) and a configuration's renderer beside it. More
    // configurations timed side by side reserve their own share as they are made.
    const size_t cameras = sweep_.cameras.empty() ? 4 : sweep_.cameras.size();
    const size_t frames = rt::saturatedProduct(
        rt::saturatedProduct(cameras * std::max<size_t>(sweep_.times.size(), 1), static_cast<size_t>(rs.width)),
        static_cast<size_t>(rs.height) * 16);
    const std::string size = std::to_string(rs.width) + "x" + std::to_string(rs.height);
    rt::checkMemoryBudget(rt::saturatedSum(rt::saturatedProduct(2, rt::rendererBytes(e->compiled.manifest, rs)), frames),
                          "tune at " + size + " (the reference's and a configuration's renderers, the reference frames)");
    referenceMemory_.emplace(frames, "tune's reference frames at " + size);
  }
  e->renderer = std::make_unique<rt::Renderer>(e->compiled.manifest, rt::waterShaderSources(e->compiled, sweep_.target), rs,
                                               context_->isEs(), rt::textureOrigins(e->compiled));
  return e;
}

GlTuneMeasurements::Entry& GlTuneMeasurements::entry(const std::optional<TuneConfig>& config) {
  auto& slot = cache_[key(config)];
  if (!slot) {
    slot = make(config);
    slot->renderer->renderFrame();  // llvmpipe compiles the shaders at the first draw
  }
  return *slot;
}

TuneError GlTuneMeasurements::compare(Entry& e) {
  TuneError err;
  for (size_t v = 0; v < views_.size(); ++v) {
    e.renderer->setCamera(views_[v].camera);
    e.renderer->setScene(views_[v].scene);
    e.renderer->renderFrame();
    std::vector<float> frame = e.renderer->readRgba32f().rgba32f;
    const std::vector<float>& ref = reference_[v];
    double sq = 0, mx = 0;
    size_t n = 0;
    bool finite = true;
    for (size_t i = 0; i < frame.size(); ++i) {
      if (!std::isfinite(frame[i])) finite = false;
      if (i % 4 == 3) continue;  // colour error over R, G, B
      // As exposure 0 without a tone curve shows the frame: linear values clamped to [0, 1].
      // The frame is HDR (docs/color.md): a sun glint of tens of thousands that moves a pixel
      // would otherwise outweigh the whole picture, and no display shows it above white.
      double d = std::abs(std::clamp(static_cast<double>(frame[i]), 0.0, 1.0) - std::clamp(static_cast<double>(ref[i]), 0.0, 1.0));
      sq += d * d, mx = std::max(mx, d), ++n;
    }
    if (!finite) {
      err.finite = false;
      err.worstFrame = views_[v].label;
      return err;
    }
    double mse = n ? sq / static_cast<double>(n) : 0;
    double psnr = mse > 0 ? 10 * std::log10(1.0 / mse) : INFINITY;
    if (err.worstFrame.empty() || psnr < err.worstPsnr) err.worstPsnr = psnr, err.worstFrame = views_[v].label;
    err.maxAbsError = std::max(err.maxAbsError, mx);
  }
  return err;
}

TuneError GlTuneMeasurements::error(const TuneConfig& config) {
  cache_.erase(key(config));  // always a fresh compile and renderer
  return compare(entry(config));
}

TuneError GlTuneMeasurements::verify(const TuneConfig& config) { return error(config); }

TuneError GlTuneMeasurements::asWrittenError() {
  cache_.erase(key(std::nullopt));
  return compare(entry(std::nullopt));
}

std::vector<TuneCost> GlTuneMeasurements::cost(const std::vector<TuneConfig>& configs) {
  std::vector<std::optional<TuneConfig>> all(configs.begin(), configs.end());
  return costOf(all);
}

std::vector<TuneCost> GlTuneMeasurements::costOf(const std::vector<std::optional<TuneConfig>>& configs) {
  std::vector<Entry*> entries;
  for (const auto& c : configs) entries.push_back(&entry(c));
  // Each repeat renders every configuration from every camera, one configuration after
  // another: the medians share the machine's state. A frame's cost is the process's CPU
  // time across it (the frame and its glFinish). The frames are those of an animation from
  // the first time on, kTimedFrameInterval apart, the same times for every configuration: a
  // spectral ocean's simulation runs at every new time (its update, and its foam's steps
  // as they fall due), as an animation pays it; frames at one held time would find the
  // maps at their time and time the drawing alone (runtime/ocean_simulation.h).
  std::vector<std::vector<double>> ms(entries.size());
  rt::SceneOptions scene;
  const double start = sweep_.times.front();
  for (auto* e : entries) {
    // Untimed: the still frames compared before leave the foam at another time, which an
    // animation's first frame replays (a replay is tens of transforms).
    e->renderer->setAnimation(true);
    scene.time = static_cast<float>(start);
    e->renderer->setScene(scene);
    e->renderer->renderFrame();
  }
  // The order rotates from repeat to repeat: whichever configuration comes first after
  // another's frames does not always pay for the switch.
  for (int run = 0; run < std::max(sweep_.runs, 1); ++run)
    for (size_t j = 0; j < entries.size(); ++j) {
      size_t i = (j + static_cast<size_t>(run)) % entries.size();
      double sum = 0;
      for (size_t c = 0; c < sweep_.cameras.size(); ++c) {
        const double frame = 1.0 + static_cast<double>(static_cast<size_t>(run) * sweep_.cameras.size() + c);
        scene.time = static_cast<float>(start + frame * kTimedFrameInterval);
        entries[i]->renderer->setCamera(*rt::cameraPreset(sweep_.cameras[c]));
        entries[i]->renderer->setScene(scene);
        const auto oceans = entries[i]->renderer->oceanSimulation();
        const long updates = oceans ? oceans->updatesRun() : 0;
        double before = processCpuMs();
        entries[i]->renderer->renderFrame();
        sum += processCpuMs() - before;
        if (oceans) timedSimulationUpdates_ += oceans->updatesRun() - updates;
      }
      ms[i].push_back(sum);
    }
  for (auto* e : entries) e->renderer->setAnimation(false);  // still frames again, should it be compared
  double megapixels = sweep_.width * static_cast<double>(sweep_.height) * static_cast<double>(sweep_.cameras.size()) / 1e6;
  std::vector<TuneCost> costs;
  for (size_t i = 0; i < entries.size(); ++i) {
    std::vector<double> repeats;
    for (double m : ms[i]) repeats.push_back(m / megapixels);
    costs.push_back({median(ms[i]) / megapixels, entries[i]->spirv, std::move(repeats)});
  }
  // Keep only what this round timed: the next round's candidates are new configurations.
  std::vector<std::string> keep;
  for (const auto& c : configs) keep.push_back(key(c));
  for (auto it = cache_.begin(); it != cache_.end();)
    it = std::find(keep.begin(), keep.end(), it->first) == keep.end() ? cache_.erase(it) : std::next(it);
  return costs;
}

}  // namespace wg::accuracy
