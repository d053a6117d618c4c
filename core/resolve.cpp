#include "core/resolve.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include <filesystem>

#include "core/color_parameters.h"
#include "core/derive.h"
#include "core/expand.h"
#include "core/file_node.h"
#include "core/graph_imports.h"
#include "core/graph_node_type.h"
#include "core/id_index.h"
#include "core/instance_options.h"
#include "core/json_string_columns.h"
#include "core/load_limits.h"
#include "core/number_format.h"
#include "core/interned_values.h"
#include "core/node_options.h"
#include "core/png_decode.h"
#include "core/port_typing.h"
#include "core/suggest.h"
#include "core/text_lines.h"
#include "core/texture_check.h"

namespace wg {
namespace {

std::string inputLabel(const std::string& port) { return "input '" + port + "'"; }
std::string optionLabel(const std::string& name) { return "option '" + name + "'"; }

// The names of a spec's ports or options, for "did you mean" (made only when reporting).
template <class Named>
std::vector<std::string> namesOf(const std::vector<Named>& list) {
  std::vector<std::string> names;
  for (const auto& x : list) names.push_back(x.name);
  return names;
}

std::string describeSource(const InputSource& s) {
  switch (s.kind) {
    case InputSource::Kind::NodeOutput: return "'" + s.name + "." + s.port + "'";
    case InputSource::Kind::Parameter: return "'$" + s.name + "'";
    case InputSource::Kind::Literal: return "the literal";
  }
  return "?";
}

Value literalValue(const std::vector<double>& xs) {
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

  std::optional<Program> run(NodeOutputValues* nodeOutputs = nullptr) {
    size_t errorsBefore = diags_.errorCount();
    program_.graphName = graph_.name;
    program_.description = graph_.description;
    program_.view = graph_.view.value_or(ViewTransform{});
    program_.file = graph_.file;
    program_.directory = std::filesystem::path(graph_.file).parent_path().string();
    program_.totalNodes = static_cast<int>(graph_.nodes.size());
    shared_.topDirectory = program_.directory;
    std::vector<std::string> files = graphFilesRead(graph_);
    for (size_t k = 1; k < files.size(); ++k) {
      namespace fs = std::filesystem;
      fs::path top(program_.folder());
      program_.importedFiles.push_back(fs::path(files[k]).lexically_normal().lexically_relative(top.lexically_normal()).generic_string());
    }
    shared_.nodeOutputs = nodeOutputs;
    shared_.instanceOptions = &graph_.instanceOptions;
    collectParameters();
    if (graph_.interface && !graph_.interface->options.empty()) bindOwnOptions();
    resolveBody();
    if (diags_.errorCount() > errorsBefore) return std::nullopt;
    resolveOutputs();
    // A function graph compiled on its own keeps its interface's promises too.
    std::vector<ValueRef> interfaceValues;
    if (graph_.interface) resolveInterfaceOutputs(interfaceValues);
    if (diags_.errorCount() > errorsBefore) return std::nullopt;
    if (nodeOutputs) listNodeOutputs(*nodeOutputs);
    return std::move(program_);
  }

  // A subgraph instance: its ops go into the shared program. False after reporting.
  bool runInstance() {
    size_t errorsBefore = diags_.errorCount();
    program_.totalNodes += static_cast<int>(graph_.nodes.size());
    for (const auto& p : graph_.parameters) paramValue_.emplace(p.name, scope_->inputs.at(p.name));
    useOptions(scope_->options);
    resolveBody();
    if (diags_.errorCount() > errorsBefore) return false;
    resolveInterfaceOutputs(scope_->outputs);
    if (diags_.errorCount() > errorsBefore) return false;
    if (shared_.nodeOutputs) listNodeOutputs(*shared_.nodeOutputs);
    return true;
  }

 private:
  void resolveBody() {
    size_t errorsBefore = diags_.errorCount();
    directory_ = std::filesystem::path(graph_.file).parent_path().string();
    checkImportNames();
    indexNodes();
    lookUpSpecs();
    if (!scope_) checkPresetOptions();
    std::vector<int> order = topologicalOrder();
    if (diags_.errorCount() > errorsBefore) return;
    buildOps(order);
  }

  // A function graph compiled on its own: its options take their defaults.
  void bindOwnOptions() {
    InstanceOptionRequest request{*graph_.interface, graph_.file};
    request.topDirectory = shared_.topDirectory;
    request.accept = [this](const TextureFile& t) { return acceptedTexture(t); };
    if (auto bound = bindInstanceOptions(request, diags_)) {
      ownOptions_ = std::move(*bound);
      useOptions(ownOptions_);
    }
  }

  // The options' static values are read as `$name`, folded like a literal input.
  void useOptions(const InstanceBindings& bound) {
    options_ = &bound;
    for (const auto& [name, value] : bound.statics)
      paramValue_.emplace(name, ValueRef::constant_(shared_.constants.intern(Value::scalar(value))));
  }

  std::string acceptedTexture(const TextureFile& texture) {
    std::string why = chargeTextureBudget(texture);
    return why.empty() ? decodedTexture(texture) : why;
  }

  void collectParameters() {
    for (const auto& p : graph_.parameters) {
      ProgramParameter pp;
      pp.name = p.name;
      pp.type = p.type;
      pp.defaultValue = literalValue(p.defaultValue);
      if (pp.defaultValue.type != p.type) pp.defaultValue = Value::ofType(p.type, p.defaultValue.empty() ? 0 : p.defaultValue[0]);
      pp.min = p.min;
      pp.max = p.max;
      pp.hint = p.hint;
      pp.description = p.description;
      pp.isStatic = p.isStatic;
      pp.where = p.where;
      paramValue_[p.name] = ValueRef::param(static_cast<int>(program_.parameters.size()));
      program_.parameters.push_back(std::move(pp));
    }
  }

  void indexNodes() {
    nodeIndex_.reserve(graph_.nodes.size());
    for (size_t i = 0; i < graph_.nodes.size(); ++i) {
      const Node& n = graph_.nodes[i];
      auto [firstIndex, inserted] = nodeIndex_.emplace(n.id, static_cast<int>(i));
      if (!inserted) {
        const Node& first = graph_.nodes[static_cast<size_t>(firstIndex)];
        auto& d = diags_.error(DiagCode::DuplicateNodeId, n.idWhere, "duplicate node id '" + n.id + "'", n.id);
        d.notes.push_back("first defined at " + std::to_string(first.idWhere.line) + ":" +
                          std::to_string(first.idWhere.col));
      }
    }
  }

  // Every preset's node options, whichever preset is applied: each names an option of the
  // node's type and a value it accepts, reported at the preset's member. A value written
  // onto its node by applyPreset (same position) is checked there instead, once.
  void checkPresetOptions() {
    for (const Preset& preset : graph_.presets)
      for (const PresetValue& v : preset.values) {
        if (!v.isOption()) continue;
        if (v.node.find('/') != std::string::npos) {
          checkInstancePresetOption(preset, v);
          continue;
        }
        int ni = nodeIndex_.find(v.node);
        if (ni < 0) continue;  // reported by the loader
        const Node& node = graph_.nodes[static_cast<size_t>(ni)];
        const NodeSpec* spec = specs_[static_cast<size_t>(ni)];
        if (!spec) continue;  // an unknown type, reported
        bool applied = std::any_of(node.options.begin(), node.options.end(),
                                   [&](const NodeOption& o) { return o.name == v.option && o.where == v.where; });
        if (applied) continue;
        if (instanceOf_[static_cast<size_t>(ni)]) {
          checkPresetInstanceOption(preset, v, *instanceOf_[static_cast<size_t>(ni)]);
          continue;
        }
        if (const OptionSpec* option = presetOptionSpec(preset, v, *spec, node.id))
          checkPresetOptionValue(preset, v, *option, node.id, directory_);
      }
  }

  // A preset member "instance.option" sets an option of the instance's interface: one it
  // declares, a value it accepts (a texture's file is checked when the preset is applied).
  void checkPresetInstanceOption(const Preset& preset, const PresetValue& v, const Import& im) {
    const std::string label = optionLabel(v.option);
    for (const auto& o : im.graph->interface->options) {
      if (o.name != v.option) continue;
      if (std::string why = interfaceOptionValueProblem(o, v.optionValue); !why.empty())
        diags_.error(DiagCode::InstanceOptionValue, v.where, "preset '" + preset.name + "': " + label + " " + why, v.node,
                     label);
      return;
    }
    diags_.error(DiagCode::InstanceOptionUnknown, v.keyWhere,
                 "preset '" + preset.name + "': the interface of '" + im.name + "' declares no " + label, v.node, label);
  }

  // The option of `spec` that preset member `v` sets on node `nodeId`; null, reported,
  // when the type has none of that name.
  const OptionSpec* presetOptionSpec(const Preset& preset, const PresetValue& v, const NodeSpec& spec,
                                     const std::string& nodeId) {
    int oi = spec.optionIndex(v.option);
    if (oi >= 0) return &spec.options[static_cast<size_t>(oi)];
    diags_.error(DiagCode::UnknownOption, v.keyWhere,
                 "preset '" + preset.name + "': node type '" + spec.type + "' has no option '" + v.option + "'" +
                     didYouMean(v.option, namesOf(spec.options)),
                 nodeId, optionLabel(v.option));
    return nullptr;
  }

  // The value preset member `v` gives `option`, checked as an option written on the node
  // (texture paths relative to `directory`, the file of the graph that holds the node).
  void checkPresetOptionValue(const Preset& preset, const PresetValue& v, const OptionSpec& option,
                              const std::string& nodeId, const std::string& directory) {
    // The path and header only: the file is decoded, within that configuration's texture
    // budget, when compile builds the graph with the preset applied (checkOtherPresets).
    std::string why = checkOption(option, v.optionValue, directory, nullptr);
    if (!why.empty())
      diags_.error(DiagCode::InvalidOption, v.where, "preset '" + preset.name + "': option '" + v.option + "' " + why,
                   nodeId, optionLabel(v.option));
  }

  // A preset member "instance/node.option": each step of the path is a node of the graph
  // before it (the first of this graph; the others of the subgraph the step before
  // instances), the last a registered node type that has the option, and the value one it
  // accepts. A value applyPreset has handed to the instance is checked when the instance is
  // inlined, as an option written on that node.
  void checkInstancePresetOption(const Preset& preset, const PresetValue& v) {
    std::string label = "preset '" + preset.name + "'";
    const Graph* g = &graph_;
    const Node* node = nullptr;
    std::string path;
    for (size_t start = 0;;) {
      size_t slash = v.node.find('/', start);
      std::string id = v.node.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
      node = g->findNode(id);
      path += (path.empty() ? "" : "/") + id;
      if (!node) {
        if (g != &graph_)  // the first step is the loader's to report
          diags_.error(DiagCode::DanglingReference, v.keyWhere,
                       label + " sets an option of node '" + v.node + "', but '" + g->name + "' has no node '" + id + "'");
        return;
      }
      if (slash == std::string::npos) break;
      GraphNodeType type = nodeTypeOf(*g, registry_, node->type);
      if (!type.import || !type.import->graph) {
        if (type.import) return;  // its import did not load: reported
        diags_.error(DiagCode::DanglingReference, v.keyWhere,
                     label + " sets an option of node '" + v.node + "', but '" + path + "' is a '" + node->type +
                         "' node, not a subgraph instance");
        return;
      }
      g = type.import->graph.get();
      start = slash + 1;
    }
    const NodeSpec* spec = registry_.find(node->type);
    if (!spec) {
      if (nodeTypeOf(*g, registry_, node->type).import)
        diags_.error(DiagCode::UnknownOption, v.keyWhere,
                     label + ": '" + v.node + "' is a subgraph instance, whose options are its interface's (set as \"instance.option\")");
      return;  // an unknown type, reported where the subgraph is checked
    }
    bool applied = std::any_of(graph_.instanceOptions.begin(), graph_.instanceOptions.end(),
                               [&](const InstanceOption& o) { return o.node == v.node && o.option.where == v.where; });
    const OptionSpec* option = presetOptionSpec(preset, v, *spec, v.node);
    if (!option || applied) return;
    checkPresetOptionValue(preset, v, *option, v.node, std::filesystem::path(g->file).parent_path().string());
  }

  // An import's name becomes a node type here, so it may not be one already.
  void checkImportNames() {
    for (const auto& im : graph_.imports)
      if (registry_.find(im.name))
        diags_.error(DiagCode::ImportShadowsNode, im.where,
                     "import name '" + im.name + "' is already a node type; choose another name for '" + im.path + "'");
  }

  // The node type an imported function graph stands for: its parameters are the inputs
  // (a parameter's default is the input's), its interface outputs the outputs.
  const NodeSpec* instanceSpec(const Import& im) {
    auto& slot = shared_.instanceSpecs[{im.graph.get(), im.name}];
    if (!slot) {
      auto spec = std::make_unique<NodeSpec>();
      spec->type = im.name;
      spec->family = "subgraph";
      spec->summary = im.graph->interface->description;
      NodePorts ports = interfacePorts(*im.graph);
      spec->inputs = std::move(ports.inputs);
      spec->outputs = std::move(ports.outputs);
      slot = std::move(spec);
    }
    return slot.get();
  }

  void lookUpSpecs() {
    specs_.assign(graph_.nodes.size(), nullptr);
    ports_.resize(graph_.nodes.size());
    instanceOf_.assign(graph_.nodes.size(), nullptr);
    std::optional<NameSuggester> types;  // made on the first unknown type
    for (size_t i = 0; i < graph_.nodes.size(); ++i) {
      const Node& n = graph_.nodes[i];
      GraphNodeType type = nodeTypeOf(graph_, registry_, n.type);
      const NodeSpec* spec = type.spec;
      if (!spec && !type.import)
        if (const FileNodeMaker* make = registry_.fileNodeType(n.type)) {
          // Its ports come from its file: a file that does not pass is reported, and the
          // node is left out like an unknown type.
          auto made = (*make)({n, directory_, shared_.fileNodes++}, diags_);
          if (!made) continue;
          spec = keepFileNode(program_, std::move(*made));
        }
      if (type.import && type.import->graph) {
        spec = instanceSpec(*type.import);
        instanceOf_[i] = type.import;
        --program_.totalNodes;  // it stands for the nodes it inlines, which count instead
      }
      if (!spec) {
        if (!types) {
          std::vector<std::string> typeNames;
          for (const NodeSpec* s : registry_.all()) typeNames.push_back(s->type);
          for (const auto& im : graph_.imports) typeNames.push_back(im.name);
          types.emplace(std::move(typeNames));
        }
        diags_.error(DiagCode::UnknownNodeType, n.typeWhere,
                     "unknown node type '" + n.type + "'" + types->didYouMean(n.type), n.id);
        continue;
      }
      bool optionsValid = true;
      for (const auto& opt : n.options) {
        if (instanceOf_[i]) break;  // an instance's options are its interface's: bound when it is inlined
        int oi = spec->optionIndex(opt.name);
        if (oi < 0) {
          diags_.error(DiagCode::UnknownOption, opt.keyWhere,
                       "node type '" + spec->type + "' has no option '" + opt.name + "'" +
                           didYouMean(opt.name, namesOf(spec->options)),
                       n.id, optionLabel(opt.name));
          continue;
        }
        if (readsInterfaceTexture(spec->options[static_cast<size_t>(oi)], opt, n)) continue;
        TextureFile texture;
        std::string why = checkOption(spec->options[static_cast<size_t>(oi)], opt.value, directory_, &texture);
        if (why.empty()) why = chargeTextureBudget(texture);
        if (why.empty()) why = decodedTexture(texture);
        if (!why.empty()) {
          diags_.error(DiagCode::InvalidOption, opt.where, "option '" + opt.name + "' " + why, n.id,
                       optionLabel(opt.name));
          optionsValid = false;
        }
      }
      if (optionsValid && spec->checkOptions) reportOptionProblem(n, *spec);
      if (spec->portsFor) {
        // Its ports follow from its options: without valid options there are none to check
        // against (the options are reported), and the node is left out like an unknown type.
        if (!optionsValid) continue;
        ports_[i] = std::make_unique<NodePorts>(
            spec->portsFor(*parseOptions(*spec, completeOptions(*spec, declaredOptions(n, *spec)))));
      }
      specs_[i] = spec;
      const std::vector<PortSpec>& inputs = inputsOf(i);
      for (const auto& in : n.inputs) {
        int pi = portIndex(inputs, in.port);
        // A derived input is the node's own (NodeSpec::derive): not a port of the file.
        if (pi >= 0 && inputs[static_cast<size_t>(pi)].derived)
          diags_.error(DiagCode::UnknownInputPort, in.keyWhere,
                       "input '" + in.port + "' of node type '" + spec->type +
                           "' is computed by the node itself and cannot be connected",
                       n.id, inputLabel(in.port));
        else if (pi < 0)
          diags_.error(DiagCode::UnknownInputPort, in.keyWhere,
                       "node type '" + spec->type + "' has no input '" + in.port + "'" +
                           didYouMean(in.port, namesOf(inputs)),
                       n.id, inputLabel(in.port));
      }
    }
  }

  // A texture option written "$name" samples the interface texture `name` (checked where
  // it was chosen); true when `opt` is one, after reporting one that is not declared.
  bool readsInterfaceTexture(const OptionSpec& spec, const NodeOption& opt, const Node& n) {
    if (spec.kind != OptionSpec::Kind::Texture) return false;
    auto name = interfaceTextureReference(opt.value);
    if (!name) return false;
    if (!options_ || !options_->textures.count(*name))
      diags_.error(DiagCode::InstanceOptionUnknown, opt.where,
                   "option '" + opt.name + "' reads the interface texture '" + std::string(*name) + "', but " +
                       (graph_.interface ? "the interface declares no texture option of that name"
                                         : "the graph has no interface (only a function graph's nodes read one)"),
                   idOf(n), optionLabel(opt.name));
    return true;
  }

  // Node i's ports: its type's, or (an expression's) those its options give.
  const std::vector<PortSpec>& inputsOf(size_t i) const { return ports_[i] ? ports_[i]->inputs : specs_[i]->inputs; }
  const std::vector<PortSpec>& outputsOf(size_t i) const { return ports_[i] ? ports_[i]->outputs : specs_[i]->outputs; }

  // Options each valid alone but meaningless together (NodeSpec::checkOptions), reported
  // at the option blamed, or at the node when the file leaves that option at its default.
  void reportOptionProblem(const Node& n, const NodeSpec& spec) {
    auto problem = spec.checkOptions(*parseOptions(spec, completeOptions(spec, declaredOptions(n, spec))));
    if (!problem) return;
    SourceRef at = n.where;
    for (const auto& o : n.options)
      if (o.name == problem->option) at = o.where;
    diags_.error(DiagCode::InvalidOption, at, "option '" + problem->option + "' " + problem->why, n.id,
                 optionLabel(problem->option));
  }

  // The options a node writes that its type declares (the others are reported).
  static nlohmann::json declaredOptions(const Node& node, const NodeSpec& spec) {
    nlohmann::json written = writtenOptions(node);
    for (const auto& o : node.options)
      if (spec.optionIndex(o.name) < 0) written.erase(o.name);
    return written;
  }

  // A PNG file whose header passed must decode too (a broken zlib stream, too few
  // pixels): found by validate, not first by render. After the budget, so a file the
  // budget refuses is not decoded. Builtin textures (no file) pass.
  static std::string decodedTexture(const TextureFile& texture) {
    if (texture.realPath.empty()) return "";
    std::string why = checkPngDecodes(texture.realPath);
    return why.empty() ? "" : "is not usable: cannot decode texture '" + texture.realPath + "': " + why;
  }

  // All of a graph's PNG textures together stay within kMaxGraphTextureTexels (each file
  // counted once, however many nodes sample it): "" or why the one that overflows it is refused.
  std::string chargeTextureBudget(const TextureFile& texture) {
    if (texture.realPath.empty() || !shared_.texturesCounted.insert(texture.realPath).second) return "";
    shared_.textureTexels += texture.width * texture.height;
    if (shared_.textureTexels <= kMaxGraphTextureTexels) return "";
    return "is not usable: the graph's PNG textures would hold " + std::to_string(shared_.textureTexels) +
           " texels together; the limit per graph is " + std::to_string(kMaxGraphTextureTexels);
  }

  // Checks a reference to another node and returns its index, or -1 after reporting.
  // `label()` makes the diagnostic's label, only when there is one to report.
  template <typename Label>
  int referencedNode(const InputSource& s, const std::string& user, const Label& label) {
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
    if (spec && portIndex(outputsOf(static_cast<size_t>(found)), s.port) < 0) {
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

  // Kahn's algorithm over node references: iterative, so a 100,000-node chain needs no
  // deep recursion. Nodes left over lie on or behind a cycle; each cycle is named.
  // The edges live in flat arrays (inputNode_ for dependencies, userBase/users for the
  // reverse), not a vector per node: two allocations per node on a large graph otherwise.
  std::vector<int> topologicalOrder() {
    size_t n = graph_.nodes.size();
    std::vector<int> pending(n, 0);
    inputBase_.assign(n + 1, 0);
    for (size_t i = 0; i < n; ++i) inputBase_[i + 1] = inputBase_[i] + graph_.nodes[i].inputs.size();
    inputNode_.assign(inputBase_[n], -1);
    for (size_t i = 0; i < n; ++i) {
      const Node& node = graph_.nodes[i];
      for (size_t k = 0; k < node.inputs.size(); ++k) {
        const NodeInput& in = node.inputs[k];
        if (in.source.kind == InputSource::Kind::Parameter) {
          if (!paramValue_.count(in.source.name)) {
            if (!parameterNames_) {
              std::vector<std::string> names;
              for (const auto& p : graph_.parameters) names.push_back(p.name);
              parameterNames_.emplace(std::move(names));
            }
            diags_.error(DiagCode::UnknownParameter, in.source.where,
                         "no parameter named '" + in.source.name + "'" +
                             parameterNames_->didYouMean(in.source.name),
                         node.id, inputLabel(in.port));
          }
          continue;
        }
        if (in.source.kind != InputSource::Kind::NodeOutput) continue;
        int dep = referencedNode(in.source, node.id, [&] { return inputLabel(in.port); });
        if (dep < 0) continue;
        inputNode_[inputBase_[i] + k] = dep;
        if (static_cast<size_t>(dep) == i) {
          diags_.error(DiagCode::Cycle, in.source.where, "node '" + node.id + "' refers to itself", node.id,
                       inputLabel(in.port));
          continue;
        }
        ++pending[i];
      }
    }
    // Each node's users, in the order of (user, input): counted, then placed.
    std::vector<size_t> userBase(n + 1, 0);
    for (size_t i = 0; i < n; ++i)
      for (size_t e = inputBase_[i]; e < inputBase_[i + 1]; ++e)
        if (int d = inputNode_[e]; d >= 0 && static_cast<size_t>(d) != i) ++userBase[static_cast<size_t>(d) + 1];
    for (size_t i = 0; i < n; ++i) userBase[i + 1] += userBase[i];
    std::vector<int> users(userBase[n]);
    std::vector<size_t> fill(userBase.begin(), userBase.end() - 1);
    for (size_t i = 0; i < n; ++i)
      for (size_t e = inputBase_[i]; e < inputBase_[i + 1]; ++e)
        if (int d = inputNode_[e]; d >= 0 && static_cast<size_t>(d) != i) users[fill[static_cast<size_t>(d)]++] = static_cast<int>(i);
    std::vector<int> order;
    order.reserve(n);
    std::vector<int> ready;
    for (size_t i = n; i-- > 0;)
      if (pending[i] == 0) ready.push_back(static_cast<int>(i));
    // Pop the lowest index first so the order follows the file where it can.
    std::vector<bool> done(n, false);
    while (!ready.empty()) {
      int i = ready.back();
      ready.pop_back();
      order.push_back(i);
      done[static_cast<size_t>(i)] = true;
      for (size_t e = userBase[static_cast<size_t>(i)]; e < userBase[static_cast<size_t>(i) + 1]; ++e)
        if (--pending[static_cast<size_t>(users[e])] == 0) ready.push_back(users[e]);
    }
    if (order.size() < n) reportCycles(done);
    return order;
  }

  // Every node left unfinished lies on a cycle or behind one. Walks dependencies among
  // them from each node not yet walked: a walk that comes back to a node of its own closes
  // a new cycle (reported); one that reaches a node of an earlier walk leads into a cycle
  // already reported. Each node is walked once, so disjoint cycles are each named in
  // linear time.
  // A node's dependencies are its inputs' nodes (inputNode_), a reference to itself aside.
  void reportCycles(const std::vector<bool>& done) {
    std::vector<size_t> walkOf(done.size(), 0);  // 0: not walked; else the walk's number
    std::vector<size_t> placeInWalk(done.size(), 0);
    size_t walkNumber = 0;
    for (size_t start = 0; start < done.size(); ++start) {
      if (done[start] || walkOf[start] != 0) continue;
      ++walkNumber;
      std::vector<int> walk;
      int cur = static_cast<int>(start);
      bool stuck = false;
      while (walkOf[static_cast<size_t>(cur)] == 0) {
        walkOf[static_cast<size_t>(cur)] = walkNumber;
        placeInWalk[static_cast<size_t>(cur)] = walk.size();
        walk.push_back(cur);
        int next = -1;
        for (size_t e = inputBase_[static_cast<size_t>(cur)]; e < inputBase_[static_cast<size_t>(cur) + 1]; ++e)
          if (int d = inputNode_[e]; d >= 0 && d != cur && !done[static_cast<size_t>(d)]) {
            next = d;
            break;
          }
        if (next < 0) {  // cannot happen: an unfinished node has an unfinished dependency
          stuck = true;
          break;
        }
        cur = next;
      }
      if (stuck || walkOf[static_cast<size_t>(cur)] != walkNumber) continue;  // into a known cycle
      reportCycle(std::vector<int>(walk.begin() + static_cast<long>(placeInWalk[static_cast<size_t>(cur)]), walk.end()));
    }
  }

  void reportCycle(std::vector<int> cycle) {
    // Name the cycle in data-flow order, starting at its first node in the file.
    std::reverse(cycle.begin(), cycle.end());
    auto first = std::min_element(cycle.begin(), cycle.end());
    std::rotate(cycle.begin(), first, cycle.end());
    // A long cycle is named by its first and last steps (one line, not a megabyte of ids).
    constexpr size_t kShown = 8;
    std::string path;
    for (size_t k = 0; k < cycle.size(); ++k) {
      if (cycle.size() > 2 * kShown && k == kShown) {
        path += "... (" + std::to_string(cycle.size() - 2 * kShown) + " more nodes) -> ";
        k = cycle.size() - kShown;
      }
      path += "'" + graph_.nodes[static_cast<size_t>(cycle[k])].id + "' -> ";
    }
    path += "'" + graph_.nodes[static_cast<size_t>(cycle.front())].id + "'";
    const Node& at = graph_.nodes[static_cast<size_t>(cycle.front())];
    diags_.error(DiagCode::Cycle, at.where, "the nodes form a cycle: " + path, at.id);
  }

  // The type a source provides, or Invalid after reporting. `node`: the node index of a
  // NodeOutput source when already known (-1: look it up by id).
  std::optional<ValueRef> sourceRef(const InputSource& s, int node = -1) {
    switch (s.kind) {
      case InputSource::Kind::Literal: return ValueRef::constant_(shared_.constants.intern(literalValue(s.literal)));
      case InputSource::Kind::Parameter: {
        auto it = paramValue_.find(s.name);
        if (it == paramValue_.end()) return std::nullopt;
        // A colour parameter is read linearised, through one op made at its first read.
        if (it->second.kind == ValueRef::Kind::Param && isColorHint(program_.parameters[static_cast<size_t>(it->second.index)].hint))
          it->second = appendParameterLinearisation(program_, registry_, it->second.index);
        return it->second;
      }
      case InputSource::Kind::NodeOutput: {
        if (node < 0) {
          node = nodeIndex_.find(s.name);
          if (node < 0) return std::nullopt;
        }
        if (const auto& values = expandedOutputs_[static_cast<size_t>(node)]; !values.empty()) {
          int port = portIndex(outputsOf(static_cast<size_t>(node)), s.port);
          if (port < 0) return std::nullopt;
          return values[static_cast<size_t>(port)];
        }
        int opIndex = opOfNode_[static_cast<size_t>(node)];
        if (opIndex < 0) return std::nullopt;
        const Op& op = program_.ops[static_cast<size_t>(opIndex)];
        int port = op.spec->outputIndex(s.port);
        if (port < 0) return std::nullopt;
        return ValueRef::op(opIndex, port);
      }
    }
    return std::nullopt;
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

  void buildOps(const std::vector<int>& order) {
    opOfNode_.assign(graph_.nodes.size(), -1);
    expandedOutputs_.assign(graph_.nodes.size(), {});
    program_.ops.reserve(order.size());
    const Node* previous = nullptr;  // the node whose ops the budget check measures
    for (int ni : order) {
      const Node& node = graph_.nodes[static_cast<size_t>(ni)];
      const NodeSpec* spec = specs_[static_cast<size_t>(ni)];
      if (previous && !withinInlinedBudget(*previous)) return;
      previous = &node;
      if (!spec) continue;
      Op op;
      op.spec = spec;
      op.nodeId = idOf(node);
      op.where = node.where;
      if (scope_) op.instanceChain = scope_->chain;
      // A node that declares no options takes its type's defaults, completed and parsed once
      // per type. Inside an instance too: texture defaults are builtin names, which
      // retargetTexturePaths leaves as they are (Registry::add checks that).
      if (node.options.empty()) {
        auto [it, fresh] = shared_.defaultOptions.try_emplace(spec);
        if (fresh) it->second = shared_.options.intern(*spec, completeOptions(*spec, nlohmann::json::object()));
        op.sharedOptions = it->second.json;
        op.parsedOptions = it->second.parsed;
      } else {
        nlohmann::json complete = completeOptions(*spec, declaredOptions(node, *spec));
        if (scope_) retargetTexturePaths(*spec, complete);
        if (options_ && !bindInterfaceTextures(*spec, node, complete)) continue;
        // Valid: lookUpSpecs checked each value.
        SharedOptions held = shared_.options.intern(*spec, std::move(complete));
        op.sharedOptions = std::move(held.json);
        op.parsedOptions = std::move(held.parsed);
      }

      const std::vector<PortSpec>& ports = inputsOf(static_cast<size_t>(ni));
      size_t nin = ports.size();
      op.inputs.assign(nin, ValueRef{});
      // Reused from node to node (two allocations per node on a large graph otherwise).
      std::vector<Type>& sourceTypes = sourceTypes_;
      std::vector<const NodeInput*>& given = given_;
      sourceTypes.assign(nin, Type::Invalid);
      given.assign(nin, nullptr);
      bool ok = true;
      for (size_t k = 0; k < node.inputs.size(); ++k) {
        const NodeInput& in = node.inputs[k];
        int pi = portIndex(ports, in.port);
        if (pi < 0) continue;
        given[static_cast<size_t>(pi)] = &in;
        // The referenced node was found by id once, in topologicalOrder.
        auto ref = sourceRef(in.source, inputNode_[inputBase_[static_cast<size_t>(ni)] + k]);
        if (!ref) {
          ok = false;  // already reported (dangling, unknown parameter, bad upstream node)
          continue;
        }
        if (!existsForItsInputs(*ref, in.source, node.id, [&] { return inputLabel(in.port); })) {
          ok = false;
          continue;
        }
        bool colorLiteral = ports[static_cast<size_t>(pi)].color && in.source.kind == InputSource::Kind::Literal;
        // An instance's literals are linearised after their range check (inlineInstance).
        op.inputs[static_cast<size_t>(pi)] = colorLiteral && !instanceOf_[static_cast<size_t>(ni)] ? linearised(*ref) : *ref;
        sourceTypes[static_cast<size_t>(pi)] = program_.typeOf(*ref);
      }
      for (size_t pi = 0; pi < nin; ++pi) {
        if (given[pi]) continue;
        const PortSpec& port = ports[pi];
        if (port.derived) continue;  // filled below by the node's derive
        if (port.defaultValue) {
          op.inputs[pi] = ValueRef::constant_(shared_.constants.intern(*port.defaultValue));
          if (port.color && !instanceOf_[static_cast<size_t>(ni)]) op.inputs[pi] = linearised(op.inputs[pi]);
          sourceTypes[pi] = port.defaultValue->type;
        } else if (port.defaultBuiltin) {
          op.inputs[pi] = ValueRef::builtin(*port.defaultBuiltin);
          sourceTypes[pi] = builtinType(*port.defaultBuiltin);
        } else {
          diags_.error(DiagCode::MissingInput, node.where,
                       "required input '" + port.name + "' of " + spec->type + " is not connected", node.id,
                       inputLabel(port.name));
          ok = false;
        }
      }
      if (!ok) continue;
      if (instanceOf_[static_cast<size_t>(ni)]) {
        inlineInstance(ni, op, sourceTypes, given);
        continue;
      }
      if (spec->expand) {
        expandNode(ni, op, sourceTypes, given);
        continue;
      }
      if (spec->derive) {
        // The node's own inputs must fit before anything is derived from them: a vec4 wired
        // into linearize_depth's vec2 near_far is the node's type error, reported as such,
        // not a derive that cannot type its op (before, an internal error).
        std::vector<Type> declared = sourceTypes;
        for (size_t pi = 0; pi < nin; ++pi)
          if (ports[pi].derived) declared[pi] = ports[pi].type;
        if (!typePorts(*spec, *op.parsedOptions, declared, [](int) { return std::string(); }).error.empty()) {
          typeOp(op, node, declared, given);  // reports the mismatch
          continue;
        }
        size_t firstDerived = program_.ops.size();
        deriveInputs(*spec, *op.parsedOptions, registry_, op.nodeId, op.where, op.inputs, program_);
        for (size_t k = firstDerived; k < program_.ops.size(); ++k) program_.ops[k].instanceChain = op.instanceChain;
        for (size_t pi = 0; pi < nin; ++pi)
          if (ports[pi].derived) sourceTypes[pi] = program_.typeOf(op.inputs[pi]);
      }
      if (!typeOp(op, node, sourceTypes, given)) continue;
      opOfNode_[static_cast<size_t>(ni)] = static_cast<int>(program_.ops.size());
      program_.ops.push_back(std::move(op));
    }
    if (previous) withinInlinedBudget(*previous);
  }

  // Whether the ops made so far keep the inlined-size budget; reports at `node`, the one
  // whose ops passed it, and stops every resolver of the graph.
  bool withinInlinedBudget(const Node& node) {
    if (shared_.overBudget) return false;
    const std::vector<Op>& ops = program_.ops;
    for (size_t k = std::min(shared_.opsMeasured, ops.size()); k < ops.size(); ++k)
      shared_.inlinedBytes += ops[k].nodeId.size() + kInlinedNodeBytes;
    shared_.opsMeasured = ops.size();
    if (shared_.inlinedBytes <= kMaxInlinedBytes && ops.size() <= kMaxOps) return true;
    shared_.overBudget = true;
    const std::string what = ops.size() > kMaxOps
                                 ? "makes more than " + std::to_string(kMaxOps) + " ops, the limit"
                                 : "passes the limit of " + std::to_string(kMaxInlinedBytes / (1024 * 1024)) +
                                       " MiB of inlined size (every op it makes, its full id and " +
                                       std::to_string(kInlinedNodeBytes) + " bytes each) after " +
                                       std::to_string(ops.size()) + " ops";
    diags_.error(DiagCode::LimitExceeded, node.where, "with node '" + idOf(node) + "' the graph " + what, node.id);
    return false;
  }

  void listNodeOutputs(NodeOutputValues& out) const {
    for (size_t i = 0; i < graph_.nodes.size(); ++i) {
      if (!specs_[i]) continue;
      const std::vector<PortSpec>& ports = outputsOf(i);
      std::vector<NodeOutputValue> values;
      if (!expandedOutputs_[i].empty()) {
        for (size_t p = 0; p < ports.size(); ++p)
          values.push_back({ports[p].name, expandedOutputs_[i][p], program_.typeOf(expandedOutputs_[i][p])});
      } else if (int op = opOfNode_[i]; op >= 0) {
        const Op& o = program_.ops[static_cast<size_t>(op)];
        for (size_t p = 0; p < ports.size(); ++p)
          values.push_back({ports[p].name, ValueRef::op(op, static_cast<int>(p)), o.outputTypes[p]});
      } else {
        continue;
      }
      out[idOf(graph_.nodes[i])] = std::move(values);
    }
  }

  // A node that expands into ops (an expression): its inputs, checked against the ports
  // its options declare and converted to their types, go to the spec's expand function;
  // the values it names become the node's outputs.
  void expandNode(int ni, const Op& op, const std::vector<Type>& sourceTypes, const std::vector<const NodeInput*>& given) {
    const Node& node = graph_.nodes[static_cast<size_t>(ni)];
    const NodeSpec& spec = *op.spec;
    NodePorts fixedPorts;  // an expanding type whose ports do not depend on its options
    if (!ports_[static_cast<size_t>(ni)]) fixedPorts = {spec.inputs, spec.outputs};
    const NodePorts& ports = ports_[static_cast<size_t>(ni)] ? *ports_[static_cast<size_t>(ni)] : fixedPorts;
    auto inputs = convertedInputs(node, op, ports.inputs, sourceTypes, given);
    if (!inputs) return;
    size_t firstOp = program_.ops.size();
    ExpandContext ctx{spec, ports, *op.parsedOptions, registry_, idOf(node), node.where, std::move(*inputs), program_,
                      [&](std::string_view option, size_t offset) { return optionWhere(node, option, offset); },
                      {}, DiagCode::InvalidOption, {}, {}, 0};
    size_t opsBefore = program_.ops.size();
    spec.expand(ctx);
    if (!ctx.error.empty()) {
      program_.ops.resize(opsBefore);
      bool atOption = !ctx.errorOption.empty();
      diags_.error(ctx.errorCode, atOption ? optionWhere(node, ctx.errorOption, ctx.errorOffset) : node.where, ctx.error,
                   node.id, atOption ? optionLabel(ctx.errorOption) : "");
      return;
    }
    if (ctx.outputs.size() != ports.outputs.size())
      throw std::logic_error("node type '" + spec.type + "' expanded into " + std::to_string(ctx.outputs.size()) +
                             " outputs for its " + std::to_string(ports.outputs.size()) + " output ports");
    if (scope_)
      for (size_t k = firstOp; k < program_.ops.size(); ++k) program_.ops[k].instanceChain = scope_->chain;
    expandedOutputs_[static_cast<size_t>(ni)] = std::move(ctx.outputs);
  }

  // An expanding node's or an instance's inputs, each of its port's type (a float splats),
  // or nothing after reporting the one that does not fit.
  std::optional<std::vector<ValueRef>> convertedInputs(const Node& node, const Op& op, const std::vector<PortSpec>& ports,
                                                       const std::vector<Type>& sourceTypes,
                                                       const std::vector<const NodeInput*>& given) {
    std::vector<ValueRef> inputs(ports.size());
    for (size_t pi = 0; pi < ports.size(); ++pi) {
      const PortSpec& port = ports[pi];
      if (port.kind != PortKind::Fixed)  // what a port of another kind means is the expansion's to say
        throw std::logic_error("node type '" + op.spec->type + "' gives its input '" + port.name + "' no fixed type");
      if (!implicitlyConvertible(sourceTypes[pi], port.type)) {
        mismatch(node, given[pi], port.name,
                 "input '" + port.name + "' expects " + std::string(typeName(port.type)) + ", but " +
                     sourceName(given[pi]) + " is " + std::string(typeName(sourceTypes[pi])));
        return std::nullopt;
      }
      inputs[pi] = splat(op.inputs[pi], port.type, node);
    }
    return inputs;
  }

  // A subgraph instance: the imported graph's nodes resolved into this program with its
  // parameters reading the instance's inputs, as if written out here. Its faults are
  // reported where they are in its file, with a note naming this instance.
  void inlineInstance(int ni, const Op& op, const std::vector<Type>& sourceTypes,
                      const std::vector<const NodeInput*>& given) {
    const Node& node = graph_.nodes[static_cast<size_t>(ni)];
    const Import& im = *instanceOf_[static_cast<size_t>(ni)];
    const Graph& sub = *im.graph;
    auto inputs = convertedInputs(node, op, op.spec->inputs, sourceTypes, given);
    if (!inputs) return;
    InstanceScope scope;
    scope.idPrefix = idOf(node) + "/";
    auto chain = std::make_shared<std::vector<LocatedNote>>();
    LocatedNote here{node.where, "in instance '" + idOf(node) + "' of '" + im.path + "'", idOf(node)};
    chain->push_back(here);
    if (scope_ && scope_->chain) chain->insert(chain->end(), scope_->chain->begin(), scope_->chain->end());
    scope.chain = std::move(chain);
    bool inRange = true;
    for (size_t pi = 0; pi < sub.parameters.size(); ++pi) {
      const Parameter& p = sub.parameters[pi];
      const ValueRef& v = (*inputs)[pi];
      if (v.kind == ValueRef::Kind::Const && !fitsRange(v.constant(), p)) {
        diags_.error(DiagCode::InterfaceMismatch, portWhere(node, given[pi]),
                     "input '" + p.name + "' of '" + im.name + "' is " + v.constant().toString() +
                         ", outside its range " + rangeText(p),
                     idOf(node), inputLabel(p.name));
        inRange = false;
      }
      bool literal = !given[pi] || given[pi]->source.kind == InputSource::Kind::Literal;
      scope.inputs.emplace(p.name, isColorHint(p.hint) && literal && v.kind == ValueRef::Kind::Const ? linearised(v) : v);
    }
    InstanceOptionRequest request{*sub.interface, sub.file, &node, idOf(node), graph_.file, shared_.topDirectory,
                                  [this](const TextureFile& t) { return acceptedTexture(t); }};
    auto bound = bindInstanceOptions(request, diags_);
    if (!inRange || !bound) return;
    scope.options = std::move(*bound);
    size_t firstDiag = diags_.all().size();
    size_t firstOp = program_.ops.size();
    bool ok = Resolver(withInstanceOptions(sub, scope.idPrefix), registry_, diags_, program_, shared_, scope).runInstance();
    diags_.addLocatedNoteFrom(firstDiag, here);
    if (!ok) {
      program_.ops.resize(firstOp);
      return;
    }
    expandedOutputs_[static_cast<size_t>(ni)] = std::move(scope.outputs);
  }

  // The subgraph an instance inlines: `sub` as written, or, where options of its own nodes
  // are set from outside (Graph::instanceOptions of the top-level graph, qualified by
  // `prefix`), a copy with them in place, kept for the program's lifetime of this resolve.
  const Graph& withInstanceOptions(const Graph& sub, const std::string& prefix) {
    if (!shared_.instanceOptions) return sub;
    Graph* copy = nullptr;
    for (const InstanceOption& o : *shared_.instanceOptions) {
      if (o.node.size() <= prefix.size() || o.node.compare(0, prefix.size(), prefix) != 0) continue;
      std::string id = o.node.substr(prefix.size());
      if (id.find('/') != std::string::npos) continue;  // deeper: the nested instance's business
      if (!copy) copy = &shared_.instanceGraphs.emplace_back(sub);
      for (auto& n : copy->nodes) {
        if (n.id != id) continue;
        auto written = std::find_if(n.options.begin(), n.options.end(), [&](const NodeOption& w) { return w.name == o.option.name; });
        if (written == n.options.end())
          n.options.push_back(o.option);
        else
          *written = o.option;
      }
    }
    return copy ? *copy : sub;
  }

  // A colour literal or default (sRGB-authored) as the linear constant the nodes receive.
  ValueRef linearised(const ValueRef& srgb) { return ValueRef::constant_(shared_.constants.intern(linearColor(srgb.constant()))); }

  static bool fitsRange(const Value& v, const Parameter& p) {
    for (int k = 0; k < componentCount(v.type); ++k)
      if ((p.min && v[k] < *p.min) || (p.max && v[k] > *p.max)) return false;
    return true;
  }
  static std::string rangeText(const Parameter& p) {
    return "[" + (p.min ? formatNumber(*p.min) : std::string("-inf")) + ", " +
           (p.max ? formatNumber(*p.max) : std::string("inf")) + "]";
  }

  // A subgraph's interface outputs: each the value of its source, of its declared type.
  void resolveInterfaceOutputs(std::vector<ValueRef>& values) {
    for (const auto& out : graph_.interface->outputs) {
      std::string label = "interface output '" + out.name + "'";
      if (out.source.kind == InputSource::Kind::NodeOutput) {
        if (referencedNode(out.source, "", [&] { return label; }) < 0) continue;
      } else if (out.source.kind == InputSource::Kind::Parameter && !paramValue_.count(out.source.name)) {
        diags_.error(DiagCode::UnknownParameter, out.source.where, "no parameter named '" + out.source.name + "'",
                     "", label);
        continue;
      }
      auto ref = sourceRef(out.source);
      if (!ref) continue;  // the node itself failed and was reported
      if (!existsForItsInputs(*ref, out.source, "", [&] { return label; })) continue;
      Type got = program_.typeOf(*ref);
      if (got != out.type) {
        diags_.error(DiagCode::InterfaceMismatch, out.source.where,
                     label + " is declared " + std::string(typeName(out.type)) + ", but " + describeSource(out.source) +
                         " is " + std::string(typeName(got)),
                     out.source.kind == InputSource::Kind::NodeOutput ? prefixed(out.source.name) : "", label);
        continue;
      }
      values.push_back(*ref);
    }
  }

  // A node's id in the program: inside an instance, prefixed with the instance's path.
  std::string idOf(const Node& node) const { return prefixed(node.id); }
  std::string prefixed(const std::string& id) const { return scope_ ? scope_->idPrefix + id : id; }

  // A PNG path in a subgraph is relative to the subgraph's file; the program reads every
  // texture relative to the top-level graph's folder (the import check keeps the
  // subgraph inside it, so the path needs no "..").
  void retargetTexturePaths(const NodeSpec& spec, nlohmann::json& options) const {
    for (const auto& o : spec.options) {
      if (o.kind != OptionSpec::Kind::Texture) continue;
      auto it = options.find(o.name);
      if (it == options.end() || !it->is_string()) continue;
      const std::string& path = it->get_ref<const std::string&>();
      if (path.rfind(kBuiltinTexturePrefix, 0) == 0 || interfaceTextureReference(*it)) continue;
      namespace fs = std::filesystem;
      fs::path top = shared_.topDirectory.empty() ? fs::path(".") : fs::path(shared_.topDirectory);
      fs::path here = directory_.empty() ? fs::path(".") : fs::path(directory_);
      *it = (here / path).lexically_normal().lexically_relative(top.lexically_normal()).generic_string();
    }
  }

  // Texture options written "$name" become the texture the instance chose, and the sampler
  // state it set becomes the node's (its wrap, filter and colour space options); a node
  // without those options samples in its own fixed state, so setting one for it is refused.
  bool bindInterfaceTextures(const NodeSpec& spec, const Node& node, nlohmann::json& options) {
    bool ok = true;
    for (const auto& o : spec.options) {
      if (o.kind != OptionSpec::Kind::Texture) continue;
      auto it = options.find(o.name);
      if (it == options.end()) continue;
      auto reference = interfaceTextureReference(*it);
      if (!reference) continue;
      // A copy: the view points into the option's string, which the next line replaces.
      const std::string name{*reference};
      const BoundTexture& bound = options_->textures.find(name)->second;  // lookUpSpecs checked it
      *it = bound.texture.source;
      auto set = [&](std::string_view key, const auto& value, auto nameOf) {
        if (!value) return;
        if (spec.optionIndex(key) < 0) {
          diags_.error(DiagCode::InstanceOptionValue, bound.where,
                       "the texture '" + name + "' sets '" + std::string(key) + "', but node '" + idOf(node) +
                           "' (" + spec.type + ") that samples it has no such option: it samples in its own fixed state",
                       idOf(node), optionLabel(o.name));
          ok = false;
          return;
        }
        options[std::string(key)] = std::string(nameOf(*value));
      };
      set("wrap", bound.texture.wrap, wrapName);
      set("filter", bound.texture.filter, filterName);
      set("color_space", bound.texture.colorSpace, colorSpaceName);
    }
    return ok;
  }

  // `v` as type `want`: a float splats to a vector (as a port does), a constant at once,
  // anything else through a `combine` op named after the node.
  ValueRef splat(const ValueRef& v, Type want, const Node& node) {
    Type have = program_.typeOf(v);
    if (have == want) return v;
    if (v.kind == ValueRef::Kind::Const) return ValueRef::constant_(shared_.constants.intern(v.constant().convertedTo(want)));
    const NodeSpec* combine = registry_.find("combine");
    if (!combine) throw std::logic_error("the registry has no 'combine' node to splat an input with");
    Op op;
    op.spec = combine;
    op.nodeId = idOf(node);
    op.where = node.where;
    if (scope_) op.instanceChain = scope_->chain;
    SharedOptions held = shared_.options.intern(*combine, completeOptions(*combine, {{"type", std::string(typeName(want))}}));
    op.sharedOptions = std::move(held.json);
    op.parsedOptions = std::move(held.parsed);
    int n = componentCount(want);
    op.inputs.assign(combine->inputs.size(), ValueRef::constant_(shared_.constants.intern(Value::scalar(0))));
    std::vector<Type> types(combine->inputs.size(), Type::Float);
    for (int k = 0; k < n; ++k) op.inputs[static_cast<size_t>(k)] = v;
    PortTyping t = typePorts(*combine, *op.parsedOptions, types, [](int) { return std::string(); });
    if (!t.error.empty()) throw std::logic_error("splatting an input: " + t.error);
    op.inputTypes = std::move(t.inputTypes);
    op.outputTypes = std::move(t.outputTypes);
    program_.ops.push_back(std::move(op));
    return ValueRef::op(static_cast<int>(program_.ops.size()) - 1, 0);
  }

  // Where byte `offset` of the string of option `option` of `node` is in the file: the
  // column counts the escapes written before it. The option's own position when the
  // file's text is not at hand (a graph built in memory), the node's when it is not written.
  SourceRef optionWhere(const Node& node, std::string_view option, size_t offset) {
    for (const auto& o : node.options) {
      if (o.name != option) continue;
      SourceRef at = o.where;
      if (at.line <= 0) return at;
      if (!sourceLines_) {
        const std::string* text = diags_.source(graph_.file);
        sourceLines_ = text ? splitLines(*text) : std::vector<std::string_view>{};
      }
      if (static_cast<size_t>(at.line) <= sourceLines_->size())
        at.col = jsonStringByteColumn((*sourceLines_)[static_cast<size_t>(at.line - 1)], at.col, offset);
      else
        at.col += 1 + static_cast<int>(offset);
      return at;
    }
    return node.where;
  }

  SourceRef portWhere(const Node& node, const NodeInput* given) const {
    return given ? given->source.where : node.where;
  }

  bool typeOp(Op& op, const Node& node, const std::vector<Type>& sourceTypes,
              const std::vector<const NodeInput*>& given) {
    PortTyping t = typePorts(*op.spec, *op.parsedOptions, sourceTypes,
                             [&](int i) { return sourceName(given[static_cast<size_t>(i)]); });
    if (!t.error.empty()) {
      const NodeInput* at = t.errorInput >= 0 ? given[static_cast<size_t>(t.errorInput)] : nullptr;
      std::string label = t.errorInput >= 0 ? op.spec->inputs[static_cast<size_t>(t.errorInput)].name : "";
      mismatch(node, at, label, t.error);
      return false;
    }
    op.inputTypes = std::move(t.inputTypes);
    op.outputTypes = std::move(t.outputTypes);
    return true;
  }

  static std::string sourceName(const NodeInput* given) {
    return given ? describeSource(given->source) : std::string("its default");
  }

  void mismatch(const Node& node, const NodeInput* given, const std::string& port, const std::string& message) {
    diags_.error(DiagCode::TypeMismatch, portWhere(node, given), message, node.id,
                 port.empty() ? std::string() : inputLabel(port));
  }

  void resolveOutputs() {
    if (graph_.outputs.empty())
      diags_.error(DiagCode::NoOutputs, graph_.outputsWhere, "the graph connects no outputs");
    for (const auto& out : graph_.outputs) {
      std::string label = "output '" + std::string(outputSlotName(out.slot)) + "'";
      if (out.source.kind == InputSource::Kind::NodeOutput) {
        if (referencedNode(out.source, "", [&] { return label; }) < 0) continue;
      } else if (out.source.kind == InputSource::Kind::Parameter && !paramValue_.count(out.source.name)) {
        diags_.error(DiagCode::UnknownParameter, out.source.where,
                     "no parameter named '" + out.source.name + "'", "", label);
        continue;
      }
      auto ref = sourceRef(out.source);
      if (!ref) continue;  // the node itself failed and was reported
      if (!existsForItsInputs(*ref, out.source, "", [&] { return label; })) continue;
      Type want = outputSlotRow(out.slot).type;
      Type got = program_.typeOf(*ref);
      if (!implicitlyConvertible(got, want)) {
        diags_.error(DiagCode::TypeMismatch, out.source.where,
                     label + " expects " + std::string(typeName(want)) + ", but " + describeSource(out.source) +
                         " is " + std::string(typeName(got)),
                     out.source.kind == InputSource::Kind::NodeOutput ? out.source.name : "", label);
        continue;
      }
      // A colour written as a literal into the colour slot is sRGB-authored, as on a colour port.
      bool colorLiteral = out.slot == OutputSlot::FragmentColor && out.source.kind == InputSource::Kind::Literal;
      program_.outputs.push_back({out.slot, colorLiteral ? linearised(*ref) : *ref, want, out.source.where});
    }
    std::sort(program_.outputs.begin(), program_.outputs.end(),
              [](const ProgramOutput& a, const ProgramOutput& b) { return a.slot < b.slot; });
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
  // Node i's inputs[k] reads node inputNode_[inputBase_[i] + k] (-1: not a node output).
  std::vector<size_t> inputBase_;
  std::vector<int> inputNode_;
  std::vector<Type> sourceTypes_;         // buildOps: the node's input types
  std::vector<const NodeInput*> given_;   // buildOps: the node's written inputs by port
};

}  // namespace

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags) {
  return Resolver(graph, registry, diags).run();
}

std::optional<Program> resolveGraph(const Graph& graph, const Registry& registry, Diagnostics& diags,
                                    NodeOutputValues& nodeOutputs) {
  return Resolver(graph, registry, diags).run(&nodeOutputs);
}

}  // namespace wg
