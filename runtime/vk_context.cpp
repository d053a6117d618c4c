#include "runtime/vk_context.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

[[noreturn]] void environmentError(const std::string& m) { throw RuntimeError(RuntimeError::Kind::Environment, m); }

bool hasLayer(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

// The first queue family with graphics, or -1.
int graphicsFamily(VkPhysicalDevice d) {
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
  for (uint32_t i = 0; i < n; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return static_cast<int>(i);
  return -1;
}

}  // namespace

void checkVk(VkResult result, const char* what) {
  if (result != VK_SUCCESS)
    throw RuntimeError(RuntimeError::Kind::Driver, std::string("Vulkan: ") + what + " failed (VkResult " + std::to_string(result) + ")");
}

VKAPI_ATTR VkBool32 VKAPI_CALL VkContext::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                    VkDebugUtilsMessageTypeFlagsEXT,
                                                    const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
  const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  static_cast<VkContext*>(self)->messages_.push_back(std::string(level) + ": " + (data->pMessage ? data->pMessage : ""));
  return VK_FALSE;  // the call goes on; the renderer reports the message after it
}

std::unique_ptr<VkContext> VkContext::create(const VulkanOptions& options) {
  std::unique_ptr<VkContext> c(new VkContext());
  uint32_t loaderVersion = 0;
  if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS || loaderVersion < VK_API_VERSION_1_3)
    environmentError("cannot render on Vulkan: the Vulkan loader offers no Vulkan 1.3 (install libvulkan1 and mesa-vulkan-drivers)");
  if (options.validation && !hasLayer(kValidationLayer))
    environmentError(std::string("cannot render on Vulkan with validation: the layer ") + kValidationLayer +
                     " is not installed (scripts/setup.sh installs vulkan-validationlayers)");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "watergraph";
  app.apiVersion = VK_API_VERSION_1_3;
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &VkContext::onMessage;
  messenger.pUserData = c.get();
  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  if (options.validation) {
    ici.enabledLayerCount = 1;
    ici.ppEnabledLayerNames = layers;
    ici.enabledExtensionCount = 1;
    ici.ppEnabledExtensionNames = extensions;
    ici.pNext = &messenger;  // also reports what instance creation itself finds
  }
  if (vkCreateInstance(&ici, nullptr, &c->instance_) != VK_SUCCESS)
    environmentError("cannot render on Vulkan: no Vulkan 1.3 instance (is mesa-vulkan-drivers installed?)");
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(c->instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create || create(c->instance_, &messenger, nullptr, &c->messenger_) != VK_SUCCESS)
      environmentError("cannot render on Vulkan with validation: VK_EXT_debug_utils is not available");
  }

  uint32_t n = 0;
  vkEnumeratePhysicalDevices(c->instance_, &n, nullptr);
  std::vector<VkPhysicalDevice> devices(n);
  vkEnumeratePhysicalDevices(c->instance_, &n, devices.data());
  int family = -1;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    family = graphicsFamily(d);
    if (p.apiVersion >= VK_API_VERSION_1_3 && family >= 0) {
      c->physical_ = d;
      c->deviceName_ = p.deviceName;
      c->apiVersion_ = p.apiVersion;
      break;
    }
  }
  if (!c->physical_)
    environmentError("cannot render on Vulkan: no Vulkan 1.3 device with graphics (mesa-vulkan-drivers provides lavapipe)");
  c->queueFamily_ = static_cast<uint32_t>(family);
  vkGetPhysicalDeviceMemoryProperties(c->physical_, &c->memory_);

  VkPhysicalDeviceFeatures supported;
  vkGetPhysicalDeviceFeatures(c->physical_, &supported);
  VkPhysicalDeviceFeatures features{};
  features.shaderClipDistance = VK_TRUE;  // the opaque scene's clip plane
  if (!supported.shaderClipDistance) environmentError("cannot render on Vulkan: " + c->deviceName_ + " has no shaderClipDistance");
  if (options.tessellation) {
    if (!supported.tessellationShader) environmentError("cannot render on Vulkan: " + c->deviceName_ + " has no tessellationShader");
    features.tessellationShader = VK_TRUE;
  }
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  v13.dynamicRendering = VK_TRUE;  // render passes without VkRenderPass/VkFramebuffer objects
  float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = c->queueFamily_;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.pNext = &v13;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.pEnabledFeatures = &features;
  checkVk(vkCreateDevice(c->physical_, &dci, nullptr, &c->device_), "creating the device");
  vkGetDeviceQueue(c->device_, c->queueFamily_, 0, &c->queue_);
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pci.queueFamilyIndex = c->queueFamily_;
  checkVk(vkCreateCommandPool(c->device_, &pci, nullptr, &c->pool_), "creating the command pool");
  return c;
}

VkContext::~VkContext() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::string VkContext::apiVersion() const {
  return std::to_string(VK_API_VERSION_MAJOR(apiVersion_)) + "." + std::to_string(VK_API_VERSION_MINOR(apiVersion_)) + "." +
         std::to_string(VK_API_VERSION_PATCH(apiVersion_));
}

void VkContext::submit(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = pool_;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  checkVk(vkAllocateCommandBuffers(device_, &ai, &cmd), "allocating a command buffer");
  struct Free {
    VkDevice d;
    VkCommandPool p;
    VkCommandBuffer c;
    ~Free() { vkFreeCommandBuffers(d, p, 1, &c); }
  } freeLater{device_, pool_, cmd};
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  checkVk(vkBeginCommandBuffer(cmd, &bi), "beginning a command buffer");
  record(cmd);
  checkVk(vkEndCommandBuffer(cmd), "ending a command buffer");
  VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd;
  checkVk(vkQueueSubmit(queue_, 1, &si, VK_NULL_HANDLE), "submitting commands");
  checkVk(vkQueueWaitIdle(queue_), "waiting for the queue");
}

std::vector<std::string> VkContext::takeValidationMessages() { return std::exchange(messages_, {}); }

void VkContext::throwOnValidationMessages(const std::string& when) {
  if (messages_.empty()) return;
  std::string text = "the Vulkan validation layer reported " + std::to_string(messages_.size()) + " message(s) while " + when;
  for (const auto& m : takeValidationMessages()) text += "\n  " + m;
  throw RuntimeError(RuntimeError::Kind::Driver, text);
}

uint32_t VkContext::memoryType(uint32_t allowedTypes, VkMemoryPropertyFlags properties) const {
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((allowedTypes & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & properties) == properties) return i;
  throw RuntimeError(RuntimeError::Kind::Driver, "Vulkan: no memory type with the properties the runtime needs");
}

}  // namespace wg::rt
