#pragma once
// The water of one compiled graph, drawn from what `watergraph compile --target glsl330
// --textures` wrote: the shaders the manifest lists, its uniforms (builtins computed here as
// docs/integration.md states them, parameters at their defaults), its node textures (each
// under the manifest's "file") and a water grid like the runtime's.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "headless_gl.h"

struct Camera {
  glm::vec3 position{0}, target{0}, up{0, 1, 0};
  float fovYDegrees = 55, near = 0.1f, far = 200;
};

struct DrawState {
  Camera camera;
  glm::vec3 sunDirection{0, 1, 0};
  double time = 0;  // seconds, in double: the time phases are formed from it
  int width = 0, height = 0;
};

class WaterDraw {
 public:
  // Reads `manifestPath` and the files beside it; builds a grid of `quads` x `quads` over
  // [-halfSize, halfSize]^2 at y = 0. False, with `why`, for anything this host cannot draw.
  bool load(const std::string& manifestPath, int quads, float halfSize, std::string& why);
  void draw(const DrawState& state) const;

 private:
  bool loadTextures(const std::string& folder, std::string& why);
  void setUniforms(const DrawState& state) const;

  nlohmann::json manifest_;
  GLuint program_ = 0, vertexArray_ = 0;
  GLsizei indexCount_ = 0;
  std::vector<GLuint> textures_;  // in the manifest's order: texture unit i
};
