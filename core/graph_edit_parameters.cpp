// GraphEditor's blackboard edits: parameters (add, rename with references following,
// delete while nothing reads them, reorder) and presets (create from the current values,
// rename, delete). See core/graph_edit.h.
#include <algorithm>

#include "core/color_parameters.h"
#include "core/graph_edit.h"
#include "core/load_limits.h"
#include "core/number_format.h"

namespace wg {
namespace {

// Every place of `g` that reads parameter `name`, as "node 'tint' input 'deep'", in file order.
std::vector<std::string> readersOfParameter(const Graph& g, const std::string& name) {
  std::vector<std::string> readers;
  auto reads = [&](const InputSource& s) { return s.kind == InputSource::Kind::Parameter && s.name == name; };
  for (const Node& n : g.nodes)
    for (const NodeInput& in : n.inputs)
      if (reads(in.source)) readers.push_back("node '" + n.id + "' input '" + in.port + "'");
  for (const GraphOutput& o : g.outputs)
    if (reads(o.source)) readers.push_back("an output slot");
  if (g.interface)
    for (const InterfaceOutput& o : g.interface->outputs)
      if (reads(o.source)) readers.push_back("interface output '" + o.name + "'");
  for (const Preset& p : g.presets)
    for (const PresetValue& v : p.values)
      if (!v.isOption() && v.parameter == name) readers.push_back("preset '" + p.name + "'");
  return readers;
}

}  // namespace

std::string GraphEditor::addParameter(Parameter p) {
  if (!isIdentifier(p.name)) return "'" + p.name + "' is not a parameter name ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  if (graph_.findParameter(p.name)) return "a parameter '" + p.name + "' already exists";
  if (graph_.parameters.size() >= kMaxNodes) return "a graph has at most " + std::to_string(kMaxNodes) + " parameters";
  int n = componentCount(p.type);
  if (n < 1 || n > 4) return "a parameter is a float, vec2, vec3 or vec4";
  if (p.defaultValue.empty()) p.defaultValue.assign(static_cast<size_t>(n), 0.0);
  if (static_cast<int>(p.defaultValue.size()) != n)
    return "parameter '" + p.name + "': a " + std::string(typeName(p.type)) + " takes " + std::to_string(n) + " number(s)";
  for (double x : p.defaultValue)
    if (!fitsFloat32(x)) return "parameter '" + p.name + "': values must be finite in float32 range";
  if ((p.min && !fitsFloat32(*p.min)) || (p.max && !fitsFloat32(*p.max))) return "min and max must be finite in float32 range";
  if (p.min && p.max && *p.min > *p.max) return "min " + formatNumber(*p.min) + " is above max " + formatNumber(*p.max);
  for (double x : p.defaultValue)
    if ((p.min && x < *p.min) || (p.max && x > *p.max)) return "the default " + formatNumber(x) + " is outside min..max";
  if (!p.hint.empty() && !(isColorHint(p.hint) && (n == 3 || n == 4)))
    return "hint '" + p.hint + "': a colour hint (color, hdr_color) is for a vec3 or vec4";
  record("add parameter '" + p.name + "'", "");
  p.where.file = graph_.file;
  graph_.parameters.push_back(std::move(p));
  return "";
}

std::string GraphEditor::renameParameter(const std::string& from, const std::string& to) {
  if (!graph_.findParameter(from)) return "no parameter '" + from + "'";
  if (from == to) return "";
  if (!isIdentifier(to)) return "'" + to + "' is not a parameter name ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  if (graph_.findParameter(to)) return "a parameter '" + to + "' already exists";
  record("rename parameter '" + from + "' to '" + to + "'", "");
  auto follow = [&](InputSource& s) {
    if (s.kind == InputSource::Kind::Parameter && s.name == from) s.name = to;
  };
  for (Parameter& p : graph_.parameters)
    if (p.name == from) p.name = to;
  for (Node& n : graph_.nodes)
    for (NodeInput& in : n.inputs) follow(in.source);
  for (GraphOutput& o : graph_.outputs) follow(o.source);
  if (graph_.interface)
    for (InterfaceOutput& o : graph_.interface->outputs) follow(o.source);
  for (Preset& p : graph_.presets)
    for (PresetValue& v : p.values)
      if (!v.isOption() && v.parameter == from) v.parameter = to;
  return "";
}

std::string GraphEditor::deleteParameter(const std::string& name) {
  if (!graph_.findParameter(name)) return "no parameter '" + name + "'";
  std::vector<std::string> readers = readersOfParameter(graph_, name);
  if (!readers.empty()) {
    std::string list;
    for (size_t i = 0; i < readers.size() && i < 5; ++i) list += (i ? ", " : "") + readers[i];
    if (readers.size() > 5) list += " and " + std::to_string(readers.size() - 5) + " more";
    return "parameter '" + name + "' is still read by " + list + ": disconnect those first";
  }
  record("delete parameter '" + name + "'", "");
  std::erase_if(graph_.parameters, [&](const Parameter& p) { return p.name == name; });
  return "";
}

std::string GraphEditor::moveParameter(const std::string& name, size_t index) {
  auto it = std::find_if(graph_.parameters.begin(), graph_.parameters.end(), [&](const Parameter& p) { return p.name == name; });
  if (it == graph_.parameters.end()) return "no parameter '" + name + "'";
  if (index >= graph_.parameters.size()) return "index " + std::to_string(index) + " is past the last parameter";
  size_t from = static_cast<size_t>(it - graph_.parameters.begin());
  if (from == index) return "";
  record("move parameter '" + name + "'", "");
  Parameter moved = std::move(graph_.parameters[from]);
  graph_.parameters.erase(graph_.parameters.begin() + static_cast<std::ptrdiff_t>(from));
  graph_.parameters.insert(graph_.parameters.begin() + static_cast<std::ptrdiff_t>(index), std::move(moved));
  return "";
}

std::string GraphEditor::createPreset(const std::string& name) {
  if (!isIdentifier(name)) return "'" + name + "' is not a preset name ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  if (graph_.findPreset(name)) return "a preset '" + name + "' already exists";
  if (graph_.parameters.empty()) return "the graph has no parameters to keep in a preset";
  record("create preset '" + name + "'", "");
  Preset p;
  p.name = name;
  p.where.file = graph_.file;
  for (const Parameter& q : graph_.parameters) {
    PresetValue v;
    v.parameter = q.name;
    v.value = q.defaultValue;
    p.values.push_back(std::move(v));
  }
  graph_.presets.push_back(std::move(p));
  return "";
}

std::string GraphEditor::renamePreset(const std::string& from, const std::string& to) {
  if (!graph_.findPreset(from)) return "no preset '" + from + "'";
  if (from == to) return "";
  if (!isIdentifier(to)) return "'" + to + "' is not a preset name ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  if (graph_.findPreset(to)) return "a preset '" + to + "' already exists";
  record("rename preset '" + from + "' to '" + to + "'", "");
  for (Preset& p : graph_.presets)
    if (p.name == from) p.name = to;
  return "";
}

std::string GraphEditor::deletePreset(const std::string& name) {
  if (!graph_.findPreset(name)) return "no preset '" + name + "'";
  record("delete preset '" + name + "'", "");
  std::erase_if(graph_.presets, [&](const Preset& p) { return p.name == name; });
  return "";
}

}  // namespace wg
