#pragma once
// A headless Vulkan 1.3 device (Mesa's lavapipe on any machine; no window system, no
// swapchain): instance, the first device with a graphics queue, its queue and a command
// pool, and one-shot command submission. With validation the Khronos validation layer is
// enabled and every message it reports at warning or error severity is kept; the Vulkan
// renderer turns any kept message into an error, so a validation message fails a render.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace wg::rt {

inline constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

struct VulkanOptions {
  bool validation = false;  // enable kValidationLayer; a missing layer is an error, never skipped
  bool tessellation = false;  // ask for the tessellationShader feature
};

class VkContext {
 public:
  // Throws RuntimeError(Kind::Environment) with one line naming what is missing: the
  // loader, a Vulkan device, the validation layer (scripts/setup.sh installs it), a feature.
  static std::unique_ptr<VkContext> create(const VulkanOptions& options);
  ~VkContext();
  VkContext(const VkContext&) = delete;
  VkContext& operator=(const VkContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  const std::string& deviceName() const { return deviceName_; }
  std::string apiVersion() const;  // "1.3.230"
  bool validating() const { return messenger_ != VK_NULL_HANDLE; }

  // Records `record` into a fresh primary command buffer, submits it and waits for the
  // queue to finish it.
  void submit(const std::function<void(VkCommandBuffer)>& record);

  // Messages the validation layer reported since the last take (empty without validation).
  std::vector<std::string> takeValidationMessages();
  // Throws RuntimeError(Kind::Driver) listing them when any were reported; `when` says
  // what the runtime was doing ("rendering a frame").
  void throwOnValidationMessages(const std::string& when);

  uint32_t memoryType(uint32_t allowedTypes, VkMemoryPropertyFlags properties) const;

 private:
  VkContext() = default;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::string deviceName_;
  uint32_t apiVersion_ = 0;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::vector<std::string> messages_;
  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT types,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
};

// Throws RuntimeError(Kind::Driver) naming `what` when `result` is not VK_SUCCESS.
void checkVk(VkResult result, const char* what);

}  // namespace wg::rt
