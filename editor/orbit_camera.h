#pragma once
// The preview's orbit camera: yaw and pitch around a target point at a distance, moved by
// the mouse (drag to orbit, wheel to zoom, right drag to pan) and set from the scene's
// camera presets.
#include <glm/glm.hpp>

#include "runtime/scene.h"

namespace wg::editor {

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float yawDegrees = 0;     // around +y, 0 looking from +z towards -z
  float pitchDegrees = 20;  // above the horizon; negative looks from below
  float distance = 20;
  float fovYDegrees = 55;   // kept from the preset

  static OrbitCamera fromCamera(const rt::Camera& camera);
  rt::Camera toCamera() const;
  void orbit(float dxPixels, float dyPixels);
  void zoom(float wheelSteps);
  void pan(float dxPixels, float dyPixels);
};

}  // namespace wg::editor
