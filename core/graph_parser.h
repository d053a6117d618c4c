#pragma once
// The parser of one graph file (parseGraph, core/graph_parse.h) as a class shared by the
// files that hold its parts; internal to core: nothing but core/graph_parse*.cpp includes
// it. One file was 940 lines; each part of the format is now a file of one job (the class
// below lists its members by file):
//   graph_parse.cpp             the entry points; the graph's fields in order, the limits
//                               of every value, version, view and the import list
//   graph_parse_parameters.cpp  parameters and presets
//   graph_parse_nodes.cpp       each node as it ends; the output slots
//   graph_parse_interface.cpp   a function graph's interface (outputs and options)
//   graph_parse_frames.cpp      the editor's frames
// Following the imports is not parsing: core/graph_imports.h does it, above this.
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/graph_draft.h"
#include "core/suggest.h"

namespace wg::parsing {

using nlohmann::json;

inline constexpr const char* kIdentifierRule =
    "(letters, digits and '_', not starting with a digit, at most 64)";
inline constexpr const char* kSourceForms =
    "an input is \"node.port\", \"$parameter\", a number, or an array of 2 to 4 numbers";

inline std::string jsonTypeName(json::value_t type) {
  switch (type) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "object";
    case json::value_t::array: return "array";
    case json::value_t::string: return "string";
    case json::value_t::boolean: return "boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "number";
    default: return "value";
  }
}

inline std::string article(std::string_view type) {
  if (type == "object" || type == "array") return "an " + std::string(type);
  return "a " + std::string(type);
}

inline std::string describeValue(const json& v) {
  std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

// The checks of the format, made on the drafts as the events arrive: every value's limits

// in the order a reader walks the format: limits, the graph's fields, version, name,
// parameters, presets, nodes, outputs.
constexpr char kTypeKeyText[] = "\"type\"";

class GraphParser : public GraphDraftReader {
 public:
  GraphParser(const std::string& file, Diagnostics& diags, std::size_t expectedNodes)
      : file_(file), fileName_(file), diags_(diags) {
    nodes_.reserve(expectedNodes);
  }

  std::optional<Graph> load();

 private:
  // A preset member "node.option": the node is one of the graph's (an identifier before
  // the first '.', an identifier after it), or a node inside one of its subgraph instances
  // ("instance/node.option", nested "a/b/node.option": identifiers joined by '/', the first
  // a node of this graph); the option and its value, and the nodes inside the instance, are
  // checked by resolve as for an option written on the node.
  struct NodeIdsOfFile {
    bool complete = false;  // false when the file has more nodes than the limit (reported)
    std::unordered_set<std::string_view> ids;
    std::optional<NameSuggester> suggester;  // made on the first unknown id
  };

  // graph_parse.cpp: the graph's fields in order; limits; version, view, imports
  void seenScalar(const JsonScalar& v, JsonPosition at) override;
  void seenKey(const std::string& name, JsonPosition at) override;
  void checkKeys(const DraftValue& obj, std::string_view what, std::initializer_list<std::string_view> allowed,
                 const std::string& node = {}, Diagnostics* to = nullptr);
  void missing(const DraftValue& obj, const std::string& message, const std::string& node = {},
               Diagnostics* to = nullptr);
  bool loadVersion(const DraftValue& root, Graph& g);
  void loadView(const DraftValue& vv, Graph& g);
  void loadImportList(const DraftValue& imports, Graph& g);

  // graph_parse_parameters.cpp: parameters and presets
  void loadParameters(const DraftValue& params, Graph& g);
  bool readValueType(const DraftValue& obj, const std::string& what, const char* kind, Type& type);
  std::optional<std::vector<double>> readValue(const Parameter& p, const DraftValue& dv, const std::string& label);
  void checkColor(const Parameter& p, const std::vector<double>& xs, JsonPosition at, const std::string& label);
  void checkRange(const Parameter& p, const std::vector<double>& xs, JsonPosition at, const std::string& label);
  std::optional<PresetValue> presetOption(const std::string& preset, const DraftValue& value, NodeIdsOfFile& nodeIds);
  void loadPresets(const DraftValue& presets, Graph& g);

  // graph_parse_nodes.cpp: each node as it ends; the output slots
  void node(DraftValue& nv) override;
  void loadOutputs(const DraftValue& outputs, Graph& g);

  // graph_parse_interface.cpp: a function graph's interface
  void loadInterface(const DraftValue& iv, Graph& g);
  void loadInterfaceOption(const DraftValue& o, const Graph& g, GraphInterface& itf);
  void loadInterfaceOutput(const DraftValue& o, GraphInterface& itf);

  // graph_parse_frames.cpp: the editor's frames
  void loadEditorLayout(const DraftValue& ev, Graph& g);

  SourceRef ref(JsonPosition p) const { return SourceRef{fileName_, p.line, p.col}; }

  // The member `key` of `obj` if present and of JSON type `type` (any number type for
  // number_float); WG004 if present with another type.
  // `label` is a view: callers pass literals, and a std::string of one was a heap block
  // per node and field.
  template <typename Draft>  // DraftValue or const DraftValue
  Draft* field(Draft& obj, std::string_view key, json::value_t type, std::string_view label,
               const std::string& node = {}, Diagnostics* to = nullptr) {
    Draft* v = obj.member(key);
    if (!v) return nullptr;
    bool ok = type == json::value_t::number_float ? isNumber(v->type) : v->type == type;
    if (!ok) {
      std::string want = type == json::value_t::number_float ? "number" : jsonTypeName(type);
      (to ? *to : diags_)
          .error(DiagCode::WrongJsonType, ref(v->at),
                 std::string(label) + " must be " + article(want) + ", found " + jsonTypeName(v->type), node);
      return nullptr;
    }
    return v;
  }

  static bool isNumber(json::value_t t) {
    return t == json::value_t::number_integer || t == json::value_t::number_unsigned || t == json::value_t::number_float;
  }

  // `port()` names the input or output for the diagnostic, made only when there is one.
  template <typename PortLabel>
  bool parseSource(const json& v, SourceRef where, InputSource& out, const std::string& node, const PortLabel& port,
                   Diagnostics& diags) {
    out.where = std::move(where);
    if (v.is_string()) {
      const auto& s = v.get_ref<const std::string&>();
      if (!s.empty() && s[0] == '$') {
        std::string name = s.substr(1);
        if (isIdentifier(name)) {
          out.kind = InputSource::Kind::Parameter;
          out.name = name;
          return true;
        }
      } else {
        auto dot = s.find('.');
        if (dot != std::string::npos && s.find('.', dot + 1) == std::string::npos) {
          std::string_view whole(s), nodeId = whole.substr(0, dot), portName = whole.substr(dot + 1);
          if (isIdentifier(nodeId) && isIdentifier(portName)) {
            out.kind = InputSource::Kind::NodeOutput;
            out.name.assign(nodeId);
            out.port.assign(portName);
            return true;
          }
        }
      }
    } else if (v.is_number()) {
      out.kind = InputSource::Kind::Literal;
      out.literal = {v.get<double>()};
      return true;
    } else if (v.is_array() && v.size() >= 2 && v.size() <= 4) {
      bool allNumbers = true;
      for (const auto& e : v) allNumbers = allNumbers && e.is_number();
      if (allNumbers) {
        out.kind = InputSource::Kind::Literal;
        for (const auto& e : v) out.literal.push_back(e.get<double>());
        return true;
      }
    }
    diags.error(DiagCode::InvalidReference, out.where, "invalid input " + describeValue(v) + ": " + kSourceForms, node,
                port());
    return false;
  }

  const std::string& file_;
  const FileName fileName_;  // shared by every position of the graph
  Diagnostics& diags_;
  Diagnostics limits_;     // from every value as it comes; reported first
  Diagnostics nodeDiags_;  // from each node as it ends; reported in the nodes' turn
  std::vector<Node> nodes_;
};

}  // namespace wg::parsing
