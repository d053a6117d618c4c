// Resolving: the node options that presets set ("node.option", "instance.option",
// "instance/node.option"), each checked whichever preset is applied.
#include <algorithm>
#include <filesystem>
#include <string>

#include "core/graph_node_type.h"
#include "core/instance_options.h"
#include "core/node_options.h"
#include "core/resolver.h"
#include "core/suggest.h"

namespace wg::resolving {

// Every preset's node options, whichever preset is applied: each names an option of the
// node's type and a value it accepts, reported at the preset's member. A value written
// onto its node by applyPreset (same position) is checked there instead, once.
void Resolver::checkPresetOptions() {
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
void Resolver::checkPresetInstanceOption(const Preset& preset, const PresetValue& v, const Import& im) {
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
const OptionSpec* Resolver::presetOptionSpec(const Preset& preset, const PresetValue& v, const NodeSpec& spec,
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
void Resolver::checkPresetOptionValue(const Preset& preset, const PresetValue& v, const OptionSpec& option,
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
void Resolver::checkInstancePresetOption(const Preset& preset, const PresetValue& v) {
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

}  // namespace wg::resolving
