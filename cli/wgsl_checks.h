#pragma once
// The checks of a WGSL module that run outside the compiler, in JavaScript: naga
// (clients/webgpu/naga_check.mjs, npm naga-wasm) and Tint (clients/webgpu/tint_check.mjs,
// Chromium's WebGPU), and what `probe --target wgsl` needs to start its helper. Each either ran, with the messages it gave, or did not run, with the
// reason (no Node.js, the client's npm packages not installed, no Chromium, no WebGPU
// adapter): a check that did not run is never reported as passed.
#include <string>
#include <vector>

namespace wg {

struct WgslCheckMessage {
  int line = 0, column = 0;  // 1-based; 0 when the checker gave no position
  std::string text;
};

struct WgslCheckOutcome {
  std::string checker;  // "naga", "Tint"
  bool ran = false;
  std::string notRunBecause;  // when !ran
  std::vector<WgslCheckMessage> errors;
};

// The folder holding the client's scripts and node_modules: $WATERGRAPH_WEBGPU_CLIENT, else the
// source tree's clients/webgpu this binary was built from.
std::string webgpuClientDir();

// Node.js found on $PATH, or "".
std::string nodeExecutable();
// Why the client's scripts needing the npm package `package` cannot run (no Node.js, the
// package not installed), or "" when they can (Chromium is the scripts' own question).
std::string webgpuClientMissing(const std::string& package);

// Runs the checker on `wgsl` (written to a temporary file that is removed afterwards).
WgslCheckOutcome runNagaCheck(const std::string& wgsl);
WgslCheckOutcome runTintCheck(const std::string& wgsl);

}  // namespace wg
