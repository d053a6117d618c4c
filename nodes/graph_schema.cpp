#include "nodes/graph_schema.h"

#include "nodes/glsl_function_node.h"

#include <algorithm>
#include <map>

#include "core/graph.h"
#include "core/load_limits.h"
#include "core/node_spec.h"
#include "core/texture_check.h"
#include "core/types.h"
#include "core/view_transform.h"

namespace wg {
namespace {

using OJ = nlohmann::ordered_json;

constexpr const char* kIdentifierPattern = "^[A-Za-z_][A-Za-z0-9_]*$";
// A preset member that sets a node's option: "node.option", or inside a subgraph instance
// "instance/node.option" (nested instances: "a/b/node.option").
constexpr const char* kPresetOptionPattern =
    "^[A-Za-z_][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*\\.[A-Za-z_][A-Za-z0-9_]*$";
constexpr const char* kNodeOutputPattern = "^[A-Za-z_][A-Za-z0-9_]*\\.[A-Za-z_][A-Za-z0-9_]*$";
constexpr const char* kParameterPattern = "^\\$[A-Za-z_][A-Za-z0-9_]*$";

OJ defRef(const std::string& name) { return OJ{{"$ref", "#/definitions/" + name}}; }
// A description beside a $ref (draft-07 ignores siblings of $ref when validating, editors show them).
OJ described(const std::string& doc, OJ s) {
  OJ out{{"description", doc}};
  for (auto& [k, v] : s.items()) out[k] = v;
  return out;
}

// A float vector literal of exactly n numbers (n >= 2), or 2..4 when n == 0.
OJ vectorLiteral(int n) {
  OJ a{{"type", "array"}, {"items", defRef("number")}};
  a["minItems"] = n ? n : 2;
  a["maxItems"] = n ? n : 4;
  return a;
}

// What may feed a port of this type: a reference always; literals where the type takes one
// (a float splats to any float vector, so a number fits every float-vector port).
std::string sourceDefinitionFor(const PortSpec& p) {
  if (p.kind != PortKind::Fixed) return "source";
  switch (p.type) {
    case Type::Float: return "source_float";
    case Type::Vec2: return "source_vec2";
    case Type::Vec3: return "source_vec3";
    case Type::Vec4: return "source_vec4";
    default: return "reference";
  }
}

std::string portTypeText(const PortSpec& p) {
  switch (p.kind) {
    case PortKind::Fixed: return std::string(typeName(p.type));
    case PortKind::Gen: return "float|vec2|vec3|vec4";
    case PortKind::Custom: return "float or vector";
  }
  return "?";
}

OJ portSchema(const PortSpec& p) {
  OJ s = defRef(sourceDefinitionFor(p));
  std::string d = portTypeText(p) + ": " + p.doc;
  if (p.defaultValue) d += " (default " + p.defaultValue->toString() + ")";
  else if (p.defaultBuiltin) d += " (default: the " + std::string(builtinName(*p.defaultBuiltin)) + " builtin)";
  else d += " (required)";
  s["description"] = d;
  return s;
}

// Json options check themselves in C++ (OptionSpec::validate); the schema knows the shape
// of the ones the registry has today. An option not listed here accepts any JSON value.
OJ knownJsonOptionSchema(const std::string& type, const std::string& option) {
  if (type == "expression" && option == "inputs")
    return OJ{{"type", "object"},
              {"maxProperties", 32},
              {"propertyNames", defRef("identifier")},
              {"additionalProperties", {{"enum", {"float", "vec2", "vec3", "vec4"}}}}};
  if (type == "swizzle" && option == "mask")
    return OJ{{"type", "string"}, {"pattern", "^[xyzwrgba]{1,4}$"}};
  if (type == "gerstner_waves" && option == "waves") {
    OJ wave{{"type", "object"},
            {"additionalProperties", false},
            {"required", {"direction", "steepness", "wavelength"}},
            {"properties",
             {{"direction", OJ{{"description", "[x, z], normalised; not zero"}, {"type", "array"},
                               {"items", defRef("number")}, {"minItems", 2}, {"maxItems", 2}}},
              {"steepness", OJ{{"description", "Q in [0, 1]"}, {"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
              {"wavelength", OJ{{"description", "metres, > 0"}, {"type", "number"}, {"exclusiveMinimum", 0},
                                {"maximum", kFloat32Max}}},
              {"amplitude", OJ{{"description", "metres (default Q/k)"}, {"type", "number"}, {"minimum", 0},
                               {"maximum", kFloat32Max}}},
              {"phase", OJ{{"description", "radians"}, {"type", "number"}, {"minimum", -kFloat32Max},
                           {"maximum", kFloat32Max}}}}}};
    return OJ{{"type", "array"}, {"minItems", 1}, {"maxItems", 16}, {"items", wave}};
  }
  return OJ::object();
}

OJ optionSchema(const NodeSpec& spec, const OptionSpec& o) {
  OJ s = OJ::object();
  s["description"] = o.doc;
  switch (o.kind) {
    case OptionSpec::Kind::Enum:
      s["type"] = "string";
      s["enum"] = o.choices;
      break;
    case OptionSpec::Kind::Number:
    case OptionSpec::Kind::Integer:
      s["type"] = o.kind == OptionSpec::Kind::Integer ? "integer" : "number";
      s["minimum"] = o.min ? *o.min : -kFloat32Max;
      s["maximum"] = o.max ? *o.max : kFloat32Max;
      break;
    case OptionSpec::Kind::Bool:
      s["type"] = "boolean";
      break;
    case OptionSpec::Kind::Texture: {
      OJ builtins = OJ::array();
      for (const auto& n : builtinTextureNames()) builtins.push_back(std::string(kBuiltinTexturePrefix) + n);
      s["type"] = "string";
      s["anyOf"] = OJ::array({OJ{{"description", "a built-in procedural texture"}, {"enum", builtins}},
                              OJ{{"description", "a .png path relative to the graph file, inside its folder"},
                                 {"pattern", "^(?![/\\\\])(?!(.*/)?\\.\\.(/|$)).*\\.png$"}},
                              OJ{{"description", "in a function graph: the texture option of its interface of that name, "
                                                 "chosen per instance"},
                                 {"pattern", "^\\$[A-Za-z_][A-Za-z0-9_]*$"}}});
      break;
    }
    case OptionSpec::Kind::Text:
      s["type"] = "string";
      s["maxLength"] = kMaxStringBytes;
      break;
    case OptionSpec::Kind::Json:
    {
      OJ known = knownJsonOptionSchema(spec.type, o.name);
      for (auto& [k, v] : known.items()) s[k] = v;
    }
      break;
  }
  if (!o.defaultValue.is_null()) s["default"] = OJ::parse(o.defaultValue.dump());
  return s;
}

OJ nodeTypeSchema(const NodeSpec& spec) {
  OJ inputs{{"type", "object"}, {"additionalProperties", false}};
  OJ inputProps = OJ::object();
  OJ required = OJ::array();
  for (const auto& p : spec.inputs) {
    if (p.derived) continue;  // the node computes it (NodeSpec::derive): not in the file
    inputProps[p.name] = portSchema(p);
    if (p.required()) required.push_back(p.name);
  }
  inputs["properties"] = inputProps;
  if (!required.empty()) inputs["required"] = required;
  if (spec.portsFor) {  // ports that the options declare (an expression's inputs): any identifier
    inputs["propertyNames"] = defRef("identifier");
    inputs["additionalProperties"] = described("an input the node's options declare", defRef("source"));
  }

  OJ options{{"type", "object"}, {"additionalProperties", false}};
  OJ optionProps = OJ::object();
  for (const auto& o : spec.options) optionProps[o.name] = optionSchema(spec, o);
  options["properties"] = optionProps;

  std::string outputs;
  for (const auto& p : spec.outputs) outputs += (outputs.empty() ? "" : ", ") + spec.type + "." + p.name;
  OJ s{{"description", spec.summary + " Outputs: " + outputs + "."},
       {"properties", {{"inputs", inputs}, {"options", options}}}};
  if (!required.empty()) s["required"] = OJ::array({"inputs"});
  return s;
}

OJ parameterSchema() {
  OJ byType = OJ::array();
  for (int n = 1; n <= 4; ++n) {
    std::string type = n == 1 ? "float" : "vec" + std::to_string(n);
    OJ then{{"properties", {{"default", n == 1 ? defRef("number") : vectorLiteral(n)}}}};
    if (n < 3) then["not"] = OJ{{"required", {"hint"}}};  // a colour hint needs vec3 or vec4
    byType.push_back(OJ{{"if", {{"properties", {{"type", {{"const", type}}}}}}}, {"then", then}});
  }
  // An sRGB colour ("hint": "color") stays within [0, 1]: its default, min and max.
  OJ unit{{"minimum", 0}, {"maximum", 1}};
  byType.push_back(OJ{{"if", {{"required", {"hint"}}, {"properties", {{"hint", {{"const", "color"}}}}}}},
                      {"then", {{"properties", {{"default", {{"items", unit}}}, {"min", unit}, {"max", unit}}}}}});
  return OJ{{"type", "object"},
            {"additionalProperties", false},
            {"required", {"type", "default"}},
            {"properties",
             {{"type", {{"description", "the uniform's type"}, {"enum", {"float", "vec2", "vec3", "vec4"}}}},
              {"default", {{"description", "a number for float; N numbers for vecN"}}},
              {"min", described("lowest value of every component", defRef("number"))},
              {"max", described("highest value of every component", defRef("number"))},
              {"hint",
               {{"description",
                 "a colour (vec3, vec4; a vec4's alpha is linear), authored as the sRGB values a colour picker shows and "
                 "linearised when compiled: color within [0, 1], hdr_color also past 1; no hint: data, used as it is"},
                {"enum", {"color", "hdr_color"}}}},
              {"description", {{"type", "string"}}},
              {"static", {{"description", "true: folded into the shader, never a uniform"}, {"type", "boolean"}}}}},
            {"allOf", byType}};
}

// A function graph's interface: its outputs (its inputs are its parameters).
OJ interfaceSchema() {
  OJ output{{"type", "object"},
            {"additionalProperties", false},
            {"required", {"type", "source"}},
            {"properties",
             {{"type", {{"description", "the output's type: the source must have exactly this type"},
                        {"enum", {"float", "vec2", "vec3", "vec4"}}}},
              {"source", defRef("source")},
              {"description", {{"type", "string"}}}}}};
  // An option fixed per instance (core/instance_options.h): the value's form follows the
  // type; choices, range and texture files are checked by the loader and resolve.
  OJ textureValue{{"anyOf", OJ::array({OJ{{"type", "string"}, {"minLength", 1}},
                                       OJ{{"type", "object"},
                                          {"additionalProperties", false},
                                          {"required", {"file"}},
                                          {"properties",
                                           {{"file", {{"type", "string"}, {"minLength", 1}}},
                                            {"wrap", {{"enum", {"repeat", "clamp", "mirror"}}}},
                                            {"filter", {{"enum", {"nearest", "linear", "mipmapped"}}}},
                                            {"color_space", {{"enum", {"srgb", "linear"}}}}}}}})}};
  OJ option{{"type", "object"},
            {"additionalProperties", false},
            {"required", {"type"}},
            {"properties",
             {{"type", {{"description", "choice: one of named values, read inside as the static `$name` (the index "
                                        "of the value chosen); number: read as the static `$name`; texture: a PNG "
                                        "(or builtin:<name>) a texture option written \"$name\" samples"},
                        {"enum", {"choice", "number", "texture"}}}},
              {"choices", {{"type", "array"}, {"minItems", 1}, {"uniqueItems", true}, {"items", defRef("identifier")}}},
              {"min", defRef("number")},
              {"max", defRef("number")},
              {"default", {{"description", "the value when an instance does not set it; without one, every instance "
                                           "must"},
                           {"anyOf", OJ::array({defRef("identifier"), defRef("number"), textureValue})}}},
              {"description", {{"type", "string"}}}}}};
  return OJ{{"description", "makes the graph a function graph: a node type for the graphs that import it; its "
                            "parameters are the inputs"},
            {"type", "object"},
            {"additionalProperties", false},
            {"required", {"outputs"}},
            {"properties",
             {{"description", {{"type", "string"}}},
              {"options", {{"description", "options fixed per instance: static choices and numbers, textures"},
                           {"type", "object"},
                           {"propertyNames", defRef("identifier")},
                           {"additionalProperties", option}}},
              {"outputs", {{"type", "object"},
                           {"minProperties", 1},
                           {"propertyNames", defRef("identifier")},
                           {"additionalProperties", output}}}}}};
}

OJ outputsSchema() {
  OJ stages = OJ::object();
  for (const auto& row : outputSlotTable()) {
    OJ& stage = stages[std::string(row.stageName)];
    if (stage.is_null()) stage = OJ{{"type", "object"}, {"additionalProperties", false}, {"properties", OJ::object()}};
    stage["properties"][std::string(row.portName)] =
        described(std::string(row.doc), defRef("source_" + std::string(typeName(row.type))));
  }
  return OJ{{"description", "shader output slots; at least one must be connected"},
            {"type", "object"},
            {"additionalProperties", false},
            {"minProperties", 1},
            {"properties", std::move(stages)}};
}

// A GLSL function node (nodes/glsl_function_node.h): its ports are its function's
// parameters, which the schema cannot see; its options are the file, the function, the
// reference and one texture per sampler2D parameter.
OJ fileNodeTypeSchema() {
  OJ options{{"type", "object"}, {"required", {"file", "function"}}};
  OJ props = OJ::object();
  for (const OptionSpec& o : glslFunctionOptions()) props[o.name] = optionSchema(NodeSpec{}, o);
  props["file"]["pattern"] = "^(?![/\\\\])(?!(.*/)?\\.\\.(/|$)).*\\.glsl$";
  props["function"]["pattern"] = kIdentifierPattern;
  props["reference"] = OJ{{"description", "output name -> formula in the expression language, for every output"},
                          {"type", "object"},
                          {"additionalProperties", {{"type", "string"}}}};
  options["properties"] = props;
  OptionSpec texture;
  texture.kind = OptionSpec::Kind::Texture;
  texture.doc = "the texture of a sampler2D parameter of the function";
  options["additionalProperties"] = optionSchema(NodeSpec{}, texture);
  OJ inputs{{"type", "object"},
            {"propertyNames", defRef("identifier")},
            {"additionalProperties", described("an input parameter of the function", defRef("source"))}};
  return OJ{{"properties", {{"options", options}, {"inputs", inputs}}}};
}

}  // namespace

nlohmann::ordered_json graphSchema(const Registry& registry) {
  std::vector<const NodeSpec*> specs = registry.all();  // sorted by type name

  OJ defs = OJ::object();
  defs["identifier"] = OJ{{"type", "string"}, {"pattern", kIdentifierPattern}, {"maxLength", 64}};
  defs["number"] = OJ{{"type", "number"}, {"minimum", -kFloat32Max}, {"maximum", kFloat32Max}};
  defs["node_output"] = OJ{{"description", "\"node.port\": an output of another node"},
                           {"type", "string"},
                           {"pattern", kNodeOutputPattern}};
  defs["parameter_ref"] = OJ{{"description", "\"$name\": a parameter"}, {"type", "string"}, {"pattern", kParameterPattern}};
  defs["reference"] = OJ{{"anyOf", {defRef("node_output"), defRef("parameter_ref")}}};
  defs["source"] = OJ{{"anyOf", {defRef("node_output"), defRef("parameter_ref"), defRef("number"), vectorLiteral(0)}}};
  defs["source_float"] = OJ{{"anyOf", {defRef("node_output"), defRef("parameter_ref"), defRef("number")}}};
  for (int n = 2; n <= 4; ++n)
    defs["source_vec" + std::to_string(n)] =
        OJ{{"anyOf", {defRef("node_output"), defRef("parameter_ref"), defRef("number"), vectorLiteral(n)}}};
  defs["parameter"] = parameterSchema();
  defs["editor"] = OJ{{"description", "the node's position in the editor canvas"},
                      {"type", "object"},
                      {"additionalProperties", false},
                      {"required", {"x", "y"}},
                      {"properties", {{"x", defRef("number")}, {"y", defRef("number")}}}};

  // Registered types and the types whose nodes take their ports from a file, by name.
  std::vector<std::pair<std::string, std::string>> types;  // name, doc
  for (const NodeSpec* s : specs) types.emplace_back(s->type, s->family + ": " + s->summary);
  for (const auto& name : registry.fileNodeTypeNames()) {
    types.emplace_back(name, "custom: a function of a .glsl file beside the graph; its parameters are the ports");
    defs["node_" + name] = fileNodeTypeSchema();
  }
  std::sort(types.begin(), types.end());
  OJ typeNames = OJ::array();
  OJ typeDocs = OJ::array();
  OJ perType = OJ::array();
  for (const auto& [name, doc] : types) {
    typeNames.push_back(name);
    typeDocs.push_back(doc);
    perType.push_back(OJ{{"if", {{"properties", {{"type", {{"const", name}}}}}, {"required", {"type"}}}},
                         {"then", defRef("node_" + name)}});
  }
  defs["node_type"] = OJ{{"description", "a registered node type (watergraph nodes)"},
                         {"enum", typeNames},
                         {"enumDescriptions", typeDocs}};
  defs["node"] = OJ{{"type", "object"},
                    {"additionalProperties", false},
                    {"required", {"id", "type"}},
                    {"properties",
                     {{"id", described("unique in the graph", defRef("identifier"))},
                      {"type", {{"anyOf", OJ::array({defRef("node_type"),
                                                        described("a name from the graph's \"imports\" (a subgraph)",
                                                                  defRef("identifier"))})}}},
                      {"options", {{"type", "object"}}},
                      {"inputs", {{"type", "object"}}},
                      {"editor", defRef("editor")}}},
                    {"allOf", perType}};
  for (const NodeSpec* s : specs) defs["node_" + s->type] = nodeTypeSchema(*s);

  OJ root = OJ::object();
  root["$schema"] = "http://json-schema.org/draft-07/schema#";
  root["title"] = "watergraph graph (format v1)";
  root["description"] =
      "A watergraph shader graph (docs/graph-format.md). Generated from the node registry by `watergraph schema`; "
      "do not edit by hand.";
  root["type"] = "object";
  root["additionalProperties"] = false;
  root["required"] = {"version", "name", "nodes"};
  // A function graph may leave its output slots out: it is used through its interface.
  // Without imports, every node type is a registered one (the schema cannot match a type
  // against the names a graph imports, so with imports any identifier passes here).
  OJ registeredTypesOnly{
      {"if", {{"not", {{"required", {"imports"}}}}}},
      {"then", {{"properties", {{"nodes", {{"items", {{"properties", {{"type", defRef("node_type")}}}}}}}}}}}};
  root["allOf"] = OJ::array({OJ{{"anyOf", OJ::array({OJ{{"required", {"outputs"}}}, OJ{{"required", {"interface"}}}})}},
                             registeredTypesOnly});
  root["properties"] = OJ{
      {"$schema", {{"description", "this schema, for editors; kept as is"}, {"type", "string"}}},
      {"version", {{"description", "the format version"}, {"const", kGraphFormatVersion}}},
      {"name", described("the graph's name", defRef("identifier"))},
      {"description", {{"type", "string"}}},
      {"view", {{"description", "how the frame is meant to be shown: the output transform's tone mapper and exposure "
                                "(EV); render, check and the editor use it unless --tonemap / --exposure say otherwise"},
                {"type", "object"},
                {"additionalProperties", false},
                {"properties",
                 {{"tonemap", {{"description", "none (clamp), aces, agx or neutral"},
                               {"enum", OJ(std::vector<std::string>(toneMapperNames().begin(), toneMapperNames().end()))}}},
                  {"exposure", {{"description", "EV: linear radiance x 2^exposure before the tone mapper"},
                                {"type", "number"},
                                {"minimum", kMinExposureEv},
                                {"maximum", kMaxExposureEv}}}}}}},
      {"imports", {{"description", "node type name -> path of a function graph, relative to this file (a subgraph)"},
                   {"type", "object"},
                   {"propertyNames", defRef("identifier")},
                   {"additionalProperties", {{"type", "string"}, {"minLength", 1}}}}},
      {"interface", interfaceSchema()},
      {"parameters", {{"description", "parameter name -> parameter (uniforms, or constants with static)"},
                      {"type", "object"},
                      {"propertyNames", defRef("identifier")},
                      {"additionalProperties", defRef("parameter")}}},
      {"presets", {{"description", "preset name -> {parameter: value, \"node.option\": value, "
                                   "\"instance/node.option\": value}: chosen with --preset, its values become the parameter "
                                   "defaults and the nodes' options"},
                   {"type", "object"},
                   {"propertyNames", defRef("identifier")},
                   {"additionalProperties",
                    {{"type", "object"},
                     {"propertyNames", {{"anyOf", {defRef("identifier"), {{"pattern", kPresetOptionPattern}}}}}},
                     // A node's option: the node type's option schema applies (checked by the compiler).
                     {"patternProperties", {{kPresetOptionPattern, OJ::object()}}},
                     {"additionalProperties", {{"anyOf", {defRef("number"), vectorLiteral(0)}}}}}}}},
      {"nodes", {{"type", "array"}, {"items", defRef("node")}}},
      {"outputs", defRef("outputs")},
      {"editor", defRef("editor_layout")}};
  defs["outputs"] = outputsSchema();
  // The editor's layout (docs/editor.md, Frames): compiling never reads it. That a frame's
  // nodes are the graph's, and in one frame each, is the loader's to check (WG013).
  defs["editor_layout"] = OJ{
      {"description", "the editor canvas's layout; compiling ignores it"},
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"frames", {{"description", "frame id -> a titled, commented box drawn around its nodes, moved with them"},
                    {"type", "object"},
                    {"propertyNames", defRef("identifier")},
                    {"additionalProperties",
                     {{"type", "object"},
                      {"additionalProperties", false},
                      {"required", {"nodes"}},
                      {"properties",
                       {{"title", {{"type", "string"}}},
                        {"comment", {{"description", "may hold line breaks"}, {"type", "string"}}},
                        {"nodes", {{"description", "the ids of the nodes it holds; a node lies in at most one frame"},
                                   {"type", "array"},
                                   {"minItems", 1},
                                   {"uniqueItems", true},
                                   {"items", defRef("identifier")}}}}}}}}}}}};
  root["definitions"] = defs;
  return root;
}

std::string graphSchemaText(const Registry& registry) { return graphSchema(registry).dump(2) + "\n"; }

}  // namespace wg
