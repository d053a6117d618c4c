#include "accuracy/check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include <glm/glm.hpp>

#include "accuracy/error_bound.h"
#include "accuracy/fragment_program.h"
#include "accuracy/gpu_executor.h"
#include "accuracy/readback.h"
#include "accuracy/target_agreement.h"
#include "codegen/cpu_backend.h"
#include "runtime/memory_budget.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

rt::Camera orbit(float elevationDegrees, float distance) {
  float e = glm::radians(elevationDegrees);
  rt::Camera c;
  // Around the deep end of the pool, looking towards the shore (-x), like the "above" preset.
  glm::vec3 target(-2.0f, 0.0f, 2.0f);
  glm::vec3 dir = glm::normalize(glm::vec3(0.8f, 0.0f, -0.6f));
  c.position = target + distance * (std::cos(e) * dir + glm::vec3(0, std::sin(e), 0));
  c.target = target;
  if (elevationDegrees > 89.0f) c.position += glm::vec3(0.0f, 0.0f, 0.01f);  // keep lookAt's up vector valid
  return c;
}

}  // namespace

std::vector<CheckView> checkSweep(bool underwater) {
  std::vector<CheckView> views;
  rt::SceneOptions base;
  for (float e : {0.5f, 2.0f, 10.0f, 30.0f, 60.0f, 89.5f}) {
    char label[48];
    std::snprintf(label, sizeof label, "elevation %g deg", e);
    views.push_back({label, orbit(e, 16.0f), base});
  }
  for (float t : {13107.0f, 524288.0f, 1e6f}) {
    rt::SceneOptions s = base;
    s.time = t;
    char label[48];
    std::snprintf(label, sizeof label, "time %g s", t);
    views.push_back({label, orbit(20.0f, 16.0f), s});
  }
  for (auto [az, el] : {std::pair{200.0f, 2.0f}, std::pair{20.0f, 85.0f}, std::pair{300.0f, -5.0f}}) {
    rt::SceneOptions s = base;
    s.sunAzimuthDegrees = az;
    s.sunElevationDegrees = el;
    char label[64];
    std::snprintf(label, sizeof label, "sun az %g el %g", az, el);
    views.push_back({label, orbit(20.0f, 16.0f), s});
  }
  if (underwater) {
    rt::Camera below = *rt::cameraPreset("underwater");
    views.push_back({"under water", below, base});
    rt::Camera up = below;
    up.target = below.position + glm::vec3(0.3f, 1.0f, 0.2f);  // looking up at the surface: TIR and Snell's window
    views.push_back({"under water, looking up", up, base});
    rt::SceneOptions late = base;
    late.time = 1e6f;
    views.push_back({"under water, time 1e6 s", below, late});
  }
  return views;
}

long CheckReport::nanInf() const {
  long n = 0;
  for (const auto& v : views) n += v.nan + v.inf;
  return n;
}

int CheckReport::samples() const {
  int n = 0;
  for (const auto& v : views) n += v.referenceSamples;
  return n;
}

double CheckReport::maxError() const {
  double m = 0;
  for (const auto& v : views) m = std::max(m, v.maxError);
  return m;
}

double CheckReport::meanError() const {
  double sum = 0;
  for (const auto& v : views) sum += v.meanError * v.referenceSamples;
  return samples() ? sum / samples() : 0.0;
}

int CheckReport::overBound() const {
  int n = 0;
  for (const auto& v : views) n += v.overBound;
  return n;
}

double CheckReport::worstRatio() const {
  double m = 0;
  for (const auto& v : views) m = std::max(m, v.worstRatio);
  return m;
}

std::string referenceUnavailable(const CompileResult& result) {
  const Program& p = result.program;
  if (!p.output(OutputSlot::FragmentColor)) return "no fragment colour";
  if (const ProgramOutput* a = p.output(OutputSlot::FragmentAlpha))
    if (!(a->value.kind == ValueRef::Kind::Const && a->value.constant()[0] == 1.0)) return "the colour is blended by alpha";
  // A GLSL function node without a `reference` formula: its GLSL is all there is, so the
  // targets are held to each other (accuracy/target_agreement.h).
  if (std::string node = nodeWithoutReference(p); !node.empty())
    return node + " has no double reference; checked for NaN and Inf, and the targets against each other";
  return "";
}

namespace {

// The builtins a drawn fragment shader computes with in float32 (interpolated varyings
// and uniforms), as the probe perturbs them; time phases carry no rounding (double).
const std::vector<BuiltinUniform>& perPixelBuiltins() {
  static const std::vector<BuiltinUniform> b = {
      BuiltinUniform::CameraPosition, BuiltinUniform::CameraNearFar,   BuiltinUniform::ProbeUv,
      BuiltinUniform::ProbeWorldPosition, BuiltinUniform::ProbeNormal, BuiltinUniform::ProbeViewDirection,
      BuiltinUniform::ProbeScreenUv,  BuiltinUniform::ProbeFragDepth,  BuiltinUniform::SunDirection};
  return b;
}

Value matrixValue(const glm::mat4& m) {
  Value v = Value::ofType(Type::Mat4);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) v[c * 4 + r] = m[c][r];  // column-major, as GLSL
  return v;
}

Value channelValue(const ReadbackImage& taps, int px, int py, int channel, int size) {
  static const Type kTypes[] = {Type::Float, Type::Vec2, Type::Vec3, Type::Vec4};
  Value v = Value::ofType(kTypes[size - 1]);
  for (int k = 0; k < size; ++k) v[k] = taps.at(px, py, channel + k);
  return v;
}

// The reference's inputs at pixel (px, py) (rows top to bottom) from the read-back: the
// pixel's interpolated varyings and depth, its scene look-ups, the uv gradient of its 2x2
// quad, the view's uniforms, the whole scene textures read back (`images`, one per
// plan.images entry). False where the pixel is not comparable: not water, near a
// silhouette (the pixel, its four neighbours and its quad must all show the water), or
// two look-ups of one scene texture that returned different values (the reference has
// one value per texture and pixel where it has no image).
bool pixelInputs(const ReadbackImage& taps, const ReadbackPlan& plan, const std::vector<SceneImage>& images, int px,
                 int py, const CheckView& view, float aspect, EvalEnvironment* envOut) {
  const int height = taps.height;
  auto water = [&](int x, int y) { return taps.water(x, y, plan); };
  if (!water(px, py) || !water(px - 1, py) || !water(px + 1, py) || !water(px, py - 1) || !water(px, py + 1)) return false;
  // llvmpipe derives a quad's derivatives from its lower-left pixel (window rows run
  // bottom-up) and the neighbours across and above.
  const int gx0 = px & ~1, row0 = height - 1 - ((height - 1 - py) & ~1), row1 = row0 - 1;
  if (!water(gx0, row0) || !water(gx0 + 1, row0) || !water(gx0, row1)) return false;
  EvalEnvironment env;
  for (const auto& lookup : plan.lookups) {
    Value v = channelValue(taps, px, py, lookup.channel, lookup.size);
    Value* field = &(env.*sceneSamplerRow(lookup.sampler).environment);
    bool first = true;
    for (const auto& earlier : plan.lookups) {
      if (&earlier == &lookup) break;
      first &= earlier.sampler != lookup.sampler;
    }
    if (first) *field = v;
    else if (!(*field == v)) return false;
  }
  const rt::Camera& cam = view.camera;
  const glm::dvec3 eye(cam.position);
  env.cameraPosition = Value::vector({eye.x, eye.y, eye.z});
  if (plan.worldPosition >= 0) {
    env.worldPosition = channelValue(taps, px, py, plan.worldPosition, 3);
    glm::dvec3 p(env.worldPosition[0], env.worldPosition[1], env.worldPosition[2]);
    glm::dvec3 vd = eye - p;
    if (glm::length(vd) > 0) vd = glm::normalize(vd);
    env.viewDirection = Value::vector({vd.x, vd.y, vd.z});
  }
  if (plan.normal >= 0) {
    glm::dvec3 n(taps.at(px, py, plan.normal), taps.at(px, py, plan.normal + 1), taps.at(px, py, plan.normal + 2));
    if (glm::length(n) > 0) n = glm::normalize(n);  // as the shader's safe normalisation
    env.normal = Value::vector({n.x, n.y, n.z});
  }
  if (plan.uv >= 0) {
    env.uv = channelValue(taps, px, py, plan.uv, 2);
    Value u00 = channelValue(taps, gx0, row0, plan.uv, 2), u10 = channelValue(taps, gx0 + 1, row0, plan.uv, 2),
          u01 = channelValue(taps, gx0, row1, plan.uv, 2);
    env.uvDx = Value::vector({u10[0] - u00[0], u10[1] - u00[1]});
    env.uvDy = Value::vector({u01[0] - u00[0], u01[1] - u00[1]});
  }
  for (size_t k = 0; k < plan.images.size(); ++k) env.sceneImages[static_cast<size_t>(plan.images[k].sampler)] = &images[k];
  if (plan.fragDepth >= 0) env.fragDepth = Value::scalar(taps.at(px, py, plan.fragDepth));
  env.screenUv = Value::vector({(px + 0.5) / taps.width, 1 - (py + 0.5) / height});
  env.time = Value::scalar(static_cast<double>(view.scene.time));
  env.cameraNearFar = Value::vector({cam.nearPlane, cam.farPlane});
  env.view = matrixValue(cam.view());
  env.projection = matrixValue(cam.projection(aspect));
  // As the shader forms the pixel_angle builtin from its float uniforms.
  env.pixelAngle = Value::scalar(2.0 / std::abs(static_cast<double>(static_cast<float>(env.projection[5])) * height));
  const glm::vec3 sun = rt::sunDirection(view.scene);  // as the renderer sets u_sun_direction
  env.sunDirection = Value::vector({sun.x, sun.y, sun.z});
  *envOut = env;
  return true;
}

// 0.5 -> "0.5": a pass scale as the manifest writes it.
std::string formatScale(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

}  // namespace

CheckReport checkGraph(const CompileResult& result, const std::string& graphFile, Target target, const CheckOptions& options) {
  return checkGraph(result, graphFile, *currentGlExecutor(target), options);
}

CheckReport checkGraph(const CompileResult& compiled, const std::string& graphFile, GpuExecutor& executor,
                       const CheckOptions& options) {
  // The read-back takes a deferred graph's scene images whole, a texel per frame pixel, and
  // the reference compares the shader's maths pixel by pixel: check renders every scene pass
  // at the frame's size. The `resolution` option changes no shader, only the pass sizes,
  // so the shaders checked are the graph's own; the report says so.
  std::optional<CompileResult> fullSize;
  if (!compiled.manifest.passScales.empty()) {
    fullSize = compiled;
    fullSize->manifest.passScales.clear();
  }
  const CompileResult& result = fullSize ? *fullSize : compiled;
  const Target target = executor.target();
  const int width = options.width, height = options.height, referenceStride = std::max(1, options.referenceStride);
  CheckReport report;
  report.graph = graphFile;
  report.target = target;
  report.targetLabel = executor.targetLabel();
  report.width = width;
  report.height = height;
  for (const auto& p : compiled.manifest.passScales)
    report.scaledPasses.push_back(std::string(renderPassRow(p.pass).name) + " at " + formatScale(p.scale));
  const bool underwater = result.manifest.lists(RenderPass::DeferredWater);
  std::vector<rt::ShaderSource> sources = executor.waterShaders(result);
  if (options.mutation.active()) {
    // The user's deliberate edit (check --mutate), not a search the check decides on.
    bool found = false;
    for (auto& stage : sources) found |= mutateText(stage.text, options.mutation);
    if (!found) throw std::invalid_argument("the mutation's text '" + options.mutation.find + "' is not in the water shaders");
  }
  rt::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.floatColor = true;
  settings.environmentSize = 32;  // the sky cube map: small frames need no more
  settings.waterGridQuads = 64;

  // The reference: the fragment stage in double on the inputs the GPU read back, planned
  // from the plan the water shaders were emitted from.
  ReadbackPlan plan;
  std::optional<ShaderPlan> shaders;
  report.reference = referenceUnavailable(result);
  if (report.reference.empty()) {
    shaders = waterPlan(result, target);
    report.reference = planReadback(result, *shaders, &plan);
  }
  // es300 renders the sweep for NaN and Inf only (docs/accuracy.md); glsl330, vk450
  // (lavapipe: llvmpipe's rasteriser, the same pixel quads) and wgsl (f32 everywhere; its
  // module shares es300's plan, so the executor's target is es300) are compared.
  if (report.reference.empty() && target == Target::Es300 && report.targetLabel == targetName(Target::Es300))
    report.reference = "reference on glsl330, vk450 and wgsl only";
  const bool compare = report.reference.empty();
  if (compare) report.reference = "cpu";
  // Everything the check holds at once, estimated before the first target is made
  // (docs/robustness.md): the frames' renderer and one per read-back frame, each with its
  // targets and read-back; on the CPU the read-back inputs (a float per channel), the scene
  // images the reference samples (up to four floats a texel each) and, with error maps, a
  // copy of the frame, the errors, the ratios and the map's picture.
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  const size_t renderers = 1 + (compare ? static_cast<size_t>(plan.frames()) : 0);
  size_t hostPerPixel = compare ? 4 * plan.channels.size() + 16 * plan.images.size() : 0;
  if (options.errorMaps) hostPerPixel += 16 + 4 + 4 + 4;
  // Kept frames: every view's linear RGBA, for comparing targets.
  if (options.keepFrames) hostPerPixel += 16 * checkSweep(underwater).size();
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const size_t hostBytes = rt::saturatedProduct(pixels, hostPerPixel);
  rt::checkMemoryBudget(rt::saturatedSum(rt::saturatedProduct(renderers, rt::rendererBytes(result.manifest, settings)), hostBytes),
                        "check at " + size + " (" + std::to_string(renderers) + " renderers' targets and read-back, the reference's buffers)");
  rt::MemoryReservation hostMemory(hostBytes, "check's CPU buffers at " + size);
  std::optional<ReadbackRenderer> readback;
  FragmentProgram fragment;
  ErrorModel model;
  std::vector<Value> parameters;
  if (compare) {
    readback.emplace(executor, result, sources, *shaders, plan, settings, options.mutation);
    fragment = fragmentProgram(result.program);
    model = programErrorModel(fragment.program);
    for (const auto& p : fragment.program.parameters) parameters.push_back(p.defaultValue);
  }

  std::unique_ptr<WaterFrames> frames = executor.waterFrames(result, sources, options.mutation.active(), settings);
  // The views in order of their times (a stable sort), reported in the sweep's order: a
  // spectral ocean's simulation runs once per distinct time (its foam replays tens of
  // transforms per cascade) instead of once per change of time.
  const std::vector<CheckView> sweep = checkSweep(underwater);
  std::vector<size_t> order(sweep.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sweep[a].scene.time < sweep[b].scene.time; });
  std::vector<std::optional<CheckViewResult>> results(sweep.size());
  for (size_t at : order) {
    const CheckView& view = sweep[at];
    frames->setView(view.camera, view.scene);
    rt::Image img = frames->render();
    CheckViewResult v;
    v.label = view.label;
    v.pixels = static_cast<long>(width) * height;
    for (size_t i = 0; i < img.rgba32f.size(); ++i) {
      if (i % 4 == 3) continue;  // alpha is the frame's, always 1
      float x = img.rgba32f[i];
      if (std::isnan(x)) ++v.nan;
      else if (std::isinf(x)) ++v.inf;
    }
    if (options.keepFrames) v.frame = img.rgba32f;
    if (compare) {
      if (options.errorMaps) {
        v.frame = img.rgba32f;
        v.errors.assign(static_cast<size_t>(width) * height, -1.0f);
        v.ratios.assign(static_cast<size_t>(width) * height, -1.0f);
      }
      ReadbackImage taps = readback->read(view.camera, view.scene);
      std::vector<SceneImage> images;
      for (const auto& image : plan.images) images.push_back(taps.sceneImage(image, readback->samplesNearest(image.sampler)));
      const float aspect = static_cast<float>(width) / static_cast<float>(height);
      double sum = 0;
      int stride = options.errorMaps ? 1 : referenceStride, first = options.errorMaps ? 0 : referenceStride / 2;
      for (int py = first; py < height; py += stride)
        for (int px = first; px < width; px += stride) {
          EvalEnvironment env;
          if (!pixelInputs(taps, plan, images, px, py, view, aspect, &env)) continue;
          for (size_t k = 0; k < plan.varyings.size(); ++k) {
            int param = fragment.varyingParameters[k];
            Type type = fragment.program.parameters[static_cast<size_t>(param)].type;
            parameters[static_cast<size_t>(param)] = channelValue(taps, px, py, plan.varyings[k], componentCount(type));
          }
          TextureFetches fetches;
          for (const auto& f : plan.textureFetches) fetches[f.source].push_back(channelValue(taps, px, py, f.channel, 4));
          CpuResult ref = evaluateProgram(fragment.program, env, parameters, &fetches);
          const Value& c = ref.outputs.front();
          const float* g = &img.rgba32f[(static_cast<size_t>(py) * width + px) * 4];
          double err[3], worst = 0, ratio = 0;
          bool within = true;
          for (int ch = 0; ch < 3; ++ch) {
            err[ch] = std::abs(static_cast<double>(g[ch]) - c[ch]);
            if (std::isnan(err[ch])) err[ch] = INFINITY;
            within &= err[ch] <= model.tolerance * std::max(1.0, std::abs(c[ch]));
            worst = std::max(worst, err[ch]);
            sum += err[ch];
          }
          // The error bound of the probe: the tolerance, and where that is exceeded, the
          // conditioning of the pixel's float32 inputs (measured only then: it costs a
          // few hundred evaluations).
          std::array<double, 4> conditioning{};
          if (!within) conditioning = conditioningTerm(fragment.program, env, parameters, perPixelBuiltins(), model.roundings, &fetches,
                                                      /*filterPrecision=*/true);
          bool over = false;
          for (int ch = 0; ch < 3; ++ch) {
            double bound = model.tolerance * std::max(1.0, std::abs(c[ch])) + conditioning[static_cast<size_t>(ch)];
            ratio = std::max(ratio, err[ch] / bound);
            over |= !(err[ch] <= bound);
          }
          v.maxError = std::max(v.maxError, worst);
          v.worstRatio = std::max(v.worstRatio, ratio);
          v.overBound += over ? 1 : 0;
          if (options.errorMaps) {
            v.errors[static_cast<size_t>(py) * width + px] = static_cast<float>(worst);
            v.ratios[static_cast<size_t>(py) * width + px] = static_cast<float>(ratio);
          }
          ++v.referenceSamples;
        }
      if (v.referenceSamples) v.meanError = sum / (3.0 * v.referenceSamples);
    }
    results[at] = std::move(v);
  }
  for (auto& v : results) report.views.push_back(std::move(*v));
  return report;
}

rt::Image errorMapImage(const CheckReport& report, const ViewTransform& view) {
  const CheckViewResult* pick = nullptr;
  for (const auto& v : report.views)
    if (!v.errors.empty() && v.referenceSamples > 0 && (!pick || v.worstRatio > pick->worstRatio)) pick = &v;
  rt::Image img;
  if (!pick) return img;
  img.width = report.width;
  img.height = report.height;
  img.rgba8.resize(static_cast<size_t>(img.width) * img.height * 4);
  for (size_t i = 0; i < pick->errors.size(); ++i) {
    uint8_t* px = &img.rgba8[i * 4];
    float e = pick->errors[i], r = pick->ratios[i];
    if (e < 0) {
      const float* f = &pick->frame[i * 4];
      const Rgb shown = outputTransform(view, {f[0], f[1], f[2]});
      // Darkened below 64 in red and green, blue lifted from 64: a picture of the scene no
      // grey error level can be mistaken for.
      px[0] = static_cast<uint8_t>(std::lround(60 * shown[0]));
      px[1] = static_cast<uint8_t>(std::lround(60 * shown[1]));
      px[2] = static_cast<uint8_t>(64 + std::lround(60 * shown[2]));
    } else if (!(r <= 1)) {
      px[0] = 255, px[1] = 0, px[2] = 0;
    } else {
      double t = e > 0 ? std::clamp((std::log10(static_cast<double>(e)) + 8.0) / 5.0, 0.0, 1.0) : 0.0;
      px[0] = px[1] = px[2] = static_cast<uint8_t>(std::lround(255 * t));
    }
    px[3] = 255;
  }
  return img;
}

std::string formatCheckText(const CheckReport& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "check %s on %s, %dx%d RGBA32F, reference: %s\n", r.graph.c_str(),
                (r.targetLabel.empty() ? std::string(targetName(r.target)) : r.targetLabel).c_str(), r.width, r.height, r.reference.c_str());
  std::string out = buf;
  if (!r.scaledPasses.empty()) {
    out += "  compared at full scene resolution: the graph renders";
    for (size_t i = 0; i < r.scaledPasses.size(); ++i) out += (i ? ", " : " ") + r.scaledPasses[i];
    out += " of the frame's size; check renders every scene pass at the frame's size\n";
  }
  for (const auto& v : r.views) {
    std::snprintf(buf, sizeof buf, "  %-28s nan %ld  inf %ld", v.label.c_str(), v.nan, v.inf);
    out += buf;
    if (v.referenceSamples) {
      std::snprintf(buf, sizeof buf, "  vs cpu: %d px, max %.2e, mean %.2e, error/bound %.3g", v.referenceSamples, v.maxError,
                    v.meanError, v.worstRatio);
      out += buf;
    }
    out += "\n";
  }
  if (r.samples()) {
    std::snprintf(buf, sizeof buf, "  against the cpu: %d px, max %.2e, mean %.2e, worst error/bound %.3g, over the bound %d\n",
                  r.samples(), r.maxError(), r.meanError(), r.worstRatio(), r.overBound());
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "%s: %ld NaN/Inf pixel values, %d pixels over the error bound, over %zu views\n",
                r.failed() ? "FAIL" : "ok", r.nanInf(), r.overBound(), r.views.size());
  return out + buf;
}

}  // namespace wg::accuracy
