#include "runtime/renderer.h"

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
#include "runtime/gpu_cache.h"
#include "runtime/oblique_projection.h"
#include "runtime/output_transform.h"
#include "runtime/runtime_error.h"
#include "runtime/tessellation_budget.h"
#include "runtime/uniform_values.h"

namespace wg::rt {
namespace {


// One render target: colour and/or depth textures and the framebuffer drawing into them.
struct GpuTarget {
  TargetSpec spec;
  Texture color;
  Texture depth;
  Framebuffer fbo;
  size_t allocatedBytes = 0;  // measured from the driver's view of the textures
};

size_t internalFormatBytes(GLint f) {
  switch (f) {
    case GL_RGBA8: return 4;
    case GL_RGBA16F: return 8;
    case GL_RGBA32F: return 16;
    case GL_DEPTH_COMPONENT32F: return 4;
    default: return 0;
  }
}

// Bytes of level 0 of the bound texture as the driver reports it (all faces of a cube).
size_t measuredBytes(GLenum bindTarget) {
  GLenum level = bindTarget == GL_TEXTURE_CUBE_MAP ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X) : bindTarget;
  GLint w = 0, h = 0, f = 0;
  glGetTexLevelParameteriv(level, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(level, 0, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(level, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
  return static_cast<size_t>(w) * static_cast<size_t>(h) * internalFormatBytes(f) * (bindTarget == GL_TEXTURE_CUBE_MAP ? 6 : 1);
}

struct GpuMesh {
  VertexArray vao;
  Buffer vbo, ibo;
  GLsizei indexCount = 0;
};

GLenum colorInternalFormat(ColorFormat f) {
  return f == ColorFormat::Rgba32f ? GL_RGBA32F : f == ColorFormat::Rgba16f ? GL_RGBA16F : GL_RGBA8;
}

void setFilter(GLenum target, GLint filter) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (target == GL_TEXTURE_CUBE_MAP) glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

GpuMesh uploadMesh(const Mesh& m, const std::vector<std::pair<GLuint, int>>& attributes) {
  GpuMesh g;
  g.vao = makeVertexArray();
  g.vbo = makeBuffer();
  g.ibo = makeBuffer();
  glBindVertexArray(g.vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, g.vbo.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.vertices.size() * sizeof(float)), m.vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(unsigned)),
               m.indices.data(), GL_STATIC_DRAW);
  GLsizei stride = static_cast<GLsizei>(m.floatsPerVertex * sizeof(float));
  int offset = 0;
  for (auto [location, components] : attributes) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(static_cast<uintptr_t>(offset * sizeof(float))));
    offset += components;
  }
  glBindVertexArray(0);
  g.indexCount = static_cast<GLsizei>(m.indices.size());
  return g;
}

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
  VertexArray emptyVao;
  std::vector<GpuTarget> targets;
  // Water textures: (texture unit, GL target, texture).
  struct Binding {
    GLuint unit;
    GLenum target;
    GLuint texture;
  };
  std::vector<Binding> waterBindings;
  std::vector<std::shared_ptr<const Texture>> nodeTextures;
  std::unique_ptr<OceanSimulation> oceans;  // when the manifest lists oceans
  GpuCache* cache = nullptr;  // not owned; may be null

  std::shared_ptr<const Program> link(const std::vector<ShaderSource>& sources, const std::string& what) {
    if (cache) return cache->program(sources, what);
    return std::make_shared<const Program>(linkProgram(sources, what));
  }

  GpuTarget* find(SceneSampler s) {
    const std::string_view name = sceneSamplerRow(s).target;
    for (auto& t : targets)
      if (t.spec.name == name) return &t;
    return nullptr;
  }
  const GpuTarget& frame() const { return targets.front(); }
  // The target whose colour is the 8-bit picture (PassPlan::picture), or null.
  const GpuTarget* picture() const {
    const TargetSpec* p = plan.picture();
    for (const auto& t : targets)
      if (p && t.spec.name == p->name) return &t;
    return nullptr;
  }

  bool floatLinear = true;

  void createTargets() {
    floatLinear = !es || epoxy_has_gl_extension("GL_OES_texture_float_linear");
    for (const TargetSpec& spec : plan.targets) {
      GpuTarget t;
      t.spec = spec;
      t.fbo = makeFramebuffer();
      GLenum texTarget = spec.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
      if (spec.color != ColorFormat::None) {
        t.color = makeTexture();
        glBindTexture(texTarget, t.color.id());
        glTexStorage2D(texTarget, 1, colorInternalFormat(spec.color), spec.width, spec.height);
        setFilter(texTarget, sampledNearest(spec, floatLinear) ? GL_NEAREST : GL_LINEAR);
        t.allocatedBytes += measuredBytes(texTarget);
      }
      if (spec.depth != DepthFormat::None) {
        t.depth = makeTexture();
        glBindTexture(GL_TEXTURE_2D, t.depth.id());
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, spec.width, spec.height);
        setFilter(GL_TEXTURE_2D, GL_NEAREST);
        t.allocatedBytes += measuredBytes(GL_TEXTURE_2D);
      }
      glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
      if (t.color) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               spec.cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X : GL_TEXTURE_2D, t.color.id(), 0);
        GLenum buf = GL_COLOR_ATTACHMENT0;
        glDrawBuffers(1, &buf);
        if (spec.name == sceneSamplerRow(SceneSampler::WaterSurface).target) {  // the G-buffer draws into water_normal as well
          GpuTarget* normal = find(SceneSampler::WaterNormalUv);
          if (!normal) throw std::logic_error("the plan creates water_position without water_normal");
          glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, normal->color.id(), 0);
          GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
          glDrawBuffers(2, bufs);
        }
      } else {
        GLenum none = GL_NONE;
        glDrawBuffers(1, &none);
        glReadBuffer(GL_NONE);
      }
      if (t.depth) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, t.depth.id(), 0);
      GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
      if (status != GL_FRAMEBUFFER_COMPLETE) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "0x%04x", status);
        throw RuntimeError(RuntimeError::Kind::Driver,
                           "render target '" + spec.name + "' is incomplete on this driver (status " + buf + ")");
      }
      targets.push_back(std::move(t));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("creating render targets");
  }

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

  // A water uniform from the manifest: a graph parameter (its value kept here, so the
  // editor can change it between frames without a recompile) or a builtin recomputed from
  // the camera, time and sun every frame.
  struct WaterUniform {
    std::string name, parameter;
    Type type = Type::Float;
    BuiltinUniform builtin = BuiltinUniform::Time;  // when parameter is ""
    double angularFrequency = 0;  // time_phase
    std::shared_ptr<const DerivedValue> derived;  // derived: computed every frame from the parameters
    std::vector<float> value;     // parameter values
    // The parameter's manifest min/max: every value is clamped into them on upload, as the
    // generated shader may rely on the range (codegen/value_facts.h).
    float lo = -std::numeric_limits<float>::infinity(), hi = std::numeric_limits<float>::infinity();
    std::vector<std::pair<GLuint, GLint>> locations;  // (program, location) where it is used
  };
  std::vector<WaterUniform> uniforms;
  static void clampParameter(WaterUniform& u) { clampIntoRange(u.value, u.lo, u.hi); }

  std::vector<float> builtinValue(const WaterUniform& u) const {
    FrameValues f;
    f.camera = camera;
    f.view = view;
    f.projection = projection;
    f.viewProjection = viewProjection;
    f.sun = sun;
    f.time = settings.scene.time;
    f.width = settings.width;
    f.height = settings.height;
    if (u.derived) return derivedUniformValue(*u.derived, f, parameterValues());
    return builtinUniformValue(u.builtin, u.angularFrequency, f);
  }

  // The parameters' current (clamped) values in manifest order, as derived programs read
  // them (manifestParameters): what setParameter last gave, so the editor's changes reach
  // the derived uniforms at the next frame without a recompile.
  std::vector<Value> parameterValues() const {
    std::vector<Value> out;
    for (const auto& u : uniforms) {
      if (u.parameter.empty()) continue;
      Value v = Value::ofType(u.type);
      for (int i = 0; i < v.size() && static_cast<size_t>(i) < u.value.size(); ++i) v[i] = u.value[static_cast<size_t>(i)];
      out.push_back(v);
    }
    return out;
  }

  // Checked when the manifest is read, so a frame meets no builtin it cannot set. The
  // runtime provides a builtin when it has a value for it (not the probe's per-case ones).
  void checkRuntimeBuiltin(const WaterUniform& u) const {
    if (builtinValue(u).empty())
      manifestError("uniform " + u.name + " asks for builtin '" + std::string(builtinUniformRow(u.builtin).meaning) +
                    "', which the runtime does not provide");
  }

  void setUniform(const WaterUniform& u, const std::vector<float>& v) const {
    if (!u.locations.empty() && v.size() != static_cast<size_t>(componentCount(u.type)))
      manifestError("uniform " + u.name + " of type " + std::string(typeName(u.type)) + " got " + std::to_string(v.size()) +
                    " value(s)");
    for (auto [program, loc] : u.locations) {
      glUseProgram(program);
      switch (u.type) {
        case Type::Float: glUniform1f(loc, v[0]); break;
        case Type::Vec2: glUniform2fv(loc, 1, v.data()); break;
        case Type::Vec3: glUniform3fv(loc, 1, v.data()); break;
        case Type::Vec4: glUniform4fv(loc, 1, v.data()); break;
        case Type::Int:
        case Type::Bool: glUniform1i(loc, static_cast<GLint>(v[0])); break;
        case Type::Mat3: glUniformMatrix3fv(loc, 1, GL_FALSE, v.data()); break;
        case Type::Mat4: glUniformMatrix4fv(loc, 1, GL_FALSE, v.data()); break;
        default: break;  // refused when the manifest is read
      }
    }
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
    for (const auto& u : uniforms) setUniform(u, u.parameter.empty() ? builtinValue(u) : u.value);
    for (const auto& s : samplerUnits) {
      glUseProgram(s.program);
      glUniform1i(s.location, s.unit);
    }
  }

  void setupWaterUniforms(const Manifest& manifest, const std::map<std::string, TextureOrigin>& origins) {
    for (const ManifestUniform& m : manifest.uniforms) {
      WaterUniform u;
      u.name = m.name;
      u.type = m.type;
      if (isSampler(u.type))
        manifestError("uniform " + u.name + " has a type the runtime cannot set: " + std::string(typeName(u.type)));
      if (m.parameter) {
        u.parameter = m.parameter->name;
        u.value.assign(m.parameter->defaultValue.begin(), m.parameter->defaultValue.end());
        if (m.parameter->min) u.lo = static_cast<float>(*m.parameter->min);
        if (m.parameter->max) u.hi = static_cast<float>(*m.parameter->max);
        clampParameter(u);
      } else {
        u.builtin = m.builtin;
        u.angularFrequency = m.angularFrequency;
        u.derived = m.derived;
        if (u.builtin == BuiltinUniform::Derived && !u.derived) manifestError("derived uniform " + u.name + " has no program");
        if (!u.derived) checkRuntimeBuiltin(u);
      }
      for (GLuint program : waterPrograms()) {
        GLint loc = glGetUniformLocation(program, u.name.c_str());
        if (loc >= 0) u.locations.emplace_back(program, loc);  // else optimised out by the driver
      }
      uniforms.push_back(std::move(u));
    }
    // Errors now, not at the first frame (derived uniforms need every parameter first).
    for (const auto& u : uniforms) setUniform(u, u.parameter.empty() ? builtinValue(u) : u.value);
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
    glm::mat4 inv = glm::inverse(vp);
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
    const GLenum filter = scaled && !sampledNearest(copy->spec, floatLinear) ? GL_LINEAR : GL_NEAREST;
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
    Image img;
    img.width = settings.width;
    img.height = settings.height;
    size_t n = static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 4;
    // Floats: the linear frame, before the output transform; bytes: the displayed image.
    const GpuTarget* source = asFloat ? &frame() : picture();
    if (!source || (asFloat && source->spec.color == ColorFormat::Rgba8))
      throw RuntimeError(RuntimeError::Kind::Manifest, asFloat ? "the frame holds no float colour"
                                                               : "an 8-bit read-back needs a renderer made without floatColor");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source->fbo.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    size_t rowElems = static_cast<size_t>(img.width) * 4;
    auto flip = [&](auto& v) {  // GL rows are bottom-up; images are top-down
      for (int y = 0; y < img.height / 2; ++y)
        std::swap_ranges(v.begin() + static_cast<ptrdiff_t>(y * rowElems), v.begin() + static_cast<ptrdiff_t>((y + 1) * rowElems),
                         v.begin() + static_cast<ptrdiff_t>((img.height - 1 - y) * rowElems));
    };
    if (asFloat) {
      img.rgba32f.resize(n);
      glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, img.rgba32f.data());
      flip(img.rgba32f);
    } else {
      img.rgba8.resize(n);
      glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba8.data());
      flip(img.rgba8);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    checkGl("reading the frame back");
    return img;
  }
};

Renderer::Renderer(const Manifest& manifest, std::vector<ShaderSource> waterSources, const RenderSettings& settings,
                   bool es, const std::map<std::string, TextureOrigin>& origins, GpuCache* cache)
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

  r.sceneMesh = uploadMesh(buildSceneMesh(), {{0, 3}, {1, 3}, {kSceneMaterialLocation, 1}});
  // A tessellated draw stays within its budget of generated triangles (tessellation_budget.h).
  int gridQuads = settings.waterGridQuads;
  if (r.tessellated && manifest.tessellation) gridQuads = tessellatedGridQuads(gridQuads, manifest.tessellation->settings.factor);
  r.waterMesh = uploadMesh(buildWaterGrid(gridQuads),
                           {{iface::kPositionLocation, 3}, {iface::kNormalLocation, 3}, {iface::kUvLocation, 2}});
  r.emptyVao = makeVertexArray();
  checkGl("uploading the scene");
  r.createTargets();
  if (r.plan.runs(PassKind::OceanSimulation))
    r.oceans = std::make_unique<OceanSimulation>(manifest.oceans, manifest.textures, es ? SceneShaderApi::Es300 : SceneShaderApi::Gl330);
  r.setupWaterUniforms(manifest, origins);
  r.cache = nullptr;  // used only while constructing: the caller may destroy it afterwards
}

Renderer::~Renderer() = default;

double Renderer::renderFrame() { return impl_->renderOneFrame(); }
Image Renderer::readRgba8() const { return impl_->read(false); }
Image Renderer::readRgba32f() const { return impl_->read(true); }

std::vector<float> Renderer::readDepth() const {
  if (impl_->es) throw RuntimeError(RuntimeError::Kind::Manifest, "OpenGL ES cannot read the depth buffer back");
  const int w = impl_->settings.width, h = impl_->settings.height;
  std::vector<float> depth(static_cast<size_t>(w) * static_cast<size_t>(h));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->frame().fbo.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  checkGl("reading the depth buffer back");
  for (int y = 0; y < h / 2; ++y)  // GL rows are bottom-up
    std::swap_ranges(depth.begin() + static_cast<ptrdiff_t>(y) * w, depth.begin() + static_cast<ptrdiff_t>(y + 1) * w,
                     depth.begin() + static_cast<ptrdiff_t>(h - 1 - y) * w);
  return depth;
}
const PassPlan& Renderer::plan() const { return impl_->plan; }

bool Renderer::samplesNearest(SceneSampler s) const {
  const GpuTarget* t = impl_->find(s);
  if (!t) throw std::logic_error("samplesNearest: the plan has no target for this sampler");
  return sampledNearest(t->spec, impl_->floatLinear);
}
int Renderer::createdTargetCount() const { return static_cast<int>(impl_->targets.size()); }
size_t Renderer::createdTargetBytes() const {
  size_t n = 0;
  for (const auto& t : impl_->targets) n += t.allocatedBytes;
  return n;
}
const RenderSettings& Renderer::settings() const { return impl_->settings; }

void Renderer::setCamera(const Camera& camera) { impl_->setCamera(camera); }

void Renderer::setScene(const SceneOptions& scene) {
  impl_->settings.scene = scene;
  impl_->sun = sunDirection(scene);
}

bool Renderer::setParameter(const std::string& parameter, const std::vector<float>& value) {
  bool found = false;
  for (auto& u : impl_->uniforms) {
    if (u.parameter != parameter) continue;
    if (value.size() != u.value.size()) return false;
    u.value = value;
    Impl::clampParameter(u);
    found = true;
  }
  return found;
}

GLuint Renderer::frameTexture() const {
  const auto* p = impl_->picture();
  return p ? p->color.id() : impl_->frame().color.id();
}

void Renderer::setView(const ViewTransform& view) { impl_->settings.view = view; }

}  // namespace wg::rt
