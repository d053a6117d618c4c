#pragma once
// The WebGPU executor's helper (clients/webgpu/executor_server.mjs: Node.js driving one headless
// Chromium) as one object: started once, asked one JSON job at a time, its answers checked.
// The probe's jobs (wgsl_executor.cpp) and check's frames (wgsl_water_frames.h) go through it.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/json_line_process.h"

namespace wg::accuracy {

struct WebgpuTools;

class WebgpuSession {
 public:
  // Starts the helper and waits for its page's WebGPU device. Throws rt::RuntimeError
  // (Kind::Environment) saying why it did not start: Chromium missing or not starting, no
  // adapter, the helper ending.
  explicit WebgpuSession(const WebgpuTools& tools);
  const std::string& device() const { return device_; }

  // Sends `job` and returns the answer. Throws rt::RuntimeError: Kind::Driver with the page's
  // message for an {"error"} answer (Tint rejected a module, WebGPU validation), Kind::Environment
  // when the helper fails or is silent for `timeoutSeconds`. `what` names the job in messages.
  nlohmann::json request(const nlohmann::json& job, int timeoutSeconds, const std::string& what);

  // Sends the runtime's scene description (`watergraph scene`) once per session: check's
  // waters and a probe of ocean maps (whose simulation runs its pass shaders) need it first.
  void sendSceneOnce();
  // Ids for check's waters, unique within the session.
  int nextWaterId = 0;

 private:
  std::unique_ptr<JsonLineProcess> helper_;
  std::string device_;
  bool sceneSent_ = false;
};

}  // namespace wg::accuracy
