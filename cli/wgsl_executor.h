#pragma once
// The WebGPU executor that `probe --target wgsl` and `check --target wgsl` run on
// (clients/webgpu/executor_server.mjs: Node.js and headless Chromium), or why it cannot run.
#ifdef WG_HAVE_RUNTIME
#include <initializer_list>
#include <memory>
#include <string>

#include "accuracy/gpu_executor.h"

namespace wg {

// Throws rt::RuntimeError (Kind::Environment: exit 2) whose message is `notRun` followed by
// what is missing (Node.js, one of `packages` in the client, Chromium, an adapter): the command
// did not run, and never passes.
std::unique_ptr<accuracy::GpuExecutor> wgslExecutorOrWhyNot(const std::string& notRun,
                                                           std::initializer_list<const char*> packages);

}  // namespace wg
#endif
