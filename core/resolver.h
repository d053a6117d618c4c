#pragma once
// The resolver (resolveGraph, core/resolve.h) as a class shared by the files that hold its
// steps; internal to core: nothing but core/resolve*.cpp includes it. One file was 1,200
// lines; each step is now a file of one job (the class below lists its members by file):
//   resolve.cpp             the entry points and the order of the steps; parameters, outputs
//   resolve_node_types.cpp  each node's type looked up, its options and textures checked
//   resolve_presets.cpp     the node options that presets set, checked whichever is applied
//   resolve_order.cpp       the nodes in data-flow order; cycles named
//   resolve_ops.cpp         one typed op per node; nodes that expand into ops
//   resolve_instances.cpp   subgraph instances inlined into the program
#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/color_parameters.h"
#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/id_index.h"
#include "core/instance_options.h"
#include "core/interned_values.h"
#include "core/node_output_values.h"
#include "core/node_spec.h"
#include "core/program.h"
#include "core/registry.h"
#include "core/suggest.h"

namespace wg::resolving {


inline std::string inputLabel(const std::string& port) { return "input '" + port + "'"; }
inline std::string optionLabel(const std::string& name) { return "option '" + name + "'"; }

// The names of a spec's ports or options, for "did you mean" (made only when reporting).
template <class Named>
inline std::vector<std::string> namesOf(const std::vector<Named>& list) {
  std::vector<std::string> names;
  for (const auto& x : list) names.push_back(x.name);
  return names;
}

inline std::string describeSource(const InputSource& s) {
  switch (s.kind) {
    case InputSource::Kind::NodeOutput: return "'" + s.name + "." + s.port + "'";
    case InputSource::Kind::Parameter: return "'$" + s.name + "'";
    case InputSource::Kind::Literal: return "the literal";
  }
  return "?";
}

inline Value literalValue(const std::vector<double>& xs) {
  Value v = Value::ofType(floatVector(static_cast<int>(xs.size())));
  for (size_t i = 0; i < xs.size(); ++i) v[static_cast<int>(i)] = xs[i];
  return v;
}

// What the resolvers of one graph and of every subgraph instance in it share.
struct SharedState {
  std::string topDirectory;            // the top-level graph's folder: texture paths end relative to it
  std::set<std::string> texturesCounted;  // real paths of PNG textures
  long long textureTexels = 0;
  // One node type per imported function graph and name it is imported under (two graphs
  // may import one file under two names), made on its first instance.
  std::map<std::pair<const Graph*, std::string>, std::unique_ptr<NodeSpec>> instanceSpecs;
  NodeOutputValues* nodeOutputs = nullptr;
  // The top-level graph's options for nodes inside instances, and the subgraphs copied to
  // carry them (a deque: the resolvers hold references to them).
  const std::vector<InstanceOption>* instanceOptions = nullptr;
  std::deque<Graph> instanceGraphs;
  // A node type's options when a node declares none: completed and parsed once per type
  // (most nodes of a large graph are math nodes that declare no options).
  std::unordered_map<const NodeSpec*, SharedOptions> defaultOptions;
  // Options that nodes declare, and constants, each held once per distinct value.
  OptionsTable options;
  ConstantTable constants;
  // The inlined size of the ops made so far (kMaxInlinedBytes): the first `opsMeasured`
  // ops measured. loadImports predicted it from the import tree; this holds the ops that an
  // expanding node makes (a formula is one node there) to the same budget.
  std::size_t opsMeasured = 0;
  std::size_t inlinedBytes = 0;
  bool overBudget = false;
  int fileNodes = 0;  // function nodes made so far: each takes the next namespace
};

// A subgraph instance being inlined: its nodes' ids take the prefix, its parameters read
// the instance's inputs, its interface outputs are what the instance's outputs are.
struct InstanceScope {
  std::string idPrefix;  // "foam/" (nested: "shore/foam/")
  std::unordered_map<std::string, ValueRef> inputs;
  // The instances this one lies in, innermost first: every op it makes carries them.
  std::shared_ptr<const std::vector<LocatedNote>> chain;
  std::vector<ValueRef> outputs;  // filled: one per interface output
  InstanceBindings options;       // the instance's options: statics read as `$name`, textures as "$name"
};


class Resolver {
 public:
  Resolver(const Graph& g, const Registry& r, Diagnostics& d)
      : graph_(g), registry_(r), diags_(d), program_(ownProgram_), shared_(ownShared_) {}
  Resolver(const Graph& g, const Registry& r, Diagnostics& d, Program& program, SharedState& shared, InstanceScope& scope)
      : graph_(g), registry_(r), diags_(d), program_(program), shared_(shared), scope_(&scope) {}

  std::optional<Program> run(NodeOutputValues* nodeOutputs = nullptr);
  // A subgraph instance: its ops go into the shared program. False after reporting.
  bool runInstance();

 private:
  // resolve.cpp: the steps in order; parameters, outputs and interface outputs
  void resolveBody();
  void bindOwnOptions();
  void useOptions(const InstanceBindings& bound);
  void collectParameters();
  void indexNodes();
  void checkImportNames();
  std::optional<ValueRef> sourceRef(const InputSource& s, int node = -1, int port = -1);
  void listNodeOutputs(NodeOutputValues& out) const;
  void resolveInterfaceOutputs(std::vector<ValueRef>& values);
  void resolveOutputs();

  // resolve_node_types.cpp: each node's type, options and textures
  std::string acceptedTexture(const TextureFile& texture);
  const NodeSpec* instanceSpec(const Import& im);
  void lookUpSpecs();
  bool readsInterfaceTexture(const OptionSpec& spec, const NodeOption& opt, const Node& n);
  void reportOptionProblem(const Node& n, const NodeSpec& spec);
  static nlohmann::json declaredOptions(const Node& node, const NodeSpec& spec);
  static std::string decodedTexture(const TextureFile& texture);
  std::string chargeTextureBudget(const TextureFile& texture);

  // resolve_presets.cpp: the presets' node options
  void checkPresetOptions();
  void checkPresetInstanceOption(const Preset& preset, const PresetValue& v, const Import& im);
  const OptionSpec* presetOptionSpec(const Preset& preset, const PresetValue& v, const NodeSpec& spec,
                                     const std::string& nodeId);
  void checkPresetOptionValue(const Preset& preset, const PresetValue& v, const OptionSpec& option,
                              const std::string& nodeId, const std::string& directory);
  void checkInstancePresetOption(const Preset& preset, const PresetValue& v);

  // resolve_order.cpp: the nodes in data-flow order, cycles named
  std::vector<int> topologicalOrder();
  void reportCycles(const std::vector<bool>& done);
  void reportCycle(std::vector<int> cycle);

  // resolve_ops.cpp: one op per node, typed; expanding nodes
  void buildOps(const std::vector<int>& order);
  bool withinInlinedBudget(const Node& node);
  void expandNode(int ni, const Op& op, const std::vector<Type>& sourceTypes, const std::vector<const NodeInput*>& given);
  std::optional<std::vector<ValueRef>> convertedInputs(const Node& node, const Op& op, const std::vector<PortSpec>& ports,
                                                       const std::vector<Type>& sourceTypes,
                                                       const std::vector<const NodeInput*>& given);
  ValueRef splat(const ValueRef& v, Type want, const Node& node);
  SourceRef optionWhere(const Node& node, std::string_view option, size_t offset);
  bool typeOp(Op& op, const Node& node, const std::vector<Type>& sourceTypes,
              const std::vector<const NodeInput*>& given);
  static std::string sourceName(const NodeInput* given);
  void mismatch(const Node& node, const NodeInput* given, const std::string& port, const std::string& message);

  // resolve_instances.cpp: subgraph instances inlined
  void inlineInstance(int ni, const Op& op, const std::vector<Type>& sourceTypes,
                      const std::vector<const NodeInput*>& given);
  const Graph& withInstanceOptions(const Graph& sub, const std::string& prefix);
  static bool fitsRange(const Value& v, const Parameter& p);
  static std::string rangeText(const Parameter& p);
  void retargetTexturePaths(const NodeSpec& spec, nlohmann::json& options) const;
  bool bindInterfaceTextures(const NodeSpec& spec, const Node& node, nlohmann::json& options);

  // Node i's ports: its type's, or (an expression's) those its options give.
  const std::vector<PortSpec>& inputsOf(size_t i) const { return ports_[i] ? ports_[i]->inputs : specs_[i]->inputs; }

  const std::vector<PortSpec>& outputsOf(size_t i) const { return ports_[i] ? ports_[i]->outputs : specs_[i]->outputs; }

  // Checks a reference to another node and returns its index, or -1 after reporting.
  // `label()` makes the diagnostic's label, only when there is one to report. `port`, when
  // given, receives the index of the output it names (-1 when the node's type is unknown).
  template <typename Label>
  int referencedNode(const InputSource& s, const std::string& user, const Label& label, int* port = nullptr) {
    int found = nodeIndex_.find(s.name);
    if (found < 0) {
      if (!nodeIds_) {  // indexed once, on the first dangling reference
        std::vector<std::string> ids;
        for (const auto& n : graph_.nodes) ids.push_back(n.id);
        nodeIds_.emplace(std::move(ids));
      }
      diags_.error(DiagCode::DanglingReference, s.where,
                   "no node with id '" + s.name + "'" + nodeIds_->didYouMean(s.name), user, label());
      return -1;
    }
    const NodeSpec* spec = specs_[static_cast<size_t>(found)];
    const int outputPort = spec ? portIndex(outputsOf(static_cast<size_t>(found)), s.port) : -1;
    if (port) *port = outputPort;
    if (spec && outputPort < 0) {
      std::vector<std::string> names = namesOf(outputsOf(static_cast<size_t>(found)));
      std::string outs;
      for (const auto& name : names) outs += (outs.empty() ? "" : ", ") + name;
      diags_.error(DiagCode::UnknownOutputPort, s.where,
                   "node '" + s.name + "' (" + spec->type + ") has no output '" + s.port +
                       "'; its outputs are: " + outs + didYouMean(s.port, names),
                   user, label());
      return -1;
    }
    return found;
  }

  template <typename Label>
  bool existsForItsInputs(const ValueRef& ref, const InputSource& s, const std::string& user, const Label& label) {
    if (ref.kind != ValueRef::Kind::Op || program_.typeOf(ref) != Type::Invalid) return true;
    const Op& op = program_.ops[static_cast<size_t>(ref.index)];
    std::string inputs;
    for (Type t : op.inputTypes) inputs += (inputs.empty() ? "" : ", ") + std::string(typeName(t));
    diags_.error(DiagCode::UnknownOutputPort, s.where,
                 "node '" + s.name + "' (" + op.spec->type + ") has no output '" + s.port + "' for its input type " + inputs,
                 user, label());
    return false;
  }

  // A colour literal or default (sRGB-authored) as the linear constant the nodes receive.
  ValueRef linearised(const ValueRef& srgb) { return ValueRef::constant_(shared_.constants.intern(linearColor(srgb.constant()))); }

  // A node's id in the program: inside an instance, prefixed with the instance's path.
  std::string idOf(const Node& node) const { return prefixed(node.id); }

  std::string prefixed(const std::string& id) const { return scope_ ? scope_->idPrefix + id : id; }

  SourceRef portWhere(const Node& node, const NodeInput* given) const {
    return given ? given->source.where : node.where;
  }

  const Graph& graph_;
  const Registry& registry_;
  Diagnostics& diags_;
  Program ownProgram_;       // the top-level resolver's; an instance's resolver adds to its parent's
  Program& program_;
  SharedState ownShared_;
  SharedState& shared_;
  InstanceScope* scope_ = nullptr;  // set: resolving a subgraph instance
  InstanceBindings ownOptions_;     // a function graph compiled on its own: its options' defaults
  const InstanceBindings* options_ = nullptr;  // the options in force (the scope's or ownOptions_)
  std::string directory_;           // this graph file's folder (its texture paths are relative to it)
  std::vector<const NodeSpec*> specs_;
  std::vector<const Import*> instanceOf_;  // by node index: the import it instances, or null
  // Keyed by views of the graph's own strings (the graph outlives the resolver): a 10,000-node
  // graph would otherwise copy every id once more.
  IdIndex nodeIndex_;
  std::unordered_map<std::string_view, ValueRef> paramValue_;  // what `$name` reads
  std::optional<NameSuggester> nodeIds_, parameterNames_;  // made on the first unknown name
  std::vector<int> opOfNode_;  // by node index: its op, or -1
  // By node index, for a node that expanded into ops: the value of each output port.
  std::vector<std::vector<ValueRef>> expandedOutputs_;
  // By node index, for a node whose ports follow from its options: those ports (null: the type's).
  std::vector<std::unique_ptr<NodePorts>> ports_;
  std::optional<std::vector<std::string_view>> sourceLines_;  // the graph file's, split on first use
  // The graph's edges, by e = inputBase_[i] + k for node i's inputs[k], each name looked up
  // once (lookUpSpecs, topologicalOrder) and read by index in buildOps: the port of the
  // node's own inputs it connects (inputPort_, -1: none), the node it reads (inputNode_, -1:
  // not a node output) and that node's output port (inputSourcePort_, -1: not known).
  // Before, buildOps compared each port name again and read the source's op for its spec:
  // on a 10,000-node graph a cache miss per input into an array of ops far from the node.
  std::vector<size_t> inputBase_;
  std::vector<int> inputPort_;
  std::vector<int> inputNode_;
  std::vector<int> inputSourcePort_;
  std::vector<Type> sourceTypes_;         // buildOps: the node's input types
  std::vector<const NodeInput*> given_;   // buildOps: the node's written inputs by port
};

}  // namespace wg::resolving
