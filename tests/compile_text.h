#pragma once
// A graph given as JSON text, compiled for glsl330 without glslang: for tests that build
// a small graph inline. Fails the test (and returns an empty result) when it does not
// load or compile.
#include <string>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"

namespace wg::test {

inline CompileResult compileText(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "inline.json", diags);
  EXPECT_TRUE(graph);
  if (!graph) return {};
  CompileOptions o;
  o.targets = {Target::Glsl330};
  auto result = compileGraph(*graph, defaultRegistry(), o, diags);
  EXPECT_TRUE(result);
  return result ? *result : CompileResult{};
}

}  // namespace wg::test
