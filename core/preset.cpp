#include "core/preset.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>

#include "core/suggest.h"

namespace wg {

bool applyPreset(Graph& graph, std::string_view name, Diagnostics& diags) {
  const Preset* preset = graph.findPreset(name);
  if (!preset) {
    std::vector<std::string> names;
    std::string list;
    for (const auto& p : graph.presets) {
      names.push_back(p.name);
      list += (list.empty() ? "" : ", ") + p.name;
    }
    SourceRef where = graph.presets.empty() ? SourceRef{graph.file, 1, 1} : graph.presets.front().where;
    std::string message = "graph '" + graph.name + "' has no preset '" + std::string(name) + "'" +
                          didYouMean(name, names) +
                          (list.empty() ? "; it defines no presets" : "; its presets: " + list);
    diags.error(DiagCode::UnknownPreset, where, std::move(message));
    return false;
  }
  writePresetInto(graph, *preset);
  return true;
}

void writePresetInto(Graph& graph, const Preset& preset) {
  // By name, not a scan of the parameters per value: a preset may set 20,000 of them.
  std::unordered_map<std::string_view, Parameter*> parameters;
  for (auto& p : graph.parameters) parameters.emplace(p.name, &p);
  std::unordered_map<std::string_view, Node*> nodes;
  for (auto& n : graph.nodes) nodes.emplace(n.id, &n);
  for (const auto& v : preset.values) {
    if (!v.isOption()) {
      if (auto it = parameters.find(v.parameter); it != parameters.end()) it->second->defaultValue = v.value;
      continue;
    }
    if (v.node.find('/') != std::string::npos) {  // a node inside a subgraph instance: resolve applies it
      auto& inner = graph.instanceOptions;
      auto written = std::find_if(inner.begin(), inner.end(), [&](const InstanceOption& o) {
        return o.node == v.node && o.option.name == v.option;
      });
      InstanceOption option{v.node, {v.option, v.optionValue, v.where, v.keyWhere}};
      if (written == inner.end())
        inner.push_back(std::move(option));
      else
        *written = std::move(option);
      continue;
    }
    auto it = nodes.find(v.node);
    if (it == nodes.end()) continue;
    std::vector<NodeOption>& options = it->second->options;
    auto written = std::find_if(options.begin(), options.end(), [&](const NodeOption& o) { return o.name == v.option; });
    NodeOption option{v.option, v.optionValue, v.where, v.keyWhere};
    if (written == options.end())
      options.push_back(std::move(option));
    else
      *written = std::move(option);
  }
}

}  // namespace wg
