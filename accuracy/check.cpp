#include "accuracy/check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/glm.hpp>

#include "accuracy/error_bound.h"
#include "codegen/cpu_backend.h"
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
  if (p.output(OutputSlot::VertexPosition) || p.output(OutputSlot::VertexNormal))
    return "vertex outputs move the surface off the flat grid";
  for (const auto& op : p.ops)
    if (!op.spec->resources.empty()) return "node '" + op.nodeId + "' reads scene resources";
  if (const ProgramOutput* a = p.output(OutputSlot::FragmentAlpha))
    if (!(a->value.kind == ValueRef::Kind::Const && a->value.constant[0] == 1.0)) return "the colour is blended by alpha";
  if (!p.output(OutputSlot::FragmentColor)) return "no fragment colour";
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

}  // namespace

CheckReport checkGraph(const CompileResult& result, const std::string& graphFile, Target target, const CheckOptions& options) {
  const int width = options.width, height = options.height, referenceStride = std::max(1, options.referenceStride);
  CheckReport report;
  report.graph = graphFile;
  report.target = target;
  report.width = width;
  report.height = height;
  report.reference = referenceUnavailable(result);
  if (report.reference.empty() && target != Target::Glsl330) report.reference = "reference on glsl330 only (ES cannot read depth)";
  bool compare = report.reference.empty();
  if (compare) report.reference = "cpu";
  const bool underwater = result.manifest.lists(RenderPass::DeferredWater);
  bool es = target == Target::Es300;
  std::vector<rt::ShaderSource> sources = rt::waterShaderSources(result, target);
  if (options.mutation.active()) {
    if (options.mutation.find.find('\n') != std::string::npos || options.mutation.replace.find('\n') != std::string::npos)
      throw std::invalid_argument("a shader mutation edits within one line");
    bool found = false;
    for (auto& stage : sources)
      for (size_t at = stage.text.find(options.mutation.find); at != std::string::npos;
           at = stage.text.find(options.mutation.find, at + options.mutation.replace.size())) {
        stage.text.replace(at, options.mutation.find.size(), options.mutation.replace);
        found = true;
      }
    if (!found) throw std::invalid_argument("the mutation's text '" + options.mutation.find + "' is not in the water shaders");
  }
  const ErrorModel model = programErrorModel(result.program);
  std::vector<Value> parameters;
  for (const auto& p : result.program.parameters) parameters.push_back(p.defaultValue);
  size_t colorIndex = 0;
  for (size_t k = 0; k < result.program.outputs.size(); ++k)
    if (result.program.outputs[k].slot == OutputSlot::FragmentColor) colorIndex = k;
  // The conditioning term reads the first output: a program whose first is the colour.
  Program colorProgram = result.program;
  if (compare) std::swap(colorProgram.outputs[0], colorProgram.outputs[colorIndex]);

  for (const auto& view : checkSweep(underwater)) {
    rt::RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.customCamera = view.camera;
    settings.scene = view.scene;
    settings.floatColor = true;
    settings.environmentSize = 32;  // the sky cube map: small frames need no more
    settings.waterGridQuads = 64;
    rt::Renderer renderer(result.manifest, sources, settings, es, rt::textureOrigins(result));
    renderer.renderFrame();
    rt::Image img = renderer.readRgba32f();
    CheckViewResult v;
    v.label = view.label;
    v.pixels = static_cast<long>(width) * height;
    for (size_t i = 0; i < img.rgba32f.size(); ++i) {
      if (i % 4 == 3) continue;  // alpha is the frame's, always 1
      float x = img.rgba32f[i];
      if (std::isnan(x)) ++v.nan;
      else if (std::isinf(x)) ++v.inf;
    }
    if (compare) {
      if (options.errorMaps) {
        v.errors.assign(static_cast<size_t>(width) * height, -1.0f);
        v.ratios.assign(static_cast<size_t>(width) * height, -1.0f);
      }
      std::vector<float> depth = renderer.readDepth();
      const rt::Camera& cam = view.camera;
      double aspect = static_cast<double>(width) / height;
      glm::dmat4 viewM = glm::dmat4(cam.view()), proj = glm::dmat4(cam.projection(static_cast<float>(aspect)));
      glm::dmat4 inv = glm::inverse(proj * viewM);
      glm::dvec3 eye(cam.position);
      const glm::vec3 sun = rt::sunDirection(view.scene);  // as the renderer sets u_sun_direction
      // The flat water at pixel (px, py) (top-down rows): the world point and its depth value.
      auto water = [&](int px, int py, glm::dvec3* point, double* depthValue) {
        double ndcX = (px + 0.5) / width * 2 - 1, ndcY = 1 - (py + 0.5) / height * 2;
        glm::dvec4 far = inv * glm::dvec4(ndcX, ndcY, 1, 1);
        glm::dvec3 dir = glm::dvec3(far) / far.w - eye;
        if (std::abs(dir.y) < 1e-12) return false;
        double t = -eye.y / dir.y;
        if (t <= 0) return false;
        *point = eye + t * dir;
        if (std::abs(point->x) > rt::kWaterHalfSize - 0.5 || std::abs(point->z) > rt::kWaterHalfSize - 0.5) return false;
        glm::dvec4 clip = proj * viewM * glm::dvec4(*point, 1);
        *depthValue = 0.5 * clip.z / clip.w + 0.5;
        return true;
      };
      auto visible = [&](int px, int py) {
        if (px < 0 || py < 0 || px >= width || py >= height) return false;
        glm::dvec3 p;
        double d = 0;
        if (!water(px, py, &p, &d)) return false;
        return std::abs(depth[static_cast<size_t>(py) * width + px] - d) < 1e-5;
      };
      double sum = 0;
      int stride = options.errorMaps ? 1 : referenceStride, first = options.errorMaps ? 0 : referenceStride / 2;
      for (int py = first; py < height; py += stride)
        for (int px = first; px < width; px += stride) {
          // Away from silhouettes: the pixel and its four neighbours show the water.
          if (!visible(px, py) || !visible(px - 1, py) || !visible(px + 1, py) || !visible(px, py - 1) || !visible(px, py + 1))
            continue;
          glm::dvec3 p;
          double d = 0;
          water(px, py, &p, &d);
          EvalEnvironment env;
          env.worldPosition = Value::vector({p.x, p.y, p.z});
          env.normal = Value::vector({0, 1, 0});
          glm::dvec3 vd = glm::normalize(eye - p);
          env.viewDirection = Value::vector({vd.x, vd.y, vd.z});
          env.cameraPosition = Value::vector({eye.x, eye.y, eye.z});
          env.uv = Value::vector({(p.x + rt::kWaterHalfSize) / (2 * rt::kWaterHalfSize),
                                  (p.z + rt::kWaterHalfSize) / (2 * rt::kWaterHalfSize)});
          // The uv gradient a mipmapped look-up takes its level from: llvmpipe derives one
          // per 2x2 quad (window rows run bottom-up), from the quad's lower-left pixel
          // and its neighbours across and above.
          {
            int gx0 = px & ~1, gy0 = (height - 1 - py) & ~1;
            glm::dvec3 p00, p10, p01;
            double ignored = 0;
            if (water(gx0, height - 1 - gy0, &p00, &ignored) && water(gx0 + 1, height - 1 - gy0, &p10, &ignored) &&
                water(gx0, height - 2 - gy0, &p01, &ignored)) {
              const double span = 2 * rt::kWaterHalfSize;  // uv = (x, z) / span + 0.5
              env.uvDx = Value::vector({(p10.x - p00.x) / span, (p10.z - p00.z) / span});
              env.uvDy = Value::vector({(p01.x - p00.x) / span, (p01.z - p00.z) / span});
            }
          }
          env.time = Value::scalar(static_cast<double>(view.scene.time));
          env.screenUv = Value::vector({(px + 0.5) / width, 1 - (py + 0.5) / height});
          env.fragDepth = Value::scalar(d);
          env.cameraNearFar = Value::vector({cam.nearPlane, cam.farPlane});
          env.sunDirection = Value::vector({sun.x, sun.y, sun.z});
          CpuResult ref = evaluateProgram(result.program, env, parameters);
          const Value& c = ref.outputs[colorIndex];
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
          if (!within) conditioning = conditioningTerm(colorProgram, env, parameters, perPixelBuiltins(), model.roundings);
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
    report.views.push_back(std::move(v));
  }
  return report;
}

rt::Image errorMapImage(const CheckReport& report) {
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
      px[0] = 0, px[1] = 0, px[2] = 64;
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
                std::string(targetName(r.target)).c_str(), r.width, r.height, r.reference.c_str());
  std::string out = buf;
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
