#include "core/preset.h"

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
  // By name, not a scan of the parameters per value: a preset may set 20,000 of them.
  std::unordered_map<std::string_view, Parameter*> byName;
  for (auto& p : graph.parameters) byName.emplace(p.name, &p);
  for (const auto& v : preset->values)
    if (auto it = byName.find(v.parameter); it != byName.end()) it->second->defaultValue = v.value;
  return true;
}

}  // namespace wg
