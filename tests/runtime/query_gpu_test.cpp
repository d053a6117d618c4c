// The surface query (compile --target query-c) against the GPU's vertex stage: the
// generated vertex shader of glsl330, es300 and vk450 runs on llvmpipe / lavapipe with the
// runtime's uniform values (model identity, the time phases computed in double), and each
// vertex's displaced position is read back: for glsl330 and es300 by transform feedback of
// gl_Position (view-projection identity), for vk450 from the compiled SPIR-V as it is, one
// point per pixel (query_vk_capture.h). It differs from the
// query's double answer by no more than the shader's float32 rounding allows: per wave, the
// phase k mod(D.x, L) + phase carries about 2^-24 (4 pi + 3 k (|x0| + |z0|)) of rounding,
// which moves the point by A (1 + Q) times that; the sums and the input point add
// 2^-24 (|x0| + |z0| + sum A) each. The bound is that sum. Cases: every example
// graph that displaces its water (tessellation off: the vertex stage displaces), a steep
// sea (sum Q k A = 0.97) at its crests, t = 1e6 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>

#include <epoxy/gl.h>

#include "codegen/query_header.h"
#include "nodes/gerstner_waves.h"
#include "query_samples.h"
#include "query_vk_capture.h"
#include "core/ocean_fft_reference.h"
#include "core/ocean_settings.h"
#include "ocean_transform_bound.h"
#include "query_ocean_samples.h"
#include "runtime/egl_context.h"
#include "runtime/ocean_simulation.h"
#include "runtime/preview.h"
#include "runtime/uniform_values.h"

namespace wg::rt {
namespace {

using test::QueryPoint;

// Parameter values a host sets, by parameter name (before clamping).
using HostValues = std::map<std::string, std::vector<double>>;

struct Captured {
  std::vector<float> positions;  // 3 per point
  std::string error;
};

GLuint compiled(GLenum stage, const std::string& source, std::string& error) {
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    error = log;
  }
  return shader;
}

// The displaced positions the vertex shader `vertexText` computes for the points, under the
// manifest's uniforms at time t (each parameter `host`'s value or its default, clamped as
// the runtime clamps it), seen from `camera`, with the ocean maps `sea` simulated (null for
// a graph without a spectral ocean): gl_Position, with the view-projection the identity.
Captured captureVertexStage(const std::string& vertexText, bool es, const Manifest& manifest,
                            const std::vector<QueryPoint>& points, double t, const HostValues& host,
                            const OceanSimulation* sea = nullptr, glm::vec3 camera = glm::vec3(0.0f)) {
  Captured c;
  GLuint shader = compiled(GL_VERTEX_SHADER, vertexText, c.error);
  // ES programs need a fragment shader even when nothing is rasterised.
  GLuint fragment = compiled(GL_FRAGMENT_SHADER,
                             es ? "#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() { c = vec4(0.0); }\n"
                                : "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.0); }\n",
                             c.error);
  if (!c.error.empty()) return c;
  GLint ok = 0;
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glAttachShader(program, fragment);
  const char* varyings[] = {"gl_Position"};
  glTransformFeedbackVaryings(program, 1, varyings, GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    c.error = log;
    return c;
  }
  glUseProgram(program);
  FrameValues frame;
  frame.time = t;
  frame.camera.position = camera;
  for (const ManifestUniform& u : manifest.uniforms) {
    GLint at = glGetUniformLocation(program, u.name.c_str());
    if (at < 0) continue;
    std::vector<float> v;
    if (u.parameter) {
      auto set = host.find(u.parameter->name);
      for (double d : set != host.end() ? set->second : u.parameter->defaultValue) v.push_back(static_cast<float>(d));
      clampIntoRange(v, u.parameter->min ? static_cast<float>(*u.parameter->min) : -INFINITY,
                     u.parameter->max ? static_cast<float>(*u.parameter->max) : INFINITY);
    } else {
      v = builtinUniformValue(u.builtin, u.angularFrequency, frame);
    }
    switch (u.type) {
      case Type::Float: glUniform1fv(at, 1, v.data()); break;
      case Type::Vec2: glUniform2fv(at, 1, v.data()); break;
      case Type::Vec3: glUniform3fv(at, 1, v.data()); break;
      case Type::Vec4: glUniform4fv(at, 1, v.data()); break;
      case Type::Mat4: glUniformMatrix4fv(at, 1, GL_FALSE, v.data()); break;
      default: c.error = "uniform " + u.name + " of a type this test does not set"; return c;
    }
  }
  GLint unit = 0;
  for (const TextureInfo& texture : manifest.textures) {
    GLint at = glGetUniformLocation(program, texture.name.c_str());
    if (at < 0) continue;
    if (!texture.ocean || !sea) {
      c.error = "sampler " + texture.name + " this test does not bind";
      return c;
    }
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, sea->map(*texture.ocean));
    glUniform1i(at, unit++);
  }
  std::vector<float> in;
  for (const QueryPoint& q : points) in.insert(in.end(), {static_cast<float>(q.x0), 0.0f, static_cast<float>(q.z0)});
  GLuint vao = 0, buffers[2] = {0, 0};
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(in.size() * sizeof(float)), in.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[1]);
  const size_t captured = 4 * points.size();  // vec4 gl_Position per point
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, static_cast<GLsizeiptr>(captured * sizeof(float)), nullptr, GL_STATIC_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers[1]);
  // The context is surfaceless: a draw needs a complete framebuffer even when nothing is
  // rasterised.
  GLuint fbo = 0, rb = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(points.size()));
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  if (GLenum e = glGetError(); e != GL_NO_ERROR) {
    c.error = "GL error " + std::to_string(e) + " drawing the points";
    return c;
  }
  const void* mapped = glMapBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, static_cast<GLsizeiptr>(captured * sizeof(float)),
                                        GL_MAP_READ_BIT);
  if (mapped) {
    const float* f = static_cast<const float*>(mapped);
    for (size_t k = 0; k < points.size(); ++k) c.positions.insert(c.positions.end(), {f[4 * k], f[4 * k + 1], f[4 * k + 2]});
    glUnmapBuffer(GL_TRANSFORM_FEEDBACK_BUFFER);
  } else {
    c.error = "the transform feedback buffer could not be mapped";
  }
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(1, &rb);
  glDeleteBuffers(2, buffers);
  glDeleteVertexArrays(1, &vao);
  glDeleteProgram(program);
  glDeleteShader(shader);
  glDeleteShader(fragment);
  return c;
}

// The displaced positions `target`'s vertex shader in `result` computes for the points.
Captured capturedOn(Target target, const CompileResult& result, const std::vector<QueryPoint>& points, double t,
                    const HostValues& host) {
  const std::string suffix = "." + std::string(targetName(target)) + ".vert" + (target == Target::Vk450 ? ".spv" : "");
  std::string vertex;
  for (const auto& f : result.files)
    if (f.name.ends_with(suffix)) vertex = f.contents;
  if (vertex.empty()) return {{}, "no " + suffix + " file"};
  if (target != Target::Vk450) {
    auto context = EglContext::create(apiFor(target));
    return captureVertexStage(vertex, target == Target::Es300, result.manifest, points, t, host);
  }
  std::vector<uint32_t> spirv(vertex.size() / 4);
  std::memcpy(spirv.data(), vertex.data(), 4 * spirv.size());
  std::vector<std::pair<double, double>> xz;
  for (const QueryPoint& q : points) xz.emplace_back(q.x0, q.z0);
  VkCapturedPoints vk = captureVulkanVertexStage(spirv, result.manifest, xz, t, host);
  return {vk.positions, vk.error};
}

// The float32 bound of the header comment for a point.
double float32Bound(const std::vector<nodes::GerstnerWave>& waves, const QueryPoint& q) {
  const double eps = std::ldexp(1.0, -24), r = std::abs(q.x0) + std::abs(q.z0);
  double sumA = 0, bound = 0;
  for (const auto& w : waves) {
    bound += w.amplitude * (1 + w.steepness) * eps * (4 * M_PI + 3 * w.k * r);
    sumA += w.amplitude;
  }
  return bound + 2 * eps * (r + sumA);
}

std::vector<QueryPoint> gpuPoints(double t) {
  std::vector<QueryPoint> v;
  for (double x0 : {-37.5, -6.25, 0.0, 2.125, 9.75, 48.5})
    for (double z0 : {-21.0, -0.5, 3.25, 30.0}) v.push_back({x0, z0, t});
  const double n = std::sqrt(1.04), dx = 1.0 / n, dz = 0.2 / n;  // the steep sea's first crests (query_header_test)
  for (double s : {2.95, 3.0, 3.05, 15.0}) v.push_back({std::round(s * dx * 4096) / 4096, std::round(s * dz * 4096) / 4096, t});
  return v;
}

// What a case adds to the Gerstner waves: parameter values a host sets (the GPU gets them
// clamped by the runtime's rule, the query as `setParameters`, C statements on `p`, and
// clamps them itself), and the float32 bound of displacements other than the waves.
struct HostSettings {
  HostValues values;
  std::string setParameters;
  std::function<double(const QueryPoint&)> extraBound;
};

// The GL targets, or vk450 alone (its own test names: the sanitizer run leaves the Vulkan
// driver's tests out, tests/sanitizer_excluded.txt).
std::vector<Target> capturedTargets(bool vulkan) {
  return vulkan ? std::vector<Target>{Target::Vk450} : std::vector<Target>{Target::Glsl330, Target::Es300};
}

void expectGpuAgrees(const std::string& graphPath, const std::string& what, bool vulkan, const HostSettings& host = {}) {
  Diagnostics diags;
  auto graph = loadGraphFile(graphPath, diags);
  ASSERT_TRUE(graph);
  CompileOptions o;
  o.targets = {Target::Glsl330, Target::Es300, Target::Vk450};
  o.tessellation = false;  // the vertex stage displaces
  auto result = compileGraph(*graph, defaultRegistry(), o, diags);
  ASSERT_TRUE(result);
  std::vector<nodes::GerstnerWave> waves;
  for (const Op& op : result->program.ops)
    if (op.spec->type == "gerstner_waves") {
      const auto& w = op.parsedOptions->as<std::vector<nodes::GerstnerWave>>();
      waves.insert(waves.end(), w.begin(), w.end());
    }
  ASSERT_FALSE(waves.empty()) << what;
  // The query's answers, from the generated header compiled and run.
  std::string dir = test::makeTempDir("wg_query_gpu");
  auto header = queryCHeader("g", result->program, diags);
  ASSERT_TRUE(header);
  test::writeFile(dir + "/g.query.h", *header);
  for (double t : {0.0, 3.5, 1e6}) {
    std::vector<QueryPoint> points = gpuPoints(t);
    test::writeFile(dir + "/main.c", test::queryDriverC("g.query.h", "wg_g_", points, host.setParameters));
    auto query = test::compileAndRunC(dir, "cc -std=c99");
    ASSERT_EQ(query.size(), points.size());
    for (Target target : capturedTargets(vulkan)) {
      Captured gpu = capturedOn(target, *result, points, t, host.values);
      ASSERT_TRUE(gpu.error.empty()) << gpu.error;
      ASSERT_EQ(gpu.positions.size(), 3 * points.size());
      double worst = 0;
      for (size_t k = 0; k < points.size(); ++k) {
        double bound = float32Bound(waves, points[k]) + (host.extraBound ? host.extraBound(points[k]) : 0.0);
        for (int i = 0; i < 3; ++i) {
          double d = std::abs(gpu.positions[3 * k + static_cast<size_t>(i)] - query[k][static_cast<size_t>(i)]);
          worst = std::max(worst, d / bound);
          EXPECT_LE(d, bound) << what << " " << targetName(target) << " t " << t << " point (" << points[k].x0 << ", "
                              << points[k].z0 << ") component " << i;
        }
      }
      std::printf("%s %s t=%g: worst GPU-query difference %.2f of the float32 bound\n", what.c_str(),
                  std::string(targetName(target)).c_str(), t, worst);
    }
  }
  std::filesystem::remove_all(dir);
}

class QueryGpu : public ::testing::TestWithParam<bool> {};  // vk450 (true) or the GL targets

TEST_P(QueryGpu, ExampleGraphsThatDisplaceTheirWater) {
  for (const char* name : {"ocean", "stylized", "tutorial_pbr"})
    expectGpuAgrees(test::sourcePath("graphs/" + std::string(name) + ".json"), name, GetParam());
}

TEST_P(QueryGpu, SteepSeaAtItsCrests) {
  std::string dir = test::makeTempDir("wg_query_gpu_steep");
  expectGpuAgrees(test::writeSteepGraph(dir, /*shadeByPosition=*/true), "steep", GetParam());
  std::filesystem::remove_all(dir);
}

// Parameters a host changes at run time reach the GPU and the query alike, clamped alike:
// `lift` set above its range (the shader gets its maximum), `int` (a C keyword) set to NaN
// (its minimum), `errno` (a macro, no range) set to a value the graph never had. The
// expression adds h sin(k x0) to y and 0.01 g to z; in float32 the product k x0 carries
// k |x0| 2^-24, sin a few units of 2^-24 (4 allowed), the products and the sums one each:
// 2^-24 (h (k |x0| + 6) + 0.03 |g|).
TEST_P(QueryGpu, ParametersAHostSetsAreClampedAsTheRuntimeClampsThem) {
  std::string dir = test::makeTempDir("wg_query_gpu_host");
  test::writeFile(dir + "/hosted.json", R"J({"version": 1, "name": "hosted",
  "parameters": {
    "lift": {"type": "float", "default": 0.3, "min": 0, "max": 1},
    "int": {"type": "float", "default": 0.5, "min": 0.1, "max": 1},
    "errno": {"type": "float", "default": 0.7}},
  "nodes": [
    {"id": "waves", "type": "gerstner_waves", "options": {"waves": )J" + std::string(test::kModerateWaves) + R"J(}},
    {"id": "p", "type": "world_position"},
    {"id": "bump", "type": "expression",
     "options": {"inputs": {"p": "vec3", "h": "float", "k": "float", "g": "float"},
                 "formula": "vec3(0.0, h * sin(k * p.x), 0.01 * g)"},
     "inputs": {"p": "p.out", "h": "$lift", "k": "$int", "g": "$errno"}},
    {"id": "surface", "type": "vertex_output",
     "inputs": {"position": "waves.position", "displacement": "bump.out", "normal": "waves.normal"}}
  ],
  "outputs": {"vertex": {"position": "surface.position", "normal": "surface.normal"},
              "fragment": {"color": "p.out"}}})J");
  const double h = 1.0, k = 0.1, g = -2.5;  // what the host's values become
  HostSettings host;
  host.values = {{"lift", {5.0}}, {"int", {std::nan("")}}, {"errno", {g}}};
  host.setParameters = "  p.lift = 5.0;\n  p.zzint = NAN;\n  p.zzerrno = -2.5;\n";
  host.extraBound = [&](const QueryPoint& q) { return std::ldexp(1.0, -24) * (h * (k * std::abs(q.x0) + 6) + 0.03 * std::abs(g)); };
  expectGpuAgrees(dir + "/hosted.json", "hosted", GetParam(), host);
  std::filesystem::remove_all(dir);
}

// The spectral ocean (graphs/open_ocean.json at its largest fft_size, 512, three cascades):
// the GPU simulates the maps in float32 (runtime/ocean_gpu_cascade.h) and the vertex stage
// reads them, the query computes them in double (codegen/query_ocean.h). Per component and
// cascade the float32 bound is the transform's error bound (ocean_transform_bound.h) times the
// 2-norm of the fields packed with it (h, Dx, Dz and dh/dx share the GPU's first texture),
// the texel coordinate's rounding 2^-24 (|u| + |v|) times 1.5 times the field's largest step
// between neighbouring texels (the slope of Catmull-Rom's cubic in u is at most 1.5 such
// steps), 24 roundings of the field's largest value in the bicubic mix (16 products and 15
// sums whose weights' magnitudes add to at most 1.25^2) and the weighted sum, and the fade weight's float32 distance and smoothstep (2^-24 (4 + 4.5 d /
// start)) times that value; plus 2^-24 (|x0| + |z0| + sum of the largest D) twice for the
// point and the sum. vk450 is not run here: the Vulkan vertex capture (query_vk_capture.h)
// binds no ocean maps; the Vulkan runtime's maps are held to the same double reference by
// tests/runtime/vk_ocean_test.cpp.
TEST(QueryGpuOcean, OpenOceanAtFftSize512OnGlsl330AndEs300) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/open_ocean.json"), diags);
  ASSERT_TRUE(graph);
  for (Node& node : graph->nodes)
    if (node.type == "ocean_spectrum") node.options.push_back({"fft_size", 512, {}, {}});
  CompileOptions o;
  o.targets = {Target::Glsl330, Target::Es300};
  o.tessellation = false;
  auto result = compileGraph(*graph, defaultRegistry(), o, diags);
  ASSERT_TRUE(result) << diags.sorted().front().message;
  const ocean::OceanSettings* sea = nullptr;
  for (const Op& op : result->program.ops)
    if (op.spec->type == "ocean_spectrum") sea = &op.parsedOptions->as<ocean::OceanSettings>();
  ASSERT_TRUE(sea);
  ASSERT_EQ(sea->cascades.resolution, 512);
  double fade = 0;
  for (const Op& op : result->program.ops)
    if (op.spec->type == "ocean_displacement") fade = op.parsedOptions->as<double>();
  ASSERT_GT(fade, 0);
  // Points (float32 numbers) near the camera, in each cascade's fade, and far out.
  const glm::vec3 camera(3.0f, 12.0f, -4.0f);
  std::vector<test::OceanPoint> at;
  for (double x0 : {-37.5, -6.25, 0.0, 2.125, 9.75, 48.5})
    for (double z0 : {-21.0, -0.5, 3.25, 30.0}) at.push_back({x0, z0});
  for (double r : {61.0, 80.0, 100.0, 119.0, 300.0, 420.0, 560.0, 2000.0}) at.push_back({r * 0.75, -r * 0.625});
  const std::vector<double> times = {0.0, 3.5, 1e6};
  std::string dir = test::makeTempDir("wg_query_gpu_ocean");
  auto header = queryCHeader("g", result->program, diags);
  ASSERT_TRUE(header);
  test::writeFile(dir + "/g.query.h", *header);
  const double cameraD[3] = {camera.x, camera.y, camera.z};
  test::writeFile(dir + "/main.c", test::oceanDriverC("g.query.h", "wg_g_", at, times, cameraD, false));
  auto query = test::compileAndRunC(dir, "cc -std=c99");
  ASSERT_EQ(query.size(), times.size() * at.size());
  std::vector<QueryPoint> points;
  for (const auto& p : at) points.push_back({p.x0, p.z0, 0.0});
  const double eps = std::ldexp(1.0, -24), lambda = sea->cascades.choppiness;
  const int n = sea->cascades.resolution;
  for (size_t k = 0; k < times.size(); ++k) {
    // Per cascade and component (lDx, h, lDz): the fields' norm, largest value and step.
    struct Scale {
      double norm = 0, largest[3] = {0, 0, 0}, step[3] = {0, 0, 0};
    };
    std::vector<Scale> scales;
    for (size_t c = 0; c < sea->cascades.tileLengths.size(); ++c) {
      ocean::OceanFields f = ocean::oceanFields(ocean::initialCascade(sea->spectrum, sea->cascades, static_cast<int>(c)),
                                                times[k], lambda);
      Scale s;
      s.norm = ocean_test::norm(f.height) + ocean_test::norm(f.displacementX) + ocean_test::norm(f.displacementZ) +
               ocean_test::norm(f.slopeX);
      const std::vector<double>* fields[3] = {&f.displacementX, &f.height, &f.displacementZ};
      for (int i = 0; i < 3; ++i) {
        const double scale = i == 1 ? 1.0 : lambda;
        for (int jz = 0; jz < n; ++jz)
          for (int jx = 0; jx < n; ++jx) {
            auto v = [&](int x, int z) { return scale * (*fields[i])[static_cast<size_t>((z % n) * n + (x % n))]; };
            s.largest[i] = std::max(s.largest[i], std::abs(v(jx, jz)));
            s.step[i] = std::max({s.step[i], std::abs(v(jx + 1, jz) - v(jx, jz)), std::abs(v(jx, jz + 1) - v(jx, jz))});
          }
      }
      scales.push_back(s);
    }
    auto bound = [&](const test::OceanPoint& p, int i) {
      const glm::dvec3 d(p.x0 - camera.x, -camera.y, p.z0 - camera.z);
      const double distance = glm::length(d);
      double b = 0, reach = 0;
      for (size_t c = 0; c < scales.size(); ++c) {
        const double texels = static_cast<float>(n / sea->cascades.tileLengths[c]);
        const double start = static_cast<float>(fade * sea->cascades.tileLengths[c]);
        const Scale& s = scales[c];
        b += ocean_test::transformBound(n) * (i == 1 ? 1.0 : lambda) * s.norm +
             1.5 * eps * texels * (std::abs(p.x0) + std::abs(p.z0)) * s.step[i] + 24 * eps * s.largest[i] +
             eps * (4 + 4.5 * distance / start) * s.largest[i];
        reach += s.largest[0] + s.largest[1] + s.largest[2];
      }
      return b + 2 * eps * (std::abs(p.x0) + std::abs(p.z0) + reach);
    };
    // The vertex stage samples the displacement maps alone: the simulation computes those,
    // not the fragment stage's slopes and foam (whose replay would be most of the passes).
    std::vector<TextureInfo> vertexMaps;
    for (const TextureInfo& t : result->manifest.textures)
      if (t.ocean && t.ocean->map == ocean::kDisplacementMap) vertexMaps.push_back(t);
    ASSERT_EQ(vertexMaps.size(), sea->cascades.tileLengths.size());
    for (Target target : {Target::Glsl330, Target::Es300}) {
      auto context = EglContext::create(apiFor(target));
      OceanSimulation simulation(result->manifest.oceans, vertexMaps,
                                 target == Target::Es300 ? SceneShaderApi::Es300 : SceneShaderApi::Gl330);
      simulation.update(times[k]);
      std::string vertex;
      for (const auto& f : result->files)
        if (f.name.ends_with("." + std::string(targetName(target)) + ".vert")) vertex = f.contents;
      Captured gpu = captureVertexStage(vertex, target == Target::Es300, result->manifest, points, times[k], {},
                                        &simulation, camera);
      ASSERT_TRUE(gpu.error.empty()) << gpu.error;
      ASSERT_EQ(gpu.positions.size(), 3 * points.size());
      double worst = 0;
      for (size_t j = 0; j < at.size(); ++j)
        for (int i = 0; i < 3; ++i) {
          const double d = std::abs(gpu.positions[3 * j + static_cast<size_t>(i)] -
                                    query[k * at.size() + j][static_cast<size_t>(i)]);
          const double allowed = bound(at[j], i);
          worst = std::max(worst, d / allowed);
          EXPECT_LE(d, allowed) << targetName(target) << " t " << times[k] << " point (" << at[j].x0 << ", " << at[j].z0
                                << ") component " << i;
        }
      std::printf("open_ocean 512 %s t=%g: worst GPU-query difference %.3f of the float32 bound\n",
                  std::string(targetName(target)).c_str(), times[k], worst);
    }
  }
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Targets, QueryGpu, ::testing::Bool(),
                         [](const auto& info) { return info.param ? std::string("vk450") : std::string("gl"); });

}  // namespace
}  // namespace wg::rt
