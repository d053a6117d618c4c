#pragma once
// What the tests of one pass each (pass_*_test.cpp) build their Programs with: small inline
// graphs parsed and resolved, and look-ups into the result.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "codegen/compile.h"
#include "codegen/passes.h"
#include "core/graph_io.h"
#include "core/resolve.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::passtest {

using test::graphJson;

inline std::string allText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.sorted()) s += formatText(x) + "\n";
  return s;
}

inline Program resolveText(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "test.json", diags);
  EXPECT_TRUE(graph) << allText(diags);
  if (!graph) return {};
  auto program = resolveGraph(*graph, defaultRegistry(), diags);
  EXPECT_TRUE(program) << allText(diags);
  if (!program) return {};
  return std::move(*program);
}

// The Program after the whole pass recipe, as compile and the frequency report see it.
inline Program finalProgram(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "test.json", diags);
  EXPECT_TRUE(graph) << allText(diags);
  if (!graph) return {};
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  EXPECT_TRUE(program) << allText(diags);
  return program ? std::move(*program) : Program{};
}

inline const Op* findOp(const Program& p, const std::string& id) {
  for (const auto& op : p.ops)
    if (op.nodeId == id) return &op;
  return nullptr;
}

inline int opIndex(const Program& p, const std::string& id) {
  for (size_t i = 0; i < p.ops.size(); ++i)
    if (p.ops[i].nodeId == id) return static_cast<int>(i);
  return -1;
}

inline const Removal* findRemoval(const Program& p, const std::string& what) {
  for (const auto& r : p.removed)
    if (r.what == what) return &r;
  return nullptr;
}

inline bool hasParameter(const Program& p, const std::string& name) {
  for (const auto& param : p.parameters)
    if (param.name == name) return true;
  return false;
}

inline const ProgramOutput& outputOf(const Program& p, OutputSlot slot) {
  const ProgramOutput* o = p.output(slot);
  if (!o) throw std::runtime_error("no such output");
  return *o;
}

struct Passes {
  Diagnostics diags;
  PassContext ctx{diags};
};

}  // namespace wg::passtest
