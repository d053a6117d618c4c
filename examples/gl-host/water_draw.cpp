#include "water_draw.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stb_image.h>

namespace {

bool readText(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream text;
  text << in.rdbuf();
  out = text.str();
  return true;
}

GLuint compileStage(GLenum stage, const std::string& source, const std::string& file, std::string& why) {
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    why = file + ": the driver rejected it: " + log;
    return 0;
  }
  return shader;
}

// The water grid: u along +x, v along +z, normal +y (as the runtime's; the graph reads only
// the attributes the manifest lists, bound at their locations).
GLsizei buildGrid(int quads, float halfSize) {
  std::vector<float> vertices;
  for (int j = 0; j <= quads; ++j)
    for (int i = 0; i <= quads; ++i) {
      float u = static_cast<float>(i) / quads, v = static_cast<float>(j) / quads;
      vertices.insert(vertices.end(), {-halfSize + 2 * halfSize * u, 0, -halfSize + 2 * halfSize * v, 0, 1, 0, u, v});
    }
  std::vector<unsigned> indices;
  for (int j = 0; j < quads; ++j)
    for (int i = 0; i < quads; ++i) {
      unsigned a = static_cast<unsigned>(j * (quads + 1) + i), b = a + 1, c = a + static_cast<unsigned>(quads) + 1,
               d = c + 1;
      indices.insert(indices.end(), {a, c, b, b, c, d});
    }
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(unsigned)), indices.data(),
               GL_STATIC_DRAW);
  return static_cast<GLsizei>(indices.size());
}

GLint glWrap(const std::string& wrap) {
  if (wrap == "clamp") return GL_CLAMP_TO_EDGE;
  if (wrap == "mirror") return GL_MIRRORED_REPEAT;
  return GL_REPEAT;
}

}  // namespace

bool WaterDraw::load(const std::string& manifestPath, int quads, float halfSize, std::string& why) {
  std::string text;
  if (!readText(manifestPath, text)) {
    why = manifestPath + ": cannot be read";
    return false;
  }
  manifest_ = nlohmann::json::parse(text, nullptr, false);
  if (manifest_.is_discarded()) {
    why = manifestPath + ": not JSON";
    return false;
  }
  // Passes other than the water surface need scene targets this host does not render
  // (docs/integration.md, "Scene resources and render passes").
  for (const auto& pass : manifest_.value("passes", nlohmann::json::array()))
    if (pass != "water_surface") {
      why = manifestPath + ": the graph needs the pass '" + pass.get<std::string>() + "', which this host does not render";
      return false;
    }
  if (manifest_.contains("tessellation")) {
    why = manifestPath + ": a tessellated graph (this host draws triangles)";
    return false;
  }
  for (const auto& u : manifest_.value("uniforms", nlohmann::json::array())) {
    static const char* const known[] = {"model", "view_projection", "view", "projection", "camera_position",
                                        "camera_near_far", "time", "viewport_size", "sun_direction", "time_phase"};
    if (!u.contains("builtin")) continue;
    bool ok = false;
    for (const char* k : known) ok = ok || u["builtin"] == k;
    if (!ok) {
      why = manifestPath + ": the builtin '" + u["builtin"].get<std::string>() +
            "' (a probe's, or the removed --derived-uniforms'), which this host does not compute";
      return false;
    }
  }
  const auto& files = manifest_["targets"]["glsl330"];
  if (!files.is_object()) {
    why = manifestPath + ": not compiled for glsl330 (compile with --target glsl330)";
    return false;
  }
  const std::string folder = manifestPath.substr(0, manifestPath.find_last_of('/') + 1);
  program_ = glCreateProgram();
  for (const auto& [key, stage] : {std::pair<const char*, GLenum>{"vert", GL_VERTEX_SHADER}, {"frag", GL_FRAGMENT_SHADER}}) {
    const std::string file = folder + files.at(key).get<std::string>();
    std::string source;
    if (!readText(file, source)) {
      why = file + ": cannot be read";
      return false;
    }
    GLuint shader = compileStage(stage, source, file, why);
    if (!shader) return false;
    glAttachShader(program_, shader);
  }
  glLinkProgram(program_);
  GLint linked = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &linked);
  if (!linked) {
    why = manifestPath + ": the shaders do not link";
    return false;
  }

  glGenVertexArrays(1, &vertexArray_);
  glBindVertexArray(vertexArray_);
  indexCount_ = buildGrid(quads, halfSize);
  // Only the attributes the manifest lists, at their locations.
  for (const auto& a : manifest_.value("attributes", nlohmann::json::array())) {
    const std::string name = a.at("name");
    const GLuint location = a.at("location");
    const size_t offset = name == "a_position" ? 0 : name == "a_normal" ? 3 : name == "a_uv" ? 6 : 99;
    if (offset == 99) {
      why = manifestPath + ": an attribute this host's grid does not have: " + name;
      return false;
    }
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, name == "a_uv" ? 2 : 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
  }
  return loadTextures(folder, why);
}

bool WaterDraw::loadTextures(const std::string& folder, std::string& why) {
  for (const auto& t : manifest_.value("textures", nlohmann::json::array())) {
    if (!t.contains("file")) {
      why = "texture " + t.value("name", std::string()) + " is a scene resource, which this host does not render";
      return false;
    }
    const std::string file = folder + t.at("file").get<std::string>();
    // A PNG's first row is its top; GL's row 0 is v = 0, the bottom: flip on load.
    stbi_set_flip_vertically_on_load(1);
    int width = 0, height = 0, channels = 0;
    unsigned char* texels = stbi_load(file.c_str(), &width, &height, &channels, 4);
    if (!texels) {
      why = file + ": cannot be decoded (compile with --textures)";
      return false;
    }
    const nlohmann::json sampler = t.value("sampler", nlohmann::json::object());  // absent: the defaults
    const std::string filter = sampler.value("filter", "linear");
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, sampler.value("color_space", "linear") == "srgb" ? GL_SRGB8_ALPHA8 : GL_RGBA8, width,
                 height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    stbi_image_free(texels);
    if (filter == "mipmapped") glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    filter == "nearest" ? GL_NEAREST : filter == "mipmapped" ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter == "nearest" ? GL_NEAREST : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, glWrap(sampler.value("wrap", "repeat")));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, glWrap(sampler.value("wrap", "repeat")));
    textures_.push_back(texture);
  }
  return true;
}

void WaterDraw::setUniforms(const DrawState& s) const {
  const float aspect = static_cast<float>(s.width) / static_cast<float>(s.height);
  const glm::mat4 view = glm::lookAt(s.camera.position, s.camera.target, s.camera.up);
  const glm::mat4 projection = glm::perspective(glm::radians(s.camera.fovYDegrees), aspect, s.camera.near, s.camera.far);
  const glm::mat4 model(1.0f), viewProjection = projection * view;
  auto clampNearFar = [](float x) { return std::isnan(x) ? 1e-6f : std::fmin(std::fmax(x, 1e-6f), 1e30f); };
  for (const auto& u : manifest_.at("uniforms")) {
    const GLint at = glGetUniformLocation(program_, u.at("name").get<std::string>().c_str());
    if (at < 0) continue;  // declared but optimised out by the driver
    if (u.contains("parameter")) {
      // The default, clamped into [min, max] as every value a host sets must be; colour
      // parameters stay sRGB-authored (the shader linearises them).
      std::vector<float> v = u.at("default").is_array() ? u.at("default").get<std::vector<float>>()
                                                        : std::vector<float>{u.at("default").get<float>()};
      for (float& x : v) x = std::fmin(std::fmax(x, u.at("min").get<float>()), u.at("max").get<float>());
      switch (v.size()) {
        case 1: glUniform1f(at, v[0]); break;
        case 2: glUniform2fv(at, 1, v.data()); break;
        case 3: glUniform3fv(at, 1, v.data()); break;
        case 4: glUniform4fv(at, 1, v.data()); break;
      }
      continue;
    }
    const std::string builtin = u.at("builtin");
    if (builtin == "model") glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(model));
    else if (builtin == "view_projection") glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(viewProjection));
    else if (builtin == "view") glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(view));
    else if (builtin == "projection") glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(projection));
    else if (builtin == "camera_position") glUniform3fv(at, 1, glm::value_ptr(s.camera.position));
    else if (builtin == "camera_near_far") glUniform2f(at, clampNearFar(s.camera.near), clampNearFar(s.camera.far));
    else if (builtin == "time") glUniform1f(at, static_cast<float>(s.time));
    else if (builtin == "viewport_size") glUniform2f(at, static_cast<float>(s.width), static_cast<float>(s.height));
    else if (builtin == "sun_direction") glUniform3fv(at, 1, glm::value_ptr(glm::normalize(s.sunDirection)));
    else if (builtin == "time_phase") {
      // mod(w t, 2 pi) formed in double, then rounded: a float w t loses the phase at large t.
      const double omegaT = u.at("angular_frequency").get<double>() * s.time, twoPi = 6.283185307179586;
      glUniform1f(at, static_cast<float>(omegaT - twoPi * std::floor(omegaT / twoPi)));
    }
  }
  // Each texture on its own unit, in the manifest's order.
  for (size_t i = 0; i < textures_.size(); ++i) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
    glBindTexture(GL_TEXTURE_2D, textures_[i]);
    const std::string name = manifest_["textures"][i].at("name");
    glUniform1i(glGetUniformLocation(program_, name.c_str()), static_cast<GLint>(i));
  }
}

void WaterDraw::draw(const DrawState& state) const {
  glUseProgram(program_);
  setUniforms(state);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBindVertexArray(vertexArray_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}
