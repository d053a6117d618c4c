// Graph format v1 (docs/graph-format.md): JSON with positions -> Graph. Reports as many
// problems as it can in one pass; any error makes the result empty.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>

#include "core/graph_io.h"
#include "core/json_source.h"
#include "core/number_format.h"
#include "core/suggest.h"

namespace wg {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxFileBytes = 16u * 1024u * 1024u;
constexpr std::size_t kMaxNodes = 200000;
constexpr std::size_t kMaxStringBytes = 4096;
constexpr double kFloat32Max = 3.4028234663852886e38;

const char* kIdentifierRule =
    "(letters, digits and '_', not starting with a digit, at most 64)";
const char* kSourceForms =
    "an input is \"node.port\", \"$parameter\", a number, or an array of 2 to 4 numbers";

std::string jsonTypeName(const json& v) {
  switch (v.type()) {
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

std::string article(std::string_view type) {
  if (type == "object" || type == "array") return "an " + std::string(type);
  return "a " + std::string(type);
}

std::string describeValue(const json& v) {
  std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

class Loader {
 public:
  Loader(const JsonSource& js, const std::string& file, Diagnostics& diags)
      : js_(js), file_(file), diags_(diags) {}

  std::optional<Graph> load() {
    const size_t before = diags_.errorCount();
    Graph g;
    g.file = file_;
    const json& root = js_.root;
    if (!root.is_object()) {
      diags_.error(DiagCode::WrongJsonType, js_.value(""),
                   "the graph must be a JSON object, found " + jsonTypeName(root));
      return std::nullopt;
    }
    std::vector<PathStep> path;
    checkLimits(root, path);

    checkKeys(js_.entries[0], "the graph",
              {"$schema", "version", "name", "description", "parameters", "presets", "nodes", "outputs"});

    if (!loadVersion(root, g)) return std::nullopt;  // a newer format: the rest is moot

    if (auto* v = field(root, "", "$schema", json::value_t::string, "'$schema'"))
      g.schema = v->get<std::string>();

    if (!root.contains("name")) {
      missing("", "the graph is missing \"name\"");
    } else if (auto* v = field(root, "", "name", json::value_t::string, "'name'")) {
      g.name = v->get<std::string>();
      if (!isIdentifier(g.name))
        diags_.error(DiagCode::InvalidIdentifier, js_.value("/name"),
                     "graph name '" + g.name + "' is not an identifier " + kIdentifierRule);
    }
    if (auto* v = field(root, "", "description", json::value_t::string, "'description'"))
      g.description = v->get<std::string>();

    if (auto* v = field(root, "", "parameters", json::value_t::object, "'parameters'"))
      loadParameters(*v, g);
    if (auto* v = field(root, "", "presets", json::value_t::object, "'presets'"))
      loadPresets(*v, g);

    if (!root.contains("nodes")) {
      missing("", "the graph is missing \"nodes\"");
    } else if (auto* v = field(root, "", "nodes", json::value_t::array, "'nodes'")) {
      loadNodes(*v, g);
    }

    if (!root.contains("outputs")) {
      missing("", "the graph is missing \"outputs\"");
    } else if (auto* v = field(root, "", "outputs", json::value_t::object, "'outputs'")) {
      loadOutputs(*v, g);
    }

    if (diags_.errorCount() > before) return std::nullopt;
    return g;
  }

 private:
  // One step of the way down to a value: an object member's key, or an array index.
  struct PathStep {
    const std::string* key = nullptr;
    std::size_t index = 0;
  };
  static std::string pointerOf(const std::vector<PathStep>& path) {
    std::string ptr;
    for (const auto& step : path) {
      ptr += '/';
      ptr += step.key ? jsonPointerEscape(*step.key) : std::to_string(step.index);
    }
    return ptr;
  }

  // Every string (and key) within the length limit, every number finite float32. The JSON
  // pointer is made only for a value that breaks a limit (making one per value was a
  // tenth of a load).
  void checkLimits(const json& v, std::vector<PathStep>& path) {
    if (v.is_string()) {
      const auto& s = v.get_ref<const std::string&>();
      if (s.size() > kMaxStringBytes)
        diags_.error(DiagCode::LimitExceeded, js_.value(pointerOf(path)),
                     "string of " + std::to_string(s.size()) + " bytes is longer than the limit of " +
                         std::to_string(kMaxStringBytes));
    } else if (v.is_number_float()) {
      double x = v.get<double>();
      if (!std::isfinite(x) || std::fabs(x) > kFloat32Max)
        diags_.error(DiagCode::NonFiniteLiteral, js_.value(pointerOf(path)),
                     "number " + formatNumber(x) + " is outside float32 range");
    } else if (v.is_number_integer()) {
      // 64-bit integers are far inside float32's range (about 3.4e38).
    } else if (v.is_array()) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        path.push_back({nullptr, i});
        checkLimits(v[i], path);
        path.pop_back();
      }
    } else if (v.is_object()) {
      for (auto it = v.begin(); it != v.end(); ++it) {
        path.push_back({&it.key(), 0});
        if (it.key().size() > kMaxStringBytes)
          diags_.error(DiagCode::LimitExceeded, js_.key(pointerOf(path)),
                       "key of " + std::to_string(it.key().size()) +
                           " bytes is longer than the limit of " + std::to_string(kMaxStringBytes));
        checkLimits(it.value(), path);
        path.pop_back();
      }
    }
  }

  // Member keys of the object at `ptr`, in file order.
  std::vector<std::string> members(const json& obj, const std::string& ptr) const {
    std::vector<std::string> keys = js_.keysInOrder(ptr);
    if (!keys.empty()) return keys;
    for (auto m = obj.begin(); m != obj.end(); ++m) keys.push_back(m.key());
    return keys;
  }

  // Every member key of the object `obj` is one of `allowed`; an error per other key.
  // Reads the position tree's names: no pointer strings, no key copies.
  void checkKeys(const JsonSource::Entry& obj, const std::string& what, std::initializer_list<const char*> allowed,
                 const std::string& node = {}) {
    std::string expected;
    for (uint32_t c : obj.children) {
      const JsonSource::Entry& member = js_.entries[c];
      bool ok = false;
      for (const char* a : allowed) ok = ok || member.name == a;
      if (ok) continue;
      if (expected.empty())
        for (const char* a : allowed) {
          if (!expected.empty()) expected += ", ";
          expected += a;
        }
      diags_.error(DiagCode::UnknownField, js_.keyOf(&member),
                   "unknown field '" + member.name + "' in " + what + " (expected " + expected + ")", node);
    }
  }

  void missing(const std::string& objPtr, const std::string& message, const std::string& node = {}) {
    diags_.error(DiagCode::MissingField, js_.value(objPtr), message, node);
  }

  // The member `key` of `obj` if present and of JSON type `type` (any number type for
  // number_float); WG004 if present with another type.
  const json* field(const json& obj, const std::string& objPtr, const char* key, json::value_t type,
                    const std::string& label, const std::string& node = {}) {
    auto it = obj.find(key);
    if (it == obj.end()) return nullptr;
    const json& v = *it;
    bool ok = type == json::value_t::number_float ? v.is_number() : v.type() == type;
    if (!ok) {
      std::string want = type == json::value_t::number_float ? "number" : jsonTypeName(json(type));
      diags_.error(DiagCode::WrongJsonType, js_.value(objPtr + "/" + jsonPointerEscape(key)),
                   label + " must be " + article(want) + ", found " + jsonTypeName(v), node);
      return nullptr;
    }
    return &v;
  }

  bool loadVersion(const json& root, Graph& g) {
    auto it = root.find("version");
    const std::string expect = "this is graph format " + std::to_string(kGraphFormatVersion);
    if (it == root.end()) {
      diags_.error(DiagCode::UnsupportedVersion, js_.value(""), "missing \"version\": " + expect);
      return true;
    }
    if (!it->is_number_integer()) {
      diags_.error(DiagCode::UnsupportedVersion, js_.value("/version"),
                   "\"version\" must be an integer, found " + describeValue(*it) + ": " + expect);
      return true;
    }
    long long v = it->is_number_unsigned()
                      ? static_cast<long long>(std::min<unsigned long long>(
                            it->get<unsigned long long>(), 1ull << 62))
                      : it->get<long long>();
    if (v > kGraphFormatVersion) {
      diags_.error(DiagCode::UnsupportedVersion, js_.value("/version"),
                   "graph format version " + std::to_string(v) +
                       " is newer than this watergraph supports (" +
                       std::to_string(kGraphFormatVersion) + ")");
      return false;
    }
    if (v < 1) {
      diags_.error(DiagCode::UnsupportedVersion, js_.value("/version"),
                   "graph format version " + std::to_string(v) + " does not exist: " + expect);
      return true;
    }
    g.version = static_cast<int>(v);
    return true;
  }

  void loadParameters(const json& params, Graph& g) {
    for (const auto& name : members(params, "/parameters")) {
      const std::string ptr = "/parameters/" + jsonPointerEscape(name);
      const json& pv = params.at(name);
      Parameter p;
      p.name = name;
      p.where = js_.key(ptr);
      bool ok = true;  // type, default, min and max are usable for the range check
      if (!isIdentifier(name))
        diags_.error(DiagCode::InvalidIdentifier, p.where,
                     "parameter name '" + name + "' is not an identifier " + kIdentifierRule);
      if (!pv.is_object()) {
        diags_.error(DiagCode::WrongJsonType, js_.value(ptr),
                     "parameter '" + name + "' must be an object, found " + jsonTypeName(pv));
        continue;
      }
      const std::string what = "parameter '" + name + "'";
      checkKeys(*js_.entry(ptr), what, {"type", "default", "min", "max", "hint", "description", "static"});

      bool typeOk = false;
      if (!pv.contains("type")) {
        missing(ptr, what + " is missing \"type\"");
      } else if (auto* t = field(pv, ptr, "type", json::value_t::string, "'type' of " + what)) {
        auto type = parseType(t->get<std::string>());
        if (!type || !isFloatScalarOrVector(*type)) {
          diags_.error(DiagCode::InvalidParameter, js_.value(ptr + "/type"),
                       what + " has type '" + t->get<std::string>() +
                           "'; a parameter is float, vec2, vec3 or vec4");
        } else {
          p.type = *type;
          typeOk = true;
        }
      }
      ok = typeOk;

      if (!pv.contains("default")) {
        missing(ptr, what + " is missing \"default\"");
        ok = false;
      } else if (typeOk) {
        auto value = readValue(p, pv.at("default"), ptr + "/default", "the default of " + what);
        if (value) p.defaultValue = std::move(*value);
        else ok = false;
      }

      if (auto* v = field(pv, ptr, "min", json::value_t::number_float, "'min' of " + what))
        p.min = v->get<double>();
      else if (pv.contains("min"))
        ok = false;
      if (auto* v = field(pv, ptr, "max", json::value_t::number_float, "'max' of " + what))
        p.max = v->get<double>();
      else if (pv.contains("max"))
        ok = false;
      if (p.min && p.max && *p.min > *p.max) {
        diags_.error(DiagCode::InvalidParameter, js_.value(ptr + "/min"),
                     "the range of " + what + " is empty: min " + formatNumber(*p.min) +
                         " is greater than max " + formatNumber(*p.max));
      } else if (ok) {
        checkRange(p, p.defaultValue, ptr + "/default", "the default of " + what);
      }

      if (auto* v = field(pv, ptr, "hint", json::value_t::string, "'hint' of " + what)) {
        p.hint = v->get<std::string>();
        if (p.hint != "color") {
          diags_.error(DiagCode::InvalidParameter, js_.value(ptr + "/hint"),
                       "unknown hint '" + p.hint + "' on " + what + " (the only hint is \"color\")");
        } else if (typeOk && p.type != Type::Vec3 && p.type != Type::Vec4) {
          diags_.error(DiagCode::InvalidParameter, js_.value(ptr + "/hint"),
                       "the \"color\" hint on " + what + " needs type vec3 or vec4, not " +
                           std::string(typeName(p.type)));
        }
      }
      if (auto* v =
              field(pv, ptr, "description", json::value_t::string, "'description' of " + what))
        p.description = v->get<std::string>();
      if (auto* v = field(pv, ptr, "static", json::value_t::boolean, "'static' of " + what))
        p.isStatic = v->get<bool>();

      g.parameters.push_back(std::move(p));
    }
  }

  // A value for parameter `p` written at `valuePtr`: a number for float, an array of n
  // numbers for vecN; WG011 naming `label` otherwise.
  std::optional<std::vector<double>> readValue(const Parameter& p, const json& d, const std::string& valuePtr,
                                               const std::string& label) {
    const int n = componentCount(p.type);
    std::vector<double> xs;
    bool shapeOk = false;
    if (n == 1 && d.is_number()) {
      xs = {d.get<double>()};
      shapeOk = true;
    } else if (n > 1 && d.is_array() && static_cast<int>(d.size()) == n) {
      shapeOk = true;
      for (const auto& e : d) shapeOk = shapeOk && e.is_number();
      if (shapeOk)
        for (const auto& e : d) xs.push_back(e.get<double>());
    }
    if (shapeOk) return xs;
    std::string shape = n == 1 ? "a number" : "an array of " + std::to_string(n) + " numbers";
    diags_.error(DiagCode::InvalidParameter, js_.value(valuePtr),
                 label + " must be " + shape + " for " + std::string(typeName(p.type)) + ", found " +
                     describeValue(d));
    return std::nullopt;
  }

  // WG011 when a component of `xs` lies outside the parameter's [min, max].
  void checkRange(const Parameter& p, const std::vector<double>& xs, const std::string& valuePtr,
                  const std::string& label) {
    if (!p.min && !p.max) return;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      double x = xs[i];
      if ((p.min && x < *p.min) || (p.max && x > *p.max)) {
        std::string range = "[" + (p.min ? formatNumber(*p.min) : std::string("-inf")) + ", " +
                            (p.max ? formatNumber(*p.max) : std::string("inf")) + "]";
        std::string comp = xs.size() > 1 ? " (component " + std::to_string(i) + ")" : std::string();
        diags_.error(DiagCode::InvalidParameter, js_.value(valuePtr),
                     label + " " + formatNumber(x) + comp + " lies outside its range " + range);
        return;
      }
    }
  }

  // "presets": {"calm": {"amplitude": 0.1, ...}, ...}: each value names a declared
  // parameter and fits its type and range (checked after the parameters are loaded).
  void loadPresets(const json& presets, Graph& g) {
    std::vector<std::string> paramNames;
    for (const auto& p : g.parameters) paramNames.push_back(p.name);
    for (const auto& name : members(presets, "/presets")) {
      const std::string ptr = "/presets/" + jsonPointerEscape(name);
      const json& pv = presets.at(name);
      Preset preset;
      preset.name = name;
      preset.where = js_.key(ptr);
      if (!isIdentifier(name))
        diags_.error(DiagCode::InvalidIdentifier, preset.where,
                     "preset name '" + name + "' is not an identifier " + kIdentifierRule);
      if (!pv.is_object()) {
        diags_.error(DiagCode::WrongJsonType, js_.value(ptr),
                     "preset '" + name + "' must be an object of parameter values, found " + jsonTypeName(pv));
        continue;
      }
      for (const auto& param : members(pv, ptr)) {
        const std::string vptr = ptr + "/" + jsonPointerEscape(param);
        const Parameter* p = g.findParameter(param);
        if (!p) {
          diags_.error(DiagCode::UnknownParameter, js_.key(vptr),
                       "preset '" + name + "' sets parameter '" + param + "', which is not declared" +
                           didYouMean(param, paramNames));
          continue;
        }
        if (p->defaultValue.empty()) continue;  // the parameter itself is broken (reported)
        const std::string label = "the value of '" + param + "' in preset '" + name + "'";
        auto value = readValue(*p, pv.at(param), vptr, label);
        if (!value) continue;
        checkRange(*p, *value, vptr, label);
        preset.values.push_back({param, std::move(*value), js_.value(vptr)});
      }
      g.presets.push_back(std::move(preset));
    }
  }

  void loadNodes(const json& nodes, Graph& g) {
    if (nodes.size() > kMaxNodes) {
      diags_.error(DiagCode::LimitExceeded, js_.value("/nodes"),
                   "the graph has " + std::to_string(nodes.size()) + " nodes; the limit is " +
                       std::to_string(kMaxNodes));
      return;
    }
    g.nodes.reserve(nodes.size());
    // Positions come from each node's entry (found once), not from pointer look-ups from
    // the root; pointers are still made for the error paths.
    const JsonSource::Entry& nodesEntry = *js_.entry("/nodes");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const std::string ptr = "/nodes/" + std::to_string(i);
      const json& nv = nodes[i];
      const JsonSource::Entry& ne = js_.child(nodesEntry, i);
      if (!nv.is_object()) {
        diags_.error(DiagCode::WrongJsonType, js_.valueOf(&ne),
                     "each node must be an object, found " + jsonTypeName(nv));
        continue;
      }
      Node n;
      n.where = js_.valueOf(&ne);
      std::string label;  // for diagnostics: the id when it is a valid one
      if (!nv.contains("id")) {
        missing(ptr, "node is missing \"id\"");
      } else if (auto* v = field(nv, ptr, "id", json::value_t::string, "a node's 'id'")) {
        n.id = v->get<std::string>();
        n.idWhere = js_.valueOf(js_.member(ne, "id"));
        if (isIdentifier(n.id))
          label = n.id;
        else
          diags_.error(DiagCode::InvalidIdentifier, n.idWhere,
                       "node id '" + n.id + "' is not an identifier " + kIdentifierRule);
      }
      checkKeys(ne, "node", {"id", "type", "options", "inputs", "editor"}, label);
      if (!nv.contains("type")) {
        missing(ptr, "node is missing \"type\"", label);
      } else if (auto* v = field(nv, ptr, "type", json::value_t::string, "a node's 'type'", label)) {
        n.type = v->get<std::string>();
        n.typeWhere = js_.valueOf(js_.member(ne, "type"));
      }
      if (auto* v = field(nv, ptr, "options", json::value_t::object, "a node's 'options'", label)) {
        for (uint32_t c : js_.member(ne, "options")->children) {
          const JsonSource::Entry& o = js_.entries[c];
          n.options.push_back(NodeOption{o.name, v->at(o.name), js_.valueOf(&o), js_.keyOf(&o)});
        }
      }
      if (auto* v = field(nv, ptr, "inputs", json::value_t::object, "a node's 'inputs'", label)) {
        const JsonSource::Entry& inputs = *js_.member(ne, "inputs");
        n.inputs.reserve(inputs.children.size());
        for (uint32_t c : inputs.children) {
          const JsonSource::Entry& e = js_.entries[c];
          NodeInput in;
          in.port = e.name;
          in.keyWhere = js_.keyOf(&e);
          if (parseSource(v->at(e.name), js_.valueOf(&e), in.source, label, [&] { return "input '" + e.name + "'"; }))
            n.inputs.push_back(std::move(in));
        }
      }
      if (auto* v = field(nv, ptr, "editor", json::value_t::object, "a node's 'editor'", label)) {
        const std::string edPtr = ptr + "/editor";
        checkKeys(*js_.member(ne, "editor"), "a node's editor position", {"x", "y"}, label);
        std::array<double, 2> pos{0, 0};
        bool ok = true;
        const char* axes[2] = {"x", "y"};
        for (int a = 0; a < 2; ++a) {
          if (!v->contains(axes[a])) {
            missing(edPtr, std::string("editor position is missing \"") + axes[a] + "\"", label);
            ok = false;
          } else if (auto* c = field(*v, edPtr, axes[a], json::value_t::number_float,
                                     std::string("'editor.") + axes[a] + "'", label)) {
            pos[a] = c->get<double>();
          } else {
            ok = false;
          }
        }
        if (ok) n.editorPosition = pos;
      }
      g.nodes.push_back(std::move(n));
    }
  }

  // `port()` names the input or output for the diagnostic, made only when there is one.
  template <typename PortLabel>
  bool parseSource(const json& v, SourceRef where, InputSource& out, const std::string& node, const PortLabel& port) {
    out.where = std::move(where);
    if (v.is_string()) {
      const auto& s = v.get_ref<const std::string&>();
      if (!s.empty() && s[0] == '$') {
        std::string name = s.substr(1);
        if (isIdentifier(name)) {
          out.kind = InputSource::Kind::Parameter;
          out.parameter = name;
          return true;
        }
      } else {
        auto dot = s.find('.');
        if (dot != std::string::npos && s.find('.', dot + 1) == std::string::npos) {
          std::string nodeId = s.substr(0, dot), portName = s.substr(dot + 1);
          if (isIdentifier(nodeId) && isIdentifier(portName)) {
            out.kind = InputSource::Kind::NodeOutput;
            out.node = nodeId;
            out.port = portName;
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
    diags_.error(DiagCode::InvalidReference, out.where,
                 "invalid input " + describeValue(v) + ": " + kSourceForms, node, port());
    return false;
  }

  void loadOutputs(const json& outputs, Graph& g) {
    const std::string expected(outputSlotList());
    int connected = 0;
    const size_t errorsBefore = diags_.errorCount();
    for (const auto& stage : members(outputs, "/outputs")) {
      const std::string stagePtr = "/outputs/" + jsonPointerEscape(stage);
      bool knownStage = false;
      for (const auto& s : outputSlotTable()) knownStage |= stage == s.stageName;
      if (!knownStage) {
        diags_.error(DiagCode::UnknownOutputSlot, js_.key(stagePtr),
                     "unknown output stage '" + stage + "' " + expected);
        continue;
      }
      const json& sv = outputs.at(stage);
      if (!sv.is_object()) {
        diags_.error(DiagCode::WrongJsonType, js_.value(stagePtr),
                     "'outputs." + stage + "' must be an object, found " + jsonTypeName(sv));
        continue;
      }
      for (const auto& name : members(sv, stagePtr)) {
        const std::string slotPtr = stagePtr + "/" + jsonPointerEscape(name);
        const OutputSlotRow* found = nullptr;
        for (const auto& s : outputSlotTable())
          if (stage == s.stageName && name == s.portName) found = &s;
        if (!found) {
          diags_.error(DiagCode::UnknownOutputSlot, js_.key(slotPtr),
                       "unknown output slot '" + stage + "." + name + "' " + expected);
          continue;
        }
        ++connected;
        GraphOutput out;
        out.slot = found->id;
        out.keyWhere = js_.key(slotPtr);
        if (parseSource(sv.at(name), js_.value(slotPtr), out.source, {},
                        [&] { return "output '" + stage + "." + name + "'"; }))
          g.outputs.push_back(std::move(out));
      }
    }
    std::stable_sort(g.outputs.begin(), g.outputs.end(),
                     [](const GraphOutput& a, const GraphOutput& b) { return a.slot < b.slot; });
    if (connected == 0 && diags_.errorCount() == errorsBefore)  // else the cause is reported
      diags_.error(DiagCode::NoOutputs, js_.value("/outputs"), "the graph connects no outputs");
  }

  const JsonSource& js_;
  const std::string& file_;
  Diagnostics& diags_;
};

}  // namespace

std::optional<Graph> parseGraph(std::string_view text, const std::string& file, Diagnostics& diags) {
  if (text.size() > kMaxFileBytes) {
    diags.error(DiagCode::LimitExceeded, SourceRef{file, 0, 0},
                "the file is " + std::to_string(text.size()) + " bytes; the limit is 16 MiB");
    return std::nullopt;
  }
  auto js = parseJsonWithPositions(text, file, diags);
  if (!js) return std::nullopt;
  return Loader(*js, file, diags).load();
}

std::optional<Graph> loadGraphFile(const std::string& path, Diagnostics& diags) {
  auto text = readGraphFile(path, diags);
  if (!text) return std::nullopt;
  return parseGraph(*text, path, diags);
}

std::optional<std::string> readGraphFile(const std::string& path, Diagnostics& diags) {
  SourceRef where{path, 0, 0};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    diags.error(DiagCode::FileRead, where, "cannot read '" + path + "': " + std::strerror(EISDIR));
    return std::nullopt;
  }
  errno = 0;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    int err = errno ? errno : ENOENT;
    diags.error(DiagCode::FileRead, where, "cannot read '" + path + "': " + std::strerror(err));
    return std::nullopt;
  }
  std::string text;
  char buf[65536];
  bool tooBig = false;
  while (true) {
    std::size_t n = std::fread(buf, 1, sizeof buf, f);
    text.append(buf, n);
    if (text.size() > kMaxFileBytes) {
      tooBig = true;
      break;
    }
    if (n < sizeof buf) break;
  }
  bool readError = std::ferror(f) != 0;
  int err = errno;
  std::fclose(f);
  if (tooBig) {
    diags.error(DiagCode::LimitExceeded, where,
                "'" + path + "' is larger than the limit of 16 MiB");
    return std::nullopt;
  }
  if (readError) {
    diags.error(DiagCode::FileRead, where,
                "cannot read '" + path + "': " + std::strerror(err ? err : EIO));
    return std::nullopt;
  }
  return text;
}

}  // namespace wg
