#pragma once
// Evaluates one registered node through the CPU reference (evaluateOp) as resolve would set
// it up: options completed with defaults, unset inputs from their defaults or the
// environment's builtins, Gen/Custom port types unified and `infer` applied, and a texture
// cache for nodes that sample textures. Shared by the noise, caustics and foam tests.
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

struct NoiseNodeOutputs {
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

inline NoiseNodeOutputs evalNode(const std::string& type, const std::vector<std::pair<std::string, Value>>& inputs,
                                 const nlohmann::json& options = nlohmann::json::object(),
                                 const EvalEnvironment& env = EvalEnvironment{}) {
  static TextureCache textures;
  const NodeSpec* s = defaultRegistry().find(type);
  if (!s) throw std::out_of_range("no node type " + type);
  Op op;
  op.spec = s;
  op.nodeId = "test";
  op.options = nlohmann::json::object();
  for (const auto& o : s->options) op.options[o.name] = o.defaultValue;
  for (auto it = options.begin(); it != options.end(); ++it) op.options[it.key()] = it.value();
  std::vector<Value> values;
  Type gen = Type::Float;
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
    if (p.kind == PortKind::Gen && v.type != Type::Float) gen = v.type;
    values.push_back(v);
  }
  for (size_t i = 0; i < s->inputs.size(); ++i) {
    const PortSpec& p = s->inputs[i];
    op.inputTypes.push_back(p.kind == PortKind::Fixed ? p.type : p.kind == PortKind::Gen ? gen : values[i].type);
  }
  for (const auto& p : s->outputs)
    op.outputTypes.push_back(p.kind == PortKind::Fixed ? p.type : p.kind == PortKind::Gen ? gen : Type::Invalid);
  if (s->infer) {
    InferContext ctx{*s, op.options, op.inputTypes, op.outputTypes, {}, -1};
    s->infer(ctx);
    if (!ctx.error.empty()) throw std::invalid_argument(ctx.error);
    op.inputTypes = ctx.inputTypes;
    op.outputTypes = ctx.outputTypes;
  }
  return {s, evaluateOp(op, values, env, &textures, sourceDir())};
}

inline EvalEnvironment atTime(double t) {
  EvalEnvironment env;
  env.time = Value::scalar(t);
  return env;
}

// Compiles a graph for every target (glslang validates each shader). Returns the result,
// or nullopt with the diagnostics in *messages.
inline std::optional<CompileResult> compileNoiseGraph(const std::string& json, std::string* messages) {
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

}  // namespace wg::test
