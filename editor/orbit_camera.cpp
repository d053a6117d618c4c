#include "editor/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace wg::editor {

OrbitCamera OrbitCamera::fromCamera(const rt::Camera& camera) {
  OrbitCamera o;
  o.target = camera.target;
  o.fovYDegrees = camera.fovYDegrees;
  glm::vec3 d = camera.position - camera.target;
  o.distance = std::max(glm::length(d), 0.1f);
  o.pitchDegrees = glm::degrees(std::asin(std::clamp(d.y / o.distance, -1.0f, 1.0f)));
  o.yawDegrees = glm::degrees(std::atan2(d.x, d.z));
  return o;
}

rt::Camera OrbitCamera::toCamera() const {
  rt::Camera c;
  float yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
  glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
  c.target = target;
  c.fovYDegrees = fovYDegrees;
  c.position = target + offset * distance;
  return c;
}

void OrbitCamera::orbit(float dx, float dy) {
  yawDegrees = std::fmod(yawDegrees - dx * 0.3f, 360.0f);
  // Short of the poles, where the view's up vector would flip.
  pitchDegrees = std::clamp(pitchDegrees + dy * 0.3f, -89.0f, 89.0f);
}

void OrbitCamera::zoom(float steps) { distance = std::clamp(distance * std::pow(0.9f, steps), 0.5f, 150.0f); }

void OrbitCamera::pan(float dx, float dy) {
  float yaw = glm::radians(yawDegrees);
  glm::vec3 right(std::cos(yaw), 0, -std::sin(yaw));
  float scale = distance * 0.002f;
  target += right * (-dx * scale) + glm::vec3(0, dy * scale, 0);
}

}  // namespace wg::editor
