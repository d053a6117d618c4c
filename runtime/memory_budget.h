#pragma once
// The memory a render may take, estimated before anything is allocated (docs/robustness.md,
// "Memory at the largest sizes"): the render targets of each renderer (PassPlan::totalBytes:
// every target's colour and depth, six faces for a cube), the frame each one reads back,
// and the buffers a command keeps per pixel on the CPU (check's reference inputs and error
// maps). A renderer reserves its share when it is made, before it creates a target; a
// command with several renderers or CPU buffers checks its whole estimate first, so a size
// too large is one clear line (RuntimeError::Kind::Budget, exit 2) in milliseconds, not
// gigabytes later a failure of the driver or std::bad_alloc.
#include <cstddef>
#include <string>

#include "codegen/manifest.h"
#include "runtime/pass_plan.h"

namespace wg::rt {

struct RenderSettings;  // renderer.h

// 2 GiB: what one render command may hold. The environment variable
// WATERGRAPH_MEMORY_BUDGET_MIB lowers (or raises) it for a process: the tests use it to
// put sizes just over and under the budget without allocating gigabytes.
inline constexpr std::size_t kDefaultMemoryBudget = std::size_t{2} << 30;
std::size_t memoryBudget();

// What the process has reserved (MemoryReservation) and not yet released.
std::size_t memoryReserved();

// "1.86 GiB", "310 MiB": a byte count for messages.
std::string byteText(std::size_t bytes);

// Throws RuntimeError(Kind::Budget) when `bytes` more than what is reserved would pass the
// budget; `what` says what would take them ("render targets and read-back at 9999x9999").
void checkMemoryBudget(std::size_t bytes, const std::string& what);

// `bytes` of the budget, held until destruction; checkMemoryBudget first.
class MemoryReservation {
 public:
  MemoryReservation(std::size_t bytes, const std::string& what);
  ~MemoryReservation();
  MemoryReservation(const MemoryReservation&) = delete;
  MemoryReservation& operator=(const MemoryReservation&) = delete;
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t bytes_;
};

// One renderer's share: its plan's targets and the frame it reads back (RGBA32F for
// accuracy renders, else the RGBA8 picture).
std::size_t rendererBytes(const PassPlan& plan, bool floatColor);
// The same for a renderer (GL or Vulkan) of `manifest` with `settings`, before it is made.
std::size_t rendererBytes(const Manifest& manifest, const RenderSettings& settings);

// The pass plan options a renderer with `settings` plans with (both runtimes).
PlanOptions planOptionsFor(const RenderSettings& settings);

// Multiplication and addition that stop at SIZE_MAX: sizes come from the command line.
std::size_t saturatedProduct(std::size_t a, std::size_t b);
std::size_t saturatedSum(std::size_t a, std::size_t b);

}  // namespace wg::rt
