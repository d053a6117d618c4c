#pragma once
// Evaluating one registered node and compiling small graphs, for the node suites. The
// set-up (defaults, builtins, port types) is the CPU backend's evaluateNode.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "test_support.h"

namespace wg::test {

struct NodeOutputs {
  const NodeSpec* spec = nullptr;
  std::vector<Value> values;
  const Value& operator[](const std::string& name) const {
    int i = spec->outputIndex(name);
    if (i < 0) throw std::out_of_range("no output " + name);
    return values[static_cast<size_t>(i)];
  }
  double scalar(const std::string& name) const { return (*this)[name][0]; }
  double first() const { return values.at(0)[0]; }
};

inline NodeOutputs runNode(const std::string& type, const std::vector<std::pair<std::string, Value>>& inputs,
                           const nlohmann::json& options = nlohmann::json::object(),
                           const EvalEnvironment& env = EvalEnvironment{}) {
  static TextureCache textures;
  const NodeSpec* s = defaultRegistry().find(type);
  if (!s) throw std::out_of_range("no node type " + type);
  return {s, evaluateNode(*s, options, inputs, env, &textures, sourceDir())};
}

inline EvalEnvironment atTime(double t) {
  EvalEnvironment env;
  env.time = Value::scalar(t);
  return env;
}

// Depth-buffer value of a linear view depth L: the inverse of linearize_depth,
// n / ((1 - d) + d n / f).
inline double depthOf(double linear, double n, double f) { return (1 - n / linear) / (1 - n / f); }

// Compiles a graph for every target (glslang validates each shader). Returns the result,
// or nullopt with the diagnostics in *messages.
inline std::optional<CompileResult> compileInline(const std::string& json, std::string* messages) {
  Diagnostics diags;
  auto graph = parseGraph(json, "inline.json", diags);
  std::optional<CompileResult> result;
  if (graph) result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  if (!result || diags.hasErrors()) {
    for (const auto& d : diags.all()) *messages += formatText(d) + "\n";
    return std::nullopt;
  }
  return result;
}

// The same, returning the diagnostics as text: empty on success.
inline std::string compileGraphText(const std::string& json) {
  std::string messages;
  return compileInline(json, &messages) ? "" : "compile failed\n" + messages;
}

}  // namespace wg::test
