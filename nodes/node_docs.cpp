#include "nodes/node_docs.h"

#include "core/instance_options.h"

#include "nodes/glsl_function_node.h"

#include <map>

#include "core/shown_text.h"
#include "core/graph_imports.h"
#include "core/number_format.h"

namespace wg {
namespace {

std::string portType(const PortSpec& p) {
  switch (p.kind) {
    case PortKind::Fixed: return std::string(typeName(p.type));
    case PortKind::Gen: return "float|vec2|vec3|vec4";
    case PortKind::Custom: return "see description";
  }
  return "?";
}

std::string portDefault(const PortSpec& p) {
  if (p.defaultValue) return p.defaultValue->toString();
  if (p.defaultBuiltin) return "the " + std::string(builtinName(*p.defaultBuiltin)) + " builtin";
  return "required";
}

// A quality knob's levels for the option's doc cell.
std::string knobText(const OptionSpec& o) {
  if (o.levels.empty()) return "";
  std::string s = ". Quality knob, cheapest to most exact: ";
  for (size_t i = 0; i < o.levels.size(); ++i) s += (i ? " < `" : "`") + o.levels[i].dump() + "`";
  return s;
}

std::string optionKind(const OptionSpec& o) {
  switch (o.kind) {
    case OptionSpec::Kind::Enum: {
      std::string s;
      for (const auto& c : o.choices) s += (s.empty() ? "" : " \\| ") + c;
      return s;
    }
    case OptionSpec::Kind::Number:
    case OptionSpec::Kind::Integer: {
      std::string s = o.kind == OptionSpec::Kind::Integer ? "integer" : "number";
      if (o.min || o.max)
        s += " in [" + (o.min ? formatNumber(*o.min) : "-inf") + ", " + (o.max ? formatNumber(*o.max) : "inf") + "]";
      return s;
    }
    case OptionSpec::Kind::Bool: return "bool";
    case OptionSpec::Kind::Json: return "JSON";
    case OptionSpec::Kind::Text: return "text";
    case OptionSpec::Kind::Texture: return "texture: `builtin:<name>` or a .png path relative to the graph";
  }
  return "?";
}

std::string stagesText(unsigned s) {
  if (s == kAnyStage) return "vertex, fragment";
  return s == kVertexStage ? "vertex" : "fragment";
}

}  // namespace

nlohmann::json functionGraphJson(const std::string& type, const Graph& g) {
  NodePorts ports = interfacePorts(g);
  nlohmann::json j;
  j["type"] = type;
  j["family"] = "subgraph";
  j["file"] = validUtf8(g.file);  // a file name need not be UTF-8; JSON must
  j["summary"] = g.interface ? g.interface->description : "";
  nlohmann::json inputs = nlohmann::json::array();
  for (size_t i = 0; i < ports.inputs.size(); ++i) {
    const Parameter& p = g.parameters[i];
    nlohmann::json pj{{"name", p.name}, {"type", portType(ports.inputs[i])}, {"doc", p.description},
                      {"default", portDefault(ports.inputs[i])}};
    if (p.min) pj["min"] = *p.min;
    if (p.max) pj["max"] = *p.max;
    inputs.push_back(pj);
  }
  nlohmann::json outputs = nlohmann::json::array();
  for (const auto& o : ports.outputs) outputs.push_back({{"name", o.name}, {"type", portType(o)}, {"doc", o.doc}});
  j["inputs"] = inputs;
  j["outputs"] = outputs;
  // Options fixed per instance (core/instance_options.h): listed only where declared.
  if (g.interface && !g.interface->options.empty()) {
    nlohmann::json options = nlohmann::json::array();
    for (const auto& o : g.interface->options) {
      nlohmann::json oj{{"name", o.name}, {"kind", std::string(interfaceOptionKindName(o.kind))}, {"doc", o.description}};
      if (!o.choices.empty()) oj["choices"] = o.choices;
      if (o.min) oj["min"] = *o.min;
      if (o.max) oj["max"] = *o.max;
      if (!o.defaultValue.is_null()) oj["default"] = o.defaultValue;
      options.push_back(oj);
    }
    j["options"] = options;
  }
  return j;
}

std::string functionGraphText(const std::string& type, const Graph& g) {
  // Every string from the file is shown escaped (core/shown_text.h): a description holding
  // ESC or BEL would act on the terminal.
  nlohmann::json j = functionGraphJson(type, g);
  auto shown = [](const nlohmann::json& v) { return escapedForTerminal(v.get<std::string>()); };
  std::string s = escapedForTerminal(type) + "  (subgraph, " + escapedForTerminal(g.file) + ")\n";
  if (!j["summary"].get<std::string>().empty()) s += "  " + shown(j["summary"]) + "\n";
  s += "  inputs:\n";
  if (j["inputs"].empty()) s += "    (none)\n";
  for (const auto& in : j["inputs"]) {
    std::string range;
    if (in.contains("min") || in.contains("max"))
      range = " in [" + (in.contains("min") ? formatNumber(in["min"].get<double>()) : std::string("-inf")) + ", " +
              (in.contains("max") ? formatNumber(in["max"].get<double>()) : std::string("inf")) + "]";
    s += "    " + shown(in["name"]) + ": " + shown(in["type"]) + ", default " + shown(in["default"]) + range;
    if (!in["doc"].get<std::string>().empty()) s += " — " + shown(in["doc"]);
    s += "\n";
  }
  if (j.contains("options")) {
    s += "  options (fixed per instance):\n";
    for (const auto& o : j["options"]) {
      s += "    " + shown(o["name"]) + ": " + shown(o["kind"]);
      if (o.contains("choices")) s += " " + escapedForTerminal(o["choices"].dump());
      if (o.contains("min") || o.contains("max"))
        s += " in [" + (o.contains("min") ? formatNumber(o["min"].get<double>()) : std::string("-inf")) + ", " +
             (o.contains("max") ? formatNumber(o["max"].get<double>()) : std::string("inf")) + "]";
      s += o.contains("default") ? ", default " + escapedForTerminal(o["default"].dump()) : std::string(", required");
      if (!o["doc"].get<std::string>().empty()) s += " — " + shown(o["doc"]);
      s += "\n";
    }
  }
  s += "  outputs:\n";
  for (const auto& out : j["outputs"]) {
    s += "    " + shown(out["name"]) + ": " + shown(out["type"]);
    if (!out["doc"].get<std::string>().empty()) s += " — " + shown(out["doc"]);
    s += "\n";
  }
  return s;
}

nlohmann::json nodesJson(const Registry& registry) {
  nlohmann::json all = nlohmann::json::array();
  for (const NodeSpec* s : registry.all()) {
    nlohmann::json j;
    j["type"] = s->type;
    j["family"] = s->family;
    j["summary"] = s->summary;
    j["formula"] = s->formula;
    if (!s->source.empty()) j["source"] = s->source;
    j["cost"] = s->cost;
    j["stages"] = stagesText(s->stages);
    j["tolerance"] = s->tolerance;
    if (s->conditionRoundings > 0)
      j["conditioning"] = {{"input_roundings", s->conditionRoundings}, {"where", s->conditionWhy}};
    auto ports = [](const std::vector<PortSpec>& ps, bool input) {
      nlohmann::json a = nlohmann::json::array();
      for (const auto& p : ps) {
        if (p.derived) continue;  // not a port a graph connects: listed under "derived_inputs"
        nlohmann::json pj{{"name", p.name}, {"type", portType(p)}, {"doc", p.doc}};
        if (input) pj["default"] = portDefault(p);
        if (p.color) pj["color"] = true;  // literals and the default are sRGB-authored
        a.push_back(pj);
      }
      return a;
    };
    j["inputs"] = ports(s->inputs, true);
    nlohmann::json derived = nlohmann::json::array();
    for (const auto& p : s->inputs)
      if (p.derived) derived.push_back({{"name", p.name}, {"type", portType(p)}, {"doc", p.doc}});
    if (!derived.empty()) j["derived_inputs"] = derived;
    j["outputs"] = ports(s->outputs, false);
    nlohmann::json opts = nlohmann::json::array();
    for (const auto& o : s->options) {
      nlohmann::json opt = {{"name", o.name}, {"values", optionKind(o)}, {"default", o.defaultValue}, {"doc", o.doc}};
      if (!o.levels.empty()) opt["levels"] = o.levels;
      opts.push_back(std::move(opt));
    }
    j["options"] = opts;
    nlohmann::json hard = nlohmann::json::array();
    for (const auto& h : s->hardCases) hard.push_back({{"name", h.name}, {"expectation", h.expectation}});
    j["hard_cases"] = hard;
    for (SceneResource r : s->resources) j["resources"].push_back(std::string(sceneResourceRow(r).name));
    all.push_back(j);
  }
  return all;
}

std::string nodesMarkdown(const Registry& registry) {
  std::map<std::string, std::vector<const NodeSpec*>> byFamily;
  for (const NodeSpec* s : registry.all()) byFamily[s->family].push_back(s);
  std::string md;
  md += "# Node reference\n\n";
  md += "Generated from the node registry by `watergraph nodes --markdown`; do not edit by hand.\n";
  md += "Every node has GLSL in `nodes/glsl/`, a double-precision reference (`eval`) that follows GLSL\n";
  md += "semantics, and the hard cases listed with it. The float32 GPU result is held to the reference by\n";
  md += "|gpu - ref| <= tolerance * max(1, |ref|) + conditioning, per component: `tolerance` bounds the\n";
  md += "rounding of the evaluation; `conditioning` (where a node lists it) is what moving each float32 input\n";
  md += "by `input roundings` x 2^-24 of itself makes of the exact result, summed over the inputs: it grows\n";
  md += "only where the formula is ill-conditioned. `watergraph probe` and the hard-case suite check it\n";
  md += "(docs/accuracy.md).\n\n";
  md += "An input whose type reads **sRGB colour** takes a colour: a literal a graph gives it, and its\n";
  md += "default, are the sRGB values a colour picker shows, and the node receives them linearised\n";
  md += "(docs/graph-format.md#colour). Every other input, and every value wired from a node or a\n";
  md += "parameter, reaches the node as it is.\n\n";
  for (const auto& [family, specs] : byFamily) {
    md += "- **" + family + "**:";
    for (const NodeSpec* s : specs) md += " [`" + s->type + "`](#" + s->type + ")";
    md += "\n";
  }
  for (const auto& type : registry.fileNodeTypeNames()) md += "- **custom**: [`" + type + "`](#" + type + ")\n";
  for (const auto& [family, specs] : byFamily) {
    md += "\n## " + family + "\n";
    for (const NodeSpec* s : specs) {
      md += "\n### " + s->type + "\n\n" + s->summary + "\n\n";
      md += "- formula: " + s->formula + "\n";
      if (!s->source.empty()) md += "- source ([sources](sources.md)): " + s->source + "\n";
      md += "- stages: " + stagesText(s->stages) + "\n";
      md += "- cost: " + s->cost + "\n";
      md += "- tolerance: " + formatNumber(s->tolerance) + "\n";
      if (s->conditionRoundings > 0)
        md += "- conditioning: input roundings " + formatNumber(s->conditionRoundings) + "; " + s->conditionWhy + "\n";
      if (!s->resources.empty()) {
        md += "- scene resources:";
        for (SceneResource r : s->resources) md.append(" `").append(sceneResourceRow(r).name).append("`");
        md += "\n";
      }
      if (!s->inputs.empty()) {
        md += "\n| input | type | default | |\n|---|---|---|---|\n";
        for (const auto& p : s->inputs)
          if (!p.derived)
            md += "| `" + p.name + "` | " + portType(p) + (p.color ? ", **sRGB colour**" : "") + " | " + portDefault(p) + " | " +
                  p.doc + " |\n";
        std::string derived;
        for (const auto& p : s->inputs)
          if (p.derived) derived += "\n  - `" + p.name + "` (" + portType(p) + "): " + p.doc;
        if (!derived.empty())
          md += "\nComputed once per draw by ops of their own (the frequency analysis classifies them per-draw; a "
                "graph cannot connect them):" + derived + "\n";
      }
      md += "\n| output | type | |\n|---|---|---|\n";
      for (const auto& p : s->outputs) md += "| `" + p.name + "` | " + portType(p) + " | " + p.doc + " |\n";
      if (!s->options.empty()) {
        md += "\n| option | values | default | |\n|---|---|---|---|\n";
        for (const auto& o : s->options)
          md += "| `" + o.name + "` | " + optionKind(o) + " | `" + o.defaultValue.dump() + "` | " + o.doc + knobText(o) + " |\n";
      }
      if (!s->hardCases.empty()) {
        md += "\nHard cases:\n";
        for (const auto& h : s->hardCases) md += "- " + h.name + ": " + h.expectation + "\n";
      }
    }
  }
  // The types whose nodes take their ports from a file: no spec until a node names one.
  for (const auto& type : registry.fileNodeTypeNames()) {
    md += "\n## custom\n\n### " + type + "\n\n";
    md += "A function of a `.glsl` file beside the graph: its `in` parameters are the node's inputs, its return "
          "value the output `out` and each `out` parameter one more output (float, vec2, vec3, vec4, mat3, mat4); "
          "an `in sampler2D` parameter is a texture the node's option of that name chooses. The file is checked by "
          "glslang for every target and renamed into the node's namespace; see "
          "[GLSL function nodes](graph-format.md#glsl-function-nodes).\n\n";
    md += "- stages: any (fragment only when the function takes derivatives)\n";
    md += "- reference: the `reference` formulas, or none (`check` then sweeps it for NaN and Inf only, and says why)\n";
    md += "\n| option | values | default | |\n|---|---|---|---|\n";
    for (const auto& o : glslFunctionOptions())
      md += "| `" + o.name + "` | " + optionKind(o) + " | `" + o.defaultValue.dump() + "` | " + o.doc + " |\n";
  }
  return md;
}

}  // namespace wg
