#include "accuracy/webgpu_session.h"

#include "accuracy/gpu_executor.h"
#include "runtime/runtime_error.h"
#include "runtime/scene_description.h"

namespace wg::accuracy {
namespace {

using rt::RuntimeError;

// How long Chromium may take to start and hand out an adapter.
constexpr int kWebgpuStartSeconds = 120;
// How long the page may take to take the scene description.
constexpr int kWebgpuSceneSeconds = 120;

}  // namespace

WebgpuSession::WebgpuSession(const WebgpuTools& tools) {
  try {
    helper_ = std::make_unique<JsonLineProcess>(
        std::vector<std::string>{tools.node, tools.clientDir + "/executor_server.mjs", "--chromium", tools.chromium});
    nlohmann::json ready = helper_->receive(kWebgpuStartSeconds);
    if (ready.contains("skipped"))
      throw RuntimeError(RuntimeError::Kind::Environment, "WebGPU is not available: " + ready["skipped"].get<std::string>());
    device_ = ready.value("device", std::string("WebGPU"));
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const RuntimeError*>(&e)) throw;
    throw RuntimeError(RuntimeError::Kind::Environment, std::string("the WebGPU helper did not start: ") + e.what());
  }
}

nlohmann::json WebgpuSession::request(const nlohmann::json& job, int timeoutSeconds, const std::string& what) {
  nlohmann::json reply;
  try {
    helper_->send(job);
    reply = helper_->receive(timeoutSeconds);
  } catch (const std::runtime_error& e) {
    throw RuntimeError(RuntimeError::Kind::Environment, what + ": the WebGPU helper failed: " + e.what());
  }
  if (reply.contains("error")) {
    const nlohmann::json& error = reply["error"];
    throw RuntimeError(RuntimeError::Kind::Driver, what + ": " + (error.is_string() ? error.get<std::string>() : error.dump()));
  }
  return reply;
}

void WebgpuSession::sendSceneOnce() {
  if (sceneSent_) return;
  request({{"kind", "scene"}, {"description", nlohmann::json::parse(rt::sceneDescriptionJson(rt::SceneOptions{}))}},
          kWebgpuSceneSeconds, "the scene description");
  sceneSent_ = true;
}

}  // namespace wg::accuracy
