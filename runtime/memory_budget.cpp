#include "runtime/memory_budget.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "runtime/renderer.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

std::atomic<std::size_t> gReserved{0};

}  // namespace

std::size_t memoryBudget() {
  // Read once: a budget that changed between two reservations would make no sense.
  static const std::size_t budget = [] {
    const char* env = std::getenv("WATERGRAPH_MEMORY_BUDGET_MIB");
    if (!env || !*env) return kDefaultMemoryBudget;
    char* end = nullptr;
    errno = 0;
    unsigned long long mib = std::strtoull(env, &end, 10);
    if (errno || *end || mib == 0 || mib > (std::numeric_limits<std::size_t>::max() >> 20)) return kDefaultMemoryBudget;
    return static_cast<std::size_t>(mib) << 20;
  }();
  return budget;
}

std::size_t memoryReserved() { return gReserved.load(); }

std::string byteText(std::size_t bytes) {
  char buf[64];
  const double mib = static_cast<double>(bytes) / (1024.0 * 1024.0);
  if (mib >= 1024) std::snprintf(buf, sizeof buf, "%.2f GiB", mib / 1024);
  else std::snprintf(buf, sizeof buf, "%.1f MiB", mib);
  return buf;
}

std::size_t saturatedProduct(std::size_t a, std::size_t b) {
  return a != 0 && b > std::numeric_limits<std::size_t>::max() / a ? std::numeric_limits<std::size_t>::max() : a * b;
}

std::size_t saturatedSum(std::size_t a, std::size_t b) {
  return b > std::numeric_limits<std::size_t>::max() - a ? std::numeric_limits<std::size_t>::max() : a + b;
}

void checkMemoryBudget(std::size_t bytes, const std::string& what) {
  const std::size_t held = memoryReserved(), budget = memoryBudget();
  if (bytes <= budget && held <= budget - bytes) return;
  std::string message = "cannot render: " + what + " would take " + byteText(bytes);
  if (held) message += " beside the " + byteText(held) + " already held";
  message += ", over the memory budget of " + byteText(budget) + " (docs/robustness.md); use a smaller --size";
  throw RuntimeError(RuntimeError::Kind::Budget, message);
}

MemoryReservation::MemoryReservation(std::size_t bytes, const std::string& what) : bytes_(bytes) {
  checkMemoryBudget(bytes, what);
  gReserved += bytes;
}

MemoryReservation::~MemoryReservation() { gReserved -= bytes_; }

std::size_t rendererBytes(const PassPlan& plan, bool floatColor) {
  const TargetSpec* frame = plan.target("frame");
  std::size_t pixels = frame ? saturatedProduct(static_cast<std::size_t>(frame->width), static_cast<std::size_t>(frame->height)) : 0;
  return saturatedSum(plan.totalBytes(), saturatedProduct(pixels, floatColor ? 16 : 4));
}

PlanOptions planOptionsFor(const RenderSettings& settings) {
  PlanOptions po;
  po.width = settings.width;
  po.height = settings.height;
  po.floatColor = settings.floatColor;
  po.pictureFormat = settings.pictureFormat;
  po.outputTransform = settings.outputTransform;
  po.environmentSize = settings.environmentSize;
  return po;
}

std::size_t rendererBytes(const Manifest& manifest, const RenderSettings& settings) {
  return rendererBytes(planPasses(manifest, planOptionsFor(settings)), settings.floatColor);
}

}  // namespace wg::rt
