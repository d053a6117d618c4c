#include "accuracy/tune_knobs.h"

#include <algorithm>
#include <stdexcept>

#include "codegen/compile.h"
#include "core/graph_node_type.h"
#include "core/ocean_settings.h"
#include "core/preset.h"
#include "nodes/registry.h"

namespace wg::accuracy {
namespace {

// The knobs of `graph`'s nodes, ids prefixed by the instances it lies in ("shore/").
void collectKnobs(const Graph& graph, const std::string& prefix, int depth, std::vector<TuneKnob>& knobs) {
  for (const auto& n : graph.nodes) {
    GraphNodeType type = nodeTypeOf(graph, defaultRegistry(), n.type);
    if (type.import && type.import->graph && depth < 64) {
      collectKnobs(*type.import->graph, prefix + n.id + "/", depth + 1, knobs);
      continue;
    }
    if (!type.spec) continue;
    for (const auto& o : type.spec->options) {
      // A knob's levels may follow the node's other options (one size per cascade).
      std::vector<nlohmann::json> levels = knobLevels(o, writtenOptions(n));
      if (levels.size() >= 2) knobs.push_back({prefix + n.id, o.name, std::move(levels)});
    }
  }
}

// The shaders the compiler writes for a configuration (the tessellation factor is a
// constant of the control stage, the passes follow from the samplers the shaders declare).
// Not the manifest (only its pass sizes and its oceans' options): it lists the bypassed nodes,
// so switching off a node whose output nothing reads would count as a change.
std::string compiledText(const Graph& graph, Target target) {
  Diagnostics diags;
  CompileOptions options;
  options.targets = {target};
  options.validate = false;  // only the text matters here; the measured configurations are validated
  options.checkPresets = false;  // one configuration of the knobs; the graph's presets were checked once
  auto compiled = compileGraph(graph, defaultRegistry(), options, diags);
  if (!compiled) return "";  // does not compile: distinct from anything that does (tune reports it)
  std::string all;
  for (const auto& f : compiled->files)
    if (!f.name.ends_with(".manifest.json")) all += f.name + '\0' + f.contents + '\0';
  // The scene passes' sizes: a `resolution` level changes no shader, only these.
  for (const auto& p : compiled->manifest.passScales)
    all += std::string(renderPassRow(p.pass).name) + '=' + std::to_string(p.scale) + '\0';
  // The spectral oceans' options: the simulation passes run from them, not from shader text,
  // so a level of `foam_step` changes the foam every frame shows and what its steps cost
  // while the shaders stay the same. The foam's options only where a shader reads the foam
  // (without ocean_foam no foam is computed, and its step changes nothing).
  const Manifest& m = compiled->manifest;
  for (size_t i = 0; i < m.oceans.size(); ++i) {
    const bool foamRead = std::any_of(m.textures.begin(), m.textures.end(), [&](const TextureInfo& t) {
      return t.ocean && t.ocean->ocean == static_cast<int>(i) && t.ocean->map == ocean::kFoamMap;
    });
    nlohmann::json options = m.oceans[i].options;
    if (!foamRead && options.is_object())
      for (auto it = options.begin(); it != options.end();) it = it.key().starts_with("foam_") ? options.erase(it) : std::next(it);
    all += "ocean " + m.oceans[i].nodeId + '=' + options.dump() + '\0';
  }
  return all;
}

}  // namespace

std::vector<TuneKnob> graphKnobs(const Graph& graph) {
  std::vector<TuneKnob> knobs;
  collectKnobs(graph, "", 0, knobs);
  return knobs;
}

std::vector<TuneKnob> distinctKnobLevels(const Graph& graph, std::vector<TuneKnob> knobs, Target target,
                                         std::vector<std::string>& unchanged) {
  TuneConfig exact;
  for (const auto& k : knobs) exact.push_back(static_cast<int>(k.levels.size()) - 1);
  std::vector<TuneKnob> kept;
  for (size_t k = 0; k < knobs.size(); ++k) {
    TuneKnob knob = knobs[k];
    std::vector<nlohmann::json> levels;
    std::string moreExact;  // the text of the level kept last (from the most exact down)
    for (size_t l = knob.levels.size(); l-- > 0;) {
      TuneConfig c = exact;
      c[k] = static_cast<int>(l);
      std::string text = compiledText(withKnobLevels(graph, knobs, c), target);
      if (l + 1 < knob.levels.size() && !text.empty() && text == moreExact) continue;
      levels.insert(levels.begin(), knob.levels[l]);
      moreExact = text;
    }
    if (levels.size() < 2) {
      unchanged.push_back(knob.name());
      continue;
    }
    knob.levels = std::move(levels);
    kept.push_back(std::move(knob));
  }
  return kept;
}

Graph withKnobLevels(const Graph& graph, const std::vector<TuneKnob>& knobs, const TuneConfig& config) {
  Preset preset;
  for (size_t k = 0; k < knobs.size(); ++k) {
    PresetValue v;
    v.node = knobs[k].node;
    v.option = knobs[k].option;
    v.optionValue = knobs[k].levels.at(static_cast<size_t>(config.at(k)));
    preset.values.push_back(std::move(v));
  }
  Graph g = graph;
  writePresetInto(g, preset);
  return g;
}

std::vector<std::string> dropBypassKnobs(std::vector<TuneKnob>& knobs, const std::vector<std::string>& keep,
                                         bool keepAll) {
  std::vector<std::string> unknown;
  for (const auto& node : keep)
    if (std::none_of(knobs.begin(), knobs.end(),
                     [&](const TuneKnob& k) { return k.option == kBypassOption && k.node == node; }))
      unknown.push_back(node);
  std::erase_if(knobs, [&](const TuneKnob& k) {
    return k.option == kBypassOption && (keepAll || std::find(keep.begin(), keep.end(), k.node) != keep.end());
  });
  return unknown;
}

std::vector<std::string> bypassedNodes(const std::vector<TuneKnob>& knobs, const TuneConfig& config) {
  std::vector<std::string> out;
  for (size_t k = 0; k < knobs.size() && k < config.size(); ++k) {
    const auto& level = knobs[k].levels[static_cast<size_t>(config[k])];
    if (knobs[k].option == kBypassOption && level.is_boolean() && level.get<bool>()) out.push_back(knobs[k].node);
  }
  return out;
}

}  // namespace wg::accuracy
