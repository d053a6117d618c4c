#pragma once
// The typed form of a graph that codegen transforms: operations in topological order,
// each a node type applied to typed values. resolve builds it; every codegen pass takes
// one Program and leaves another.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/node_spec.h"
#include "core/source_ref.h"
#include "core/type_list.h"
#include "core/value.h"

namespace wg {

struct ValueRef {
  enum class Kind { None, Op, Param, Const, Builtin };
  Kind kind = Kind::None;
  int index = -1;  // Op: op index; Param: parameter index; Builtin: Builtin enumerator
  int port = 0;    // Op: output port

  static ValueRef op(int index, int port) { return {Kind::Op, index, port, nullptr}; }
  static ValueRef param(int index) { return {Kind::Param, index, 0, nullptr}; }
  static ValueRef constant_(const Value& v) { return {Kind::Const, -1, 0, std::make_shared<const Value>(v)}; }
  // A constant another ref already holds (resolve shares one per distinct literal).
  static ValueRef constant_(std::shared_ptr<const Value> v) { return {Kind::Const, -1, 0, std::move(v)}; }
  static ValueRef builtin(Builtin b) { return {Kind::Builtin, static_cast<int>(b), 0, nullptr}; }
  // Const: its value; any other kind: an invalid Value.
  const Value& constant() const { return constant_value ? *constant_value : noConstant(); }
  bool operator==(const ValueRef& o) const {
    return kind == o.kind && index == o.index && port == o.port &&
           (kind != Kind::Const || constant() == o.constant());
  }

  // Held out of line and shared: a Value is 136 bytes (room for a mat4) and a program holds
  // a ref per op input, nearly all of them op outputs; inline, they made every input vector,
  // copy and pass table several times larger than the references themselves.
  std::shared_ptr<const Value> constant_value;

 private:
  static const Value& noConstant() {
    static const Value none;
    return none;
  }
};

struct Op {
  const NodeSpec* spec = nullptr;
  std::string nodeId;               // the graph node it came from (for messages, manifest)
  SourceRef where;
  // Complete (defaults filled in), and the same in the node's struct. Both are held once
  // per distinct value and shared by the ops that have it: a large graph repeats a few
  // option sets, and a JSON object per op was a map and its strings per op.
  std::shared_ptr<const nlohmann::json> sharedOptions;
  std::shared_ptr<const ParsedOptions> parsedOptions;
  const nlohmann::json& options() const { return sharedOptions ? *sharedOptions : noOptions(); }
  void setOptions(nlohmann::json complete) { sharedOptions = std::make_shared<const nlohmann::json>(std::move(complete)); }
  std::vector<ValueRef> inputs;     // one per spec input port
  TypeList inputTypes;   // the port types (after unification)
  TypeList outputTypes;
  std::vector<std::string> mergedIds;  // node ids CSE folded into this op
  // Inside a subgraph: the instances it was inlined through, innermost first (`where` is
  // in the subgraph's file). Diagnostics about the op carry them as notes.
  std::shared_ptr<const std::vector<LocatedNote>> instanceChain;
  unsigned stage = 0;               // set by the stage pass: kVertexStage / kFragmentStage

 private:
  static const nlohmann::json& noOptions() {
    static const nlohmann::json none;  // null, as a default-constructed member was
    return none;
  }
};

// A diagnostic about `op` names the subgraph instances it lies in.
inline Diagnostic& withInstanceNotes(Diagnostic& d, const Op& op) {
  if (op.instanceChain) d.locatedNotes.insert(d.locatedNotes.end(), op.instanceChain->begin(), op.instanceChain->end());
  return d;
}

struct ProgramParameter {
  std::string name;
  Type type = Type::Float;
  Value defaultValue;
  std::optional<double> min, max;
  std::string hint;
  std::string description;
  bool isStatic = false;
  SourceRef where;
};

struct ProgramOutput {
  OutputSlot slot{};
  ValueRef value;
  Type type = Type::Invalid;
  SourceRef where;
};

// A node or parameter that did not reach the output, and why (for the manifest).
struct Removal {
  std::string what;    // node id or "$param"
  std::string reason;  // "unreachable", "folded", "merged into 'x'", "static"
};

struct Program {
  std::string graphName;
  std::string description;
  ViewTransform view;  // the graph's "view", or the default (none, 0 EV)
  std::string file;
  std::string directory;  // the graph file's folder: texture paths are relative to it
  // `directory`, or "." for a graph file named without one: where a texture's (top-relative)
  // path is resolved, also for a texture a subgraph in another folder names.
  std::string folder() const { return directory.empty() ? "." : directory; }
  int totalNodes = 0;  // nodes in the graph file, each subgraph instance counted as the nodes it inlines
  // The graph files it imports, relative to `directory`, each once (the manifest's "imports").
  std::vector<std::string> importedFiles;
  // The GLSL function files its function nodes read, relative to `directory`, each once
  // (the depfile lists them), and the node types made from them, which its ops point at
  // (core/file_node.h).
  std::vector<std::string> functionFiles;
  std::vector<std::shared_ptr<const NodeSpec>> fileNodeSpecs;
  std::vector<ProgramParameter> parameters;
  std::vector<Op> ops;  // topological: inputs come before their users
  std::vector<ProgramOutput> outputs;
  std::vector<Removal> removed;
  // Set by the stage pass: op outputs computed in the vertex stage and read by the
  // fragment stage through a varying.
  std::vector<ValueRef> varyings;

  const ProgramOutput* output(OutputSlot slot) const;
  Type typeOf(const ValueRef& v) const;
  // The scene resources its ops read, in sceneResourceTable() order.
  std::vector<SceneResource> sceneResources() const;
  bool reads(SceneResource r) const;
};

}  // namespace wg
