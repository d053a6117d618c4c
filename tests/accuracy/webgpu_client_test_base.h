#pragma once
// The fixture of the tests that run the WebGPU executor (clients/webgpu/executor_server.mjs):
// skipped, with the reason, without Node.js; the client's npm packages installed once per
// suite (a failed install fails each test, naming it); needChromium() skips without Debian's
// Chromium.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "test_support.h"

namespace wg::test {

class WebgpuClientTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (nodeOnPath().empty()) {
      skip_ = "Node.js (node) is not on PATH";
      return;
    }
    CmdResult r = runSplit(shellQuote(sourcePath("clients/three/test/npm_ci_cached.sh")) + " " +
                           shellQuote(sourcePath("clients/webgpu")));
    npmError_ = r.exit == 0 ? "" : "installing clients/webgpu's npm packages failed: " + r.err;
  }
  void SetUp() override {
    if (!skip_.empty()) GTEST_SKIP() << skip_;
    ASSERT_TRUE(npmError_.empty()) << npmError_;
  }
  static void needChromium() {
    if (!std::filesystem::exists("/usr/bin/chromium")) GTEST_SKIP() << "Debian's chromium is not installed (/usr/bin/chromium)";
  }
  static inline std::string skip_, npmError_;
};

}  // namespace wg::test
