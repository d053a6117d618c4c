#include "runtime/renderer.h"

#include <stdexcept>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "codegen/shader_interface.h"
#include "nodes/texture_source.h"
#include "runtime/memory_budget.h"
#include "runtime/node_texture.h"
#include "runtime/ocean_simulation.h"
#include "runtime/floating_buoys.h"
#include "runtime/gpu_cache.h"
#include "runtime/gpu_mesh.h"
#include "runtime/oblique_projection.h"
#include "runtime/output_transform.h"
#include "runtime/render_targets.h"
#include "runtime/water_uniforms.h"
#include "runtime/runtime_error.h"
#include "runtime/tessellation_budget.h"
#include "runtime/uniform_values.h"

namespace wg::rt {
namespace {

// The opaque scene's vertex layout (runtime/scene.h): position, normal, material.
const std::vector<std::pair<GLuint, int>> kOpaqueAttributes = {{0, 3}, {1, 3}, {kSceneMaterialLocation, 1}};


// A node texture's identity: the source and folder, and for a file its size and time of
// last change (builtin:* sources are made in memory and never change).
std::string textureCacheKey(const std::string& source, const std::string& dir) {
  std::string key = source + '\n' + dir;
  std::error_code ec;
  std::filesystem::path file = std::filesystem::path(dir) / source;
  auto size = std::filesystem::file_size(file, ec);
  if (!ec) {
    auto time = std::filesystem::last_write_time(file, ec);
    if (!ec) key += '\n' + std::to_string(size) + '\n' + std::to_string(time.time_since_epoch().count());
  }
  return key;
}

}  // namespace

struct Renderer::Impl {
  RenderSettings settings;
  bool es = false;
  PassPlan plan;
  // The plan's share of the memory budget, reserved before any target is made.
  std::optional<MemoryReservation> memory;
  Camera camera;
  float aspect = 1.0f;
  glm::mat4 view{1.0f}, projection{1.0f}, viewProjection{1.0f};
  glm::vec3 sun{0.0f, 1.0f, 0.0f};

  // Shared with a GpuCache when the Renderer was given one (identical texts, same object).
  std::shared_ptr<const Program> sky, opaque, water;
  // Deferred water: `water` is the graph's fragment shader on a full-screen triangle and
  // this the graph's vertex shader writing the water G-buffer.
  bool deferred = false;
  bool tessellated = false;  // the water grid is drawn as GL_PATCHES of 3

  void drawWaterMesh() const {
    if (tessellated) {
      glPatchParameteri(GL_PATCH_VERTICES, 3);
      glDrawElements(GL_PATCHES, waterMesh.indexCount, GL_UNSIGNED_INT, nullptr);
    } else {
      glDrawElements(GL_TRIANGLES, waterMesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
  }
  std::shared_ptr<const Program> waterGbuffer;
  std::vector<GLuint> waterPrograms() const {
    std::vector<GLuint> p{water->id()};
    if (waterGbuffer) p.push_back(waterGbuffer->id());
    return p;
  }
  std::shared_ptr<const Program> output;  // the output transform, when the plan runs it
  GLint outputFrame = -1, outputExposure = -1, outputToneMapper = -1;
  GLint skyInverseVp = -1, skySun = -1;
  GLint opaqueVp = -1, opaqueClip = -1, opaqueSun = -1;
  GpuMesh sceneMesh, waterMesh;
  GpuMesh buoys;                         // the floating buoys of settings.scene, in world space
  std::vector<FloatingPose> buoysDrawn;  // the poses `buoys` holds
  VertexArray emptyVao;
  // Water textures: (texture unit, GL target, texture).
  struct Binding {
    GLuint unit;
    GLenum target;
    GLuint texture;
  };
  std::vector<Binding> waterBindings;
  std::vector<std::shared_ptr<const Texture>> nodeTextures;
  std::shared_ptr<OceanSimulation> oceans;  // when the manifest lists oceans; may be shared
  GpuCache* cache = nullptr;  // not owned; may be null

  std::shared_ptr<const Program> link(const std::vector<ShaderSource>& sources, const std::string& what) {
    if (cache) return cache->program(sources, what);
    return std::make_shared<const Program>(linkProgram(sources, what));
  }

  RenderTargets targets;
  GpuTarget* find(SceneSampler s) { return targets.find(s); }
  const GpuTarget& frame() const { return targets.frame(); }
  const GpuTarget* picture() const { return targets.picture(plan); }

  // Uploads a node texture as the CPU reference samples it: its sampler state
  // (runtime/node_texture.h), row 0 at v = 0. Through the cache when there is one, keyed
  // by the source, its folder, the state and, for a file, its size and modification time:
  // a PNG saved again while the editor runs is loaded again.
  std::shared_ptr<const Texture> nodeTexture(const std::string& sampler, const std::string& source,
                                             const SamplerState& state,
                                             const std::map<std::string, TextureOrigin>& origins) {
    auto o = origins.find(source);
    std::string dir = o != origins.end() ? o->second.graphDir : ".";
    std::string owner = o != origins.end() ? o->second.owner : "texture " + sampler;
    auto upload = [&] {
      std::string why;
      auto img = loadTexture(source, dir, &why);
      if (!img || img->width <= 0 || img->height <= 0 ||
          img->rgba.size() != static_cast<size_t>(img->width) * static_cast<size_t>(img->height) * 4) {
        if (why.empty()) why = "no image data";
        throw TextureLoadError(owner + ": texture '" + source + "' cannot be loaded: " + why, source, why);
      }
      return makeNodeTexture(img->width, img->height, img->rgba.data(), state);
    };
    if (!cache) return std::make_shared<const Texture>(upload());
    std::string key = textureCacheKey(source, dir) + '\n' + std::string(wrapName(state.wrap)) + ' ' +
                      std::string(filterName(state.filter)) + ' ' + std::string(colorSpaceName(state.colorSpace));
    return cache->texture(key, upload);
  }

  WaterUniforms uniforms;
  FrameValues frameValues() const {
    FrameValues f;
    f.camera = camera;
    f.view = view;
    f.projection = projection;
    f.viewProjection = viewProjection;
    f.sun = sun;
    f.time = settings.scene.time;
    f.width = settings.width;
    f.height = settings.height;
    return f;
  }

  // Which texture unit each water sampler reads. Set again every frame, with the uniforms:
  // a program from the GpuCache may be shared with another Renderer.
  struct SamplerUnit {
    GLuint program;
    GLint location, unit;
  };
  std::vector<SamplerUnit> samplerUnits;

  // Every frame: the camera, time and sun may have changed since the last one.
  void applyUniforms() const {
    uniforms.apply(frameValues());
    for (const auto& s : samplerUnits) {
      glUseProgram(s.program);
      glUniform1i(s.location, s.unit);
    }
  }

  void setupWaterUniforms(const Manifest& manifest, const std::map<std::string, TextureOrigin>& origins) {
    uniforms.setup(manifest, waterPrograms(), frameValues());
    // Samplers: node textures (loaded here) and scene textures (render targets of the
    // planned passes), one texture unit each in manifest order.
    GLuint nextUnit = 0;
    for (const TextureInfo& t : manifest.textures) {
      const bool cube = t.type == Type::SamplerCube;
      GLuint texture = 0;
      if (t.ocean) {
        if (!oceans) manifestError("texture " + t.name + " is an ocean map, but the manifest lists no ocean_simulation pass");
        texture = oceans->map(*t.ocean);
      } else if (t.scene) {
        const GpuTarget* target = find(*t.scene);
        if (!target)
          manifestError("texture " + t.name + " (scene resource '" +
                        std::string(sceneResourceRow(sceneSamplerRow(*t.scene).resource).name) +
                        "') is not rendered by any pass the manifest lists");
        if (cube != target->spec.cube)
          manifestError("texture " + t.name + " has the wrong sampler type " + std::string(typeName(t.type)));
        texture = target->color ? target->color.id() : target->depth.id();
      } else {
        if (t.type != Type::Sampler2D)
          manifestError("node texture " + t.name + " must be a sampler2D, not " + std::string(typeName(t.type)));
        nodeTextures.push_back(nodeTexture(t.name, t.source, t.sampler, origins));
        texture = nodeTextures.back()->id();
      }
      bool used = false;
      for (GLuint program : waterPrograms()) {
        GLint loc = glGetUniformLocation(program, t.name.c_str());
        if (loc < 0) continue;
        if (!used) waterBindings.push_back({nextUnit++, cube ? GLenum(GL_TEXTURE_CUBE_MAP) : GLenum(GL_TEXTURE_2D), texture});
        used = true;
        samplerUnits.push_back({program, loc, static_cast<GLint>(waterBindings.back().unit)});  // set each frame
      }
    }
    // A scene sampler the shader reads but the manifest does not list is a contract break.
    for (const auto& row : sceneSamplerTable()) {
      const std::string s(row.glslName);
      const bool listed = std::any_of(manifest.textures.begin(), manifest.textures.end(),
                                      [&](const TextureInfo& t) { return t.name == s; });
      for (GLuint program : waterPrograms())
        if (glGetUniformLocation(program, s.c_str()) >= 0 && !listed)
          manifestError("the water shader samples " + s + " but the manifest's \"textures\" does not list it");
    }
    checkGl("setting the water uniforms and textures");
  }

  // The sky lies at the far plane (depth 1): drawn after the opaque scene with LEQUAL and
  // no depth writes, it shades only the pixels nothing else covered.
  void drawSky(const glm::mat4& vp) {
    if (!settings.scene.drawScene) return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(sky->id());
    // Inverted in double: a float inverse of a narrow field's matrix far from the origin
    // distorts the view directions' spacing by percents, and the disc is band-limited to
    // that spacing (sky_model.h). The web clients invert in double (JavaScript) too.
    glm::mat4 inv = glm::mat4(glm::inverse(glm::dmat4(vp)));
    glUniformMatrix4fv(skyInverseVp, 1, GL_FALSE, glm::value_ptr(inv));
    glUniform3fv(skySun, 1, glm::value_ptr(sun));
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
  }

  // Draws the opaque scene keeping the side where dot(plane, (p, 1)) >= 0.
  void drawOpaque(const glm::mat4& vp, const glm::vec4& plane) {
    if (!settings.scene.drawScene) return;
    glUseProgram(opaque->id());
    glUniformMatrix4fv(opaqueVp, 1, GL_FALSE, glm::value_ptr(vp));
    glUniform4fv(opaqueClip, 1, glm::value_ptr(plane));
    glUniform3fv(opaqueSun, 1, glm::value_ptr(sun));
    if (!es) glEnable(GL_CLIP_DISTANCE0);
    glBindVertexArray(sceneMesh.vao.id());
    glDrawElements(GL_TRIANGLES, sceneMesh.indexCount, GL_UNSIGNED_INT, nullptr);
    if (buoys.indexCount) {
      glBindVertexArray(buoys.vao.id());
      glDrawElements(GL_TRIANGLES, buoys.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    if (!es) glDisable(GL_CLIP_DISTANCE0);
  }

  void bindTarget(const GpuTarget& t, bool clearColor) {
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
    glViewport(0, 0, t.spec.width, t.spec.height);
    glDepthMask(GL_TRUE);
    glClearColor(0, 0, 0, 1);
    glClearDepthf(1.0f);
    glClear((clearColor && t.color ? GL_COLOR_BUFFER_BIT : 0) | (t.depth ? GL_DEPTH_BUFFER_BIT : 0));
  }

  void bindWaterTextures(bool bind) {
    for (const auto& b : waterBindings) {
      glActiveTexture(GL_TEXTURE0 + b.unit);
      glBindTexture(b.target, bind ? b.texture : 0);
    }
    glActiveTexture(GL_TEXTURE0);
  }

  void setCamera(const Camera& c) {
    camera = c;
    view = camera.view();
    projection = camera.projection(aspect);
    viewProjection = projection * view;
  }

  // Which half-space the water's own camera side is: above (+y) unless under water.
  float cameraSide() const { return camera.position.y >= 0.0f ? 1.0f : -1.0f; }

  // --- One function per pass kind (PassKind), run in the plan's order.
  static inline const glm::vec4 kNoClip = glm::vec4(0, 0, 0, 1);

  void environmentPass() {
    GpuTarget* t = find(SceneSampler::Environment);
    glm::mat4 p = glm::perspective(glm::radians(90.0f), 1.0f, kEnvironmentNear, kEnvironmentFar);
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo.id());
    glViewport(0, 0, t->spec.width, t->spec.height);
    for (int f = 0; f < 6; ++f) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f),
                             t->color.id(), 0);
      glClearColor(0, 0, 0, 1);  // what stays there without the scene (drawScene false)
      glClear(GL_COLOR_BUFFER_BIT);
      const EnvironmentFace& face = environmentFaces()[static_cast<size_t>(f)];
      drawSky(p * glm::lookAt(glm::vec3(0.0f), face.direction, face.up));
    }
  }

  // Every ocean's cascades at the scene's time (runtime/ocean_simulation.h).
  void oceanSimulationPass() {
    oceans->setFoamHistory(settings.animation ? FoamHistory::Continue : FoamHistory::Replay);
    oceans->update(settings.scene.time);
    // The state the passes after it expect (renderFrame's): the simulation turned depth
    // testing off, and the water mesh drawn without it shows its far waves over its near ones.
    glEnable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, settings.width, settings.height);
  }

  void depthPrepass() {
    bindTarget(*find(SceneSampler::SceneDepth), false);
    drawOpaque(viewProjection, kNoClip);
  }

  // The camera mirrored about y = 0; only what is on the camera's side of the water is
  // reflected.
  void planarReflectionPass() {
    bindTarget(*find(SceneSampler::Reflection), true);
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(1, -1, 1));
    const glm::mat4 mirrored = viewProjection * mirror;
    const glm::vec4 waterPlane(0, cameraSide(), 0, 0);
    if (settings.obliqueReflection) {
      // The mirrored camera sits on the far side of the water plane, as the oblique
      // projection requires; the sky keeps the plain matrix (it only reconstructs view
      // directions from it).
      glm::mat4 oblique = obliqueProjection(projection, planeToEye(view * mirror, waterPlane));
      drawOpaque(oblique * view * mirror, kNoClip);
    } else {
      drawOpaque(mirrored, waterPlane);
    }
    drawSky(mirrored);
  }

  // What lies beyond the surface, seen by the real camera.
  void refractionPass() {
    bindTarget(*find(SceneSampler::Refraction), true);
    drawOpaque(viewProjection, glm::vec4(0, -cameraSide(), 0, 0));
    drawSky(viewProjection);
  }

  void opaqueScenePass() {
    bindTarget(frame(), true);
    drawOpaque(viewProjection, kNoClip);
    drawSky(viewProjection);
  }

  void sceneColorCopyPass() {
    GpuTarget* copy = find(SceneSampler::SceneColor);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, frame().fbo.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, copy->fbo.id());
    // At a reduced scene resolution (manifest "pass_scales") the blit also shrinks the frame,
    // filtered where the colour format can be (float colour on ES without float filtering
    // cannot: nearest there, as the water samples it).
    const bool scaled = copy->spec.width != settings.width || copy->spec.height != settings.height;
    const GLenum filter = scaled && !sampledNearest(copy->spec, targets.floatLinear()) ? GL_LINEAR : GL_NEAREST;
    glBlitFramebuffer(0, 0, settings.width, settings.height, 0, 0, copy->spec.width, copy->spec.height, GL_COLOR_BUFFER_BIT,
                      filter);
  }

  // The water G-buffer: the graph's vertex shader (displacement included) writes the
  // surface's position, depth, normal and uv; where no water is, depth w = 1.
  void deferredWaterPass() {
    GpuTarget* g = find(SceneSampler::WaterSurface);
    bindTarget(*g, false);
    const float surfaceClear[4] = {0, 0, 0, 1}, normalClear[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, surfaceClear);
    glClearBufferfv(GL_COLOR, 1, normalClear);
    glUseProgram(waterGbuffer->id());
    bindWaterTextures(true);
    glBindVertexArray(waterMesh.vao.id());
    drawWaterMesh();
    bindWaterTextures(false);
  }

  void waterSurfacePass() {
    glBindFramebuffer(GL_FRAMEBUFFER, frame().fbo.id());
    glViewport(0, 0, settings.width, settings.height);
    glEnable(GL_BLEND);
    // Colour blended by the water's alpha; the frame's alpha stays 1.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(water->id());
    bindWaterTextures(true);
    if (deferred) {
      // Full-screen: every pixel is shaded by the graph (the underwater node's case 1
      // returns the scene colour), reading the scene and the G-buffer from textures.
      glDisable(GL_DEPTH_TEST);
      glBindVertexArray(emptyVao.id());
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glEnable(GL_DEPTH_TEST);
    } else {
      glBindVertexArray(waterMesh.vao.id());
      drawWaterMesh();
    }
    glDisable(GL_BLEND);
    bindWaterTextures(false);
  }

  // The frame's linear radiance through the view (core/view_transform.h) into the 8-bit
  // display image, texel for texel.
  void outputTransformPass() {
    const GpuTarget* d = picture();
    glBindFramebuffer(GL_FRAMEBUFFER, d->fbo.id());
    glViewport(0, 0, d->spec.width, d->spec.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(output->id());
    const OutputTransformUniforms u = outputTransformUniforms(settings.view);
    glUniform1f(outputExposure, u.exposureScale);
    glUniform1i(outputToneMapper, u.toneMapper);
    glUniform1i(outputFrame, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, frame().color.id());
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnable(GL_DEPTH_TEST);
  }

  double renderOneFrame() {
    // By PassKind, in renderPassTable() order.
    using PassFunction = void (Impl::*)();
    static constexpr PassFunction kPassFunctions[] = {
        &Impl::oceanSimulationPass,
        &Impl::environmentPass, &Impl::depthPrepass,       &Impl::planarReflectionPass, &Impl::refractionPass,
        &Impl::opaqueScenePass, &Impl::sceneColorCopyPass, &Impl::deferredWaterPass,    &Impl::waterSurfacePass,
        &Impl::outputTransformPass,
    };
    static_assert(std::size(kPassFunctions) == kRenderPassCount);
    auto start = std::chrono::steady_clock::now();
    // The buoys where this frame's scene floats them (a few hundred vertices, made again
    // only when they moved).
    if (settings.scene.buoys != buoysDrawn) {
      buoys = settings.scene.buoys.empty() ? GpuMesh{}
                                           : uploadMesh(buoyMesh(settings.scene.buoys), kOpaqueAttributes);
      buoysDrawn = settings.scene.buoys;
    }
    applyUniforms();
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    for (PassKind pass : plan.passes) (this->*kPassFunctions[static_cast<size_t>(pass)])();
    glBindVertexArray(0);
    glFinish();
    auto end = std::chrono::steady_clock::now();
    checkGl("rendering a frame");
    return std::chrono::duration<double, std::milli>(end - start).count();
  }

  Image read(bool asFloat) const {
    // Floats: the linear frame, before the output transform; bytes: the displayed image.
    const GpuTarget* source = asFloat ? &frame() : picture();
    if (!source || (asFloat && source->spec.color == ColorFormat::Rgba8))
      throw RuntimeError(RuntimeError::Kind::Manifest, asFloat ? "the frame holds no float colour"
                                                               : "an 8-bit read-back needs a renderer made without floatColor");
    return readTargetColor(*source, asFloat);
  }
};

Renderer::Renderer(const Manifest& manifest, std::vector<ShaderSource> waterSources, const RenderSettings& settings,
                   bool es, const std::map<std::string, TextureOrigin>& origins, GpuCache* cache,
                   std::shared_ptr<OceanSimulation> oceans)
    : impl_(std::make_unique<Impl>()) {
  Impl& r = *impl_;
  r.settings = settings;
  r.es = es;
  r.cache = cache;
  auto cam = settings.customCamera ? settings.customCamera : cameraPreset(settings.camera);
  if (!cam) throw RuntimeError(RuntimeError::Kind::Manifest, "unknown camera preset '" + settings.camera + "'");
  r.aspect = static_cast<float>(settings.width) / static_cast<float>(std::max(settings.height, 1));
  r.setCamera(*cam);
  r.sun = sunDirection(settings.scene);

  r.plan = planPasses(manifest, planOptionsFor(settings));
  r.memory.emplace(rendererBytes(r.plan, settings.floatColor),
                   "render targets and read-back at " + std::to_string(settings.width) + "x" + std::to_string(settings.height));

  // The attributes the graph reads must be the ones the grid provides, where it provides them.
  for (const AttributeInfo& a : manifest.attributes) {
    bool ok = (a.name == iface::kPositionAttribute && a.location == iface::kPositionLocation) ||
              (a.name == iface::kNormalAttribute && a.location == iface::kNormalLocation) ||
              (a.name == iface::kUvAttribute && a.location == iface::kUvLocation);
    if (!ok) manifestError("the water grid has no attribute " + a.name + " at location " + std::to_string(a.location));
  }
  // Tessellated graphs (manifest "tessellation") bring control and evaluation stages; the
  // water grid is then drawn as patches of three vertices.
  for (const auto& s : waterSources)
    r.tessellated |= s.stage == GL_TESS_CONTROL_SHADER || s.stage == GL_TESS_EVALUATION_SHADER;

  // ES 3.2 blends RGBA32F targets only with EXT_float_blend (llvmpipe has it).
  if (es && settings.floatColor && !epoxy_has_gl_extension("GL_EXT_float_blend"))
    throw RuntimeError(RuntimeError::Kind::Environment,
                       "cannot render: this OpenGL ES driver cannot blend RGBA32F targets (no GL_EXT_float_blend)");
  if (!es) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // ES 3 cube maps are always seamless

  SceneShaderSources ss = sceneShaderSources(es);
  r.sky = r.link({{GL_VERTEX_SHADER, "runtime sky.vert", ss.skyVertex}, {GL_FRAGMENT_SHADER, "runtime sky.frag", ss.skyFragment}},
                      "the runtime's sky pass");
  r.skyInverseVp = glGetUniformLocation(r.sky->id(), "u_inverse_view_projection");
  r.skySun = glGetUniformLocation(r.sky->id(), "u_sun_direction");
  r.opaque = r.link({{GL_VERTEX_SHADER, "runtime opaque.vert", ss.opaqueVertex},
                          {GL_FRAGMENT_SHADER, "runtime opaque.frag", ss.opaqueFragment}},
                         "the runtime's opaque scene");
  r.opaqueVp = glGetUniformLocation(r.opaque->id(), "u_view_projection");
  r.opaqueClip = glGetUniformLocation(r.opaque->id(), "u_clip_plane");
  r.opaqueSun = glGetUniformLocation(r.opaque->id(), "u_sun_direction");
  if (r.plan.runs(PassKind::OutputTransform)) {
    const SceneShaderApi api = es ? SceneShaderApi::Es300 : SceneShaderApi::Gl330;
    r.output = r.link({{GL_VERTEX_SHADER, "runtime fullscreen.vert", ss.fullscreenVertex},
                       {GL_FRAGMENT_SHADER, "runtime output_transform.frag", outputTransformFragment(api)}},
                      "the runtime's output transform");
    r.outputFrame = glGetUniformLocation(r.output->id(), "u_frame");
    r.outputExposure = glGetUniformLocation(r.output->id(), "u_exposure_scale");
    r.outputToneMapper = glGetUniformLocation(r.output->id(), "u_tone_mapper");
  }
  r.deferred = r.plan.runs(PassKind::DeferredWater);
  if (r.deferred) {
    // The graph's fragment shader runs full-screen; its other stages write the G-buffer.
    std::vector<ShaderSource> fullscreen{{GL_VERTEX_SHADER, "runtime fullscreen.vert", ss.fullscreenVertex}};
    std::vector<ShaderSource> gbuffer;
    for (const auto& src : waterSources) (src.stage == GL_FRAGMENT_SHADER ? fullscreen : gbuffer).push_back(src);
    gbuffer.push_back({GL_FRAGMENT_SHADER, "runtime water_gbuffer.frag", ss.waterGbufferFragment});
    r.water = r.link(fullscreen, "the graph's deferred water pass (full-screen); glslang accepted it");
    r.waterGbuffer = r.link(gbuffer, "the graph's water G-buffer; glslang accepted it");
  } else {
    r.water = r.link(waterSources, "the graph's water surface; glslang accepted it");
  }

  r.sceneMesh = uploadMesh(buildSceneMesh(), kOpaqueAttributes);
  // A tessellated draw stays within its budget of generated triangles (tessellation_budget.h).
  int gridQuads = settings.waterGridQuads;
  if (r.tessellated && manifest.tessellation) gridQuads = tessellatedGridQuads(gridQuads, manifest.tessellation->settings.factor);
  r.waterMesh = uploadMesh(buildWaterGrid(gridQuads),
                           {{iface::kPositionLocation, 3}, {iface::kNormalLocation, 3}, {iface::kUvLocation, 2}});
  r.emptyVao = makeVertexArray();
  checkGl("uploading the scene");
  r.targets.create(r.plan, r.es);
  if (r.plan.runs(PassKind::OceanSimulation)) {
    if (oceans && oceans->identity() != OceanSimulation::identity(manifest.oceans, manifest.textures))
      throw std::logic_error("a shared ocean simulation simulates other oceans than this manifest's");
    r.oceans = oceans ? std::move(oceans)
                      : std::make_shared<OceanSimulation>(manifest.oceans, manifest.textures,
                                                          es ? SceneShaderApi::Es300 : SceneShaderApi::Gl330);
  }
  r.setupWaterUniforms(manifest, origins);
  r.cache = nullptr;  // used only while constructing: the caller may destroy it afterwards
}

Renderer::~Renderer() = default;

double Renderer::renderFrame() { return impl_->renderOneFrame(); }
Image Renderer::readRgba8() const { return impl_->read(false); }
Image Renderer::readRgba32f() const { return impl_->read(true); }

std::vector<float> Renderer::readDepth() const {
  if (impl_->es) throw RuntimeError(RuntimeError::Kind::Manifest, "OpenGL ES cannot read the depth buffer back");
  return readTargetDepth(impl_->frame());
}
const PassPlan& Renderer::plan() const { return impl_->plan; }

bool Renderer::samplesNearest(SceneSampler s) const {
  const GpuTarget* t = impl_->find(s);
  if (!t) throw std::logic_error("samplesNearest: the plan has no target for this sampler");
  return sampledNearest(t->spec, impl_->targets.floatLinear());
}
int Renderer::createdTargetCount() const { return static_cast<int>(impl_->targets.size()); }
size_t Renderer::createdTargetBytes() const {
  size_t n = 0;
  for (const auto& t : impl_->targets) n += t.allocatedBytes;
  return n;
}
const RenderSettings& Renderer::settings() const { return impl_->settings; }

std::shared_ptr<OceanSimulation> Renderer::oceanSimulation() const { return impl_->oceans; }

void Renderer::setCamera(const Camera& camera) { impl_->setCamera(camera); }

void Renderer::setScene(const SceneOptions& scene) {
  impl_->settings.scene = scene;
  impl_->sun = sunDirection(scene);
}

bool Renderer::setParameter(const std::string& parameter, const std::vector<float>& value) {
  return impl_->uniforms.setParameter(parameter, value);
}

GLuint Renderer::frameTexture() const {
  const auto* p = impl_->picture();
  return p ? p->color.id() : impl_->frame().color.id();
}

void Renderer::setView(const ViewTransform& view) { impl_->settings.view = view; }

void Renderer::setAnimation(bool animation) { impl_->settings.animation = animation; }

}  // namespace wg::rt
