#pragma once
// Evaluates one registered node through the CPU reference (evaluateOp), as resolve would
// set it up: options completed with defaults, unset inputs from their defaults or the
// environment's builtins. Shared by the optics, depth-and-colour and scattering tests.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "nodes/registry.h"

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
};

inline NodeOutputs runNode(const std::string& type, const std::vector<std::pair<std::string, Value>>& inputs,
                           const nlohmann::json& options = nlohmann::json::object(),
                           const EvalEnvironment& env = EvalEnvironment{}) {
  const NodeSpec* s = defaultRegistry().find(type);
  if (!s) throw std::out_of_range("no node type " + type);
  Op op;
  op.spec = s;
  op.nodeId = "test";
  op.options = nlohmann::json::object();
  for (const auto& o : s->options) op.options[o.name] = o.defaultValue;
  for (auto it = options.begin(); it != options.end(); ++it) op.options[it.key()] = it.value();
  std::vector<Value> values;
  for (const auto& p : s->inputs) {
    Value v;
    bool found = false;
    for (const auto& [name, value] : inputs)
      if (name == p.name) v = value, found = true;
    if (!found) {
      if (p.defaultValue) v = *p.defaultValue;
      else if (p.defaultBuiltin) v = env.builtin(*p.defaultBuiltin);
      else throw std::invalid_argument("input " + p.name + " unset");
    }
    values.push_back(v);
    op.inputTypes.push_back(p.type);
  }
  for (const auto& p : s->outputs) op.outputTypes.push_back(p.type);
  return {s, evaluateOp(op, values, env)};
}

// Parses and compiles a graph for every target (glslang validates each shader); returns
// the diagnostics as text, empty on success.
inline std::string compileGraphText(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "inline.json", diags);
  bool ok = false;
  if (graph) ok = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags).has_value() && !diags.hasErrors();
  if (ok) return "";
  std::string messages = graph ? "compile failed\n" : "parse failed\n";
  for (const auto& d : diags.all()) messages += formatText(d) + "\n";
  return messages;
}

}  // namespace wg::test
