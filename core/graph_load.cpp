// Graph format v1 (docs/graph-format.md): JSON events -> Graph, with no DOM of the file.
// Reports as many problems as it can in one pass; any error makes the result empty.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

#include "core/color_parameters.h"
#include "core/graph_io.h"
#include "core/file_read.h"
#include "core/graph_imports.h"
#include "core/graph_draft.h"
#include "core/instance_options.h"
#include "core/load_limits.h"
#include "core/number_format.h"
#include "core/suggest.h"

namespace wg {

namespace {

using nlohmann::json;

const char* kIdentifierRule =
    "(letters, digits and '_', not starting with a digit, at most 64)";
const char* kSourceForms =
    "an input is \"node.port\", \"$parameter\", a number, or an array of 2 to 4 numbers";

std::string jsonTypeName(json::value_t type) {
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

std::string article(std::string_view type) {
  if (type == "object" || type == "array") return "an " + std::string(type);
  return "a " + std::string(type);
}

std::string describeValue(const json& v) {
  std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

// The checks of the format, made on the drafts as the events arrive: every value's limits
// at once, each node when it ends, the rest when the file is complete (load()), reporting
// in the order a reader walks the format: limits, the graph's fields, version, name,
// parameters, presets, nodes, outputs.
constexpr char kTypeKeyText[] = "\"type\"";

// How many nodes to make room for before the events say: every node has a "type" key (so
// do parameters, a few). Growing the vector instead moved every Node built so far, into
// fresh pages, at each doubling: a quarter of a 1,000-node load. One scan of the text costs
// about a hundredth of its parse.
std::size_t expectedNodes(std::string_view text) {
  static const std::boyer_moore_horspool_searcher<const char*> kTypeKey(kTypeKeyText, kTypeKeyText + 6);
  std::size_t count = 0;
  for (auto at = text.begin(); count <= kMaxNodes; ++count) {
    at = std::search(at, text.end(), kTypeKey);
    if (at == text.end()) break;
    at += 6;
  }
  return count;
}

class Loader : public GraphDraftReader {
 public:
  Loader(const std::string& file, Diagnostics& diags, std::size_t expectedNodes)
      : file_(file), fileName_(file), diags_(diags) {
    nodes_.reserve(expectedNodes);
  }

  std::optional<Graph> load() {
    const size_t before = diags_.errorCount();
    Graph g;
    g.file = file_;
    const DraftValue& root = this->root();
    if (root.type != json::value_t::object) {
      diags_.error(DiagCode::WrongJsonType, ref(root.at),
                   "the graph must be a JSON object, found " + jsonTypeName(root.type));
      return std::nullopt;
    }
    diags_.append(limits_);

    checkKeys(root, "the graph",
              {"$schema", "version", "name", "description", "view", "imports", "interface", "parameters", "presets",
               "nodes", "outputs", "editor"});

    if (!loadVersion(root, g)) return std::nullopt;  // a newer format: the rest is moot

    if (auto* v = field(root, "$schema", json::value_t::string, "'$schema'"))
      g.schema = v->value.get<std::string>();

    if (!root.member("name")) {
      missing(root, "the graph is missing \"name\"");
    } else if (auto* v = field(root, "name", json::value_t::string, "'name'")) {
      g.name = v->value.get<std::string>();
      if (!isIdentifier(g.name))
        diags_.error(DiagCode::InvalidIdentifier, ref(v->at),
                     "graph name '" + g.name + "' is not an identifier " + kIdentifierRule);
    }
    if (auto* v = field(root, "description", json::value_t::string, "'description'"))
      g.description = v->value.get<std::string>();

    if (auto* v = field(root, "view", json::value_t::object, "'view'")) loadView(*v, g);
    if (auto* v = field(root, "imports", json::value_t::object, "'imports'")) loadImportList(*v, g);
    if (auto* v = field(root, "parameters", json::value_t::object, "'parameters'")) loadParameters(*v, g);
    if (auto* v = field(root, "presets", json::value_t::object, "'presets'")) loadPresets(*v, g);

    if (!root.member("nodes")) {
      missing(root, "the graph is missing \"nodes\"");
    } else if (auto* v = field(root, "nodes", json::value_t::array, "'nodes'")) {
      if (nodeCount() > kMaxNodes) {
        diags_.error(DiagCode::LimitExceeded, ref(v->at),
                     "the graph has " + std::to_string(nodeCount()) + " nodes; the limit is " +
                         std::to_string(kMaxNodes));
      } else {
        diags_.append(nodeDiags_);
        g.nodes = std::move(nodes_);
      }
    }

    // A function graph needs no output slots: it is used through its interface (and may
    // still connect slots, to be previewed on its own).
    if (!root.member("outputs")) {
      if (!root.member("interface")) missing(root, "the graph is missing \"outputs\"");
      g.outputsWhere = ref(root.at);
    } else if (auto* v = field(root, "outputs", json::value_t::object, "'outputs'")) {
      loadOutputs(*v, g);
    }
    if (auto* v = field(root, "interface", json::value_t::object, "'interface'")) loadInterface(*v, g);
    if (auto* v = field(root, "editor", json::value_t::object, "'editor'")) loadEditorLayout(*v, g);

    if (diags_.errorCount() > before) return std::nullopt;
    return g;
  }

 private:
  SourceRef ref(JsonPosition p) const { return SourceRef{fileName_, p.line, p.col}; }

  // Every string (and key) within the length limit, every number finite float32.
  void seenScalar(const JsonScalar& v, JsonPosition at) override {
    if (v.type == json::value_t::string) {
      if (v.string->size() > kMaxStringBytes)
        limits_.error(DiagCode::LimitExceeded, ref(at),
                      "string of " + std::to_string(v.string->size()) + " bytes is longer than the limit of " +
                          std::to_string(kMaxStringBytes));
    } else if (v.type == json::value_t::number_float) {
      // 64-bit integers are far inside float32's range (about 3.4e38).
      if (!std::isfinite(v.number) || std::fabs(v.number) > kFloat32Max)
        limits_.error(DiagCode::NonFiniteLiteral, ref(at), "number " + formatNumber(v.number) + " is outside float32 range");
    }
  }
  void seenKey(const std::string& name, JsonPosition at) override {
    if (name.size() > kMaxStringBytes)
      limits_.error(DiagCode::LimitExceeded, ref(at),
                    "key of " + std::to_string(name.size()) + " bytes is longer than the limit of " +
                        std::to_string(kMaxStringBytes));
  }

  // Every member key of the object `obj` is one of `allowed`; an error per other key.
  void checkKeys(const DraftValue& obj, std::string_view what, std::initializer_list<std::string_view> allowed,
                 const std::string& node = {}, Diagnostics* to = nullptr) {
    Diagnostics& out = to ? *to : diags_;
    std::string expected;
    for (const DraftValue& member : obj.members) {
      bool ok = false;
      for (std::string_view a : allowed) ok = ok || member.name == a;
      if (ok) continue;
      if (expected.empty())
        for (std::string_view a : allowed) {
          if (!expected.empty()) expected += ", ";
          expected += a;
        }
      out.error(DiagCode::UnknownField, ref(member.key),
                "unknown field '" + member.name + "' in " + std::string(what) + " (expected " + expected + ")", node);
    }
  }

  void missing(const DraftValue& obj, const std::string& message, const std::string& node = {},
               Diagnostics* to = nullptr) {
    (to ? *to : diags_).error(DiagCode::MissingField, ref(obj.at), message, node);
  }

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

  bool loadVersion(const DraftValue& root, Graph& g) {
    const DraftValue* it = root.member("version");
    const std::string expect = "this is graph format " + std::to_string(kGraphFormatVersion);
    if (!it) {
      diags_.error(DiagCode::UnsupportedVersion, ref(root.at), "missing \"version\": " + expect);
      return true;
    }
    if (!it->value.is_number_integer()) {
      diags_.error(DiagCode::UnsupportedVersion, ref(it->at),
                   "\"version\" must be an integer, found " + describeValue(it->value) + ": " + expect);
      return true;
    }
    long long v = it->value.is_number_unsigned()
                      ? static_cast<long long>(std::min<unsigned long long>(it->value.get<unsigned long long>(), 1ull << 62))
                      : it->value.get<long long>();
    if (v > kGraphFormatVersion) {
      diags_.error(DiagCode::UnsupportedVersion, ref(it->at),
                   "graph format version " + std::to_string(v) + " is newer than this watergraph supports (" +
                       std::to_string(kGraphFormatVersion) + ")");
      return false;
    }
    if (v < 1) {
      diags_.error(DiagCode::UnsupportedVersion, ref(it->at),
                   "graph format version " + std::to_string(v) + " does not exist: " + expect);
      return true;
    }
    g.version = static_cast<int>(v);
    return true;
  }

  void loadParameters(const DraftValue& params, Graph& g) {
    for (const DraftValue& pv : params.members) {
      const std::string& name = pv.name;
      Parameter p;
      p.name = name;
      p.where = ref(pv.key);
      bool ok = true;  // type, default, min and max are usable for the range check
      if (!isIdentifier(name))
        diags_.error(DiagCode::InvalidIdentifier, p.where,
                     "parameter name '" + name + "' is not an identifier " + kIdentifierRule);
      if (pv.type != json::value_t::object) {
        diags_.error(DiagCode::WrongJsonType, ref(pv.at),
                     "parameter '" + name + "' must be an object, found " + jsonTypeName(pv.type));
        continue;
      }
      const std::string what = "parameter '" + name + "'";
      checkKeys(pv, what, {"type", "default", "min", "max", "hint", "description", "static"});

      bool typeOk = readValueType(pv, what, "a parameter", p.type);
      ok = typeOk;

      const DraftValue* def = pv.member("default");
      if (!def) {
        missing(pv, what + " is missing \"default\"");
        ok = false;
      } else if (typeOk) {
        auto value = readValue(p, *def, "the default of " + what);
        if (value) p.defaultValue = std::move(*value);
        else ok = false;
      }

      if (auto* v = field(pv, "min", json::value_t::number_float, "'min' of " + what))
        p.min = v->value.get<double>();
      else if (pv.member("min"))
        ok = false;
      if (auto* v = field(pv, "max", json::value_t::number_float, "'max' of " + what))
        p.max = v->value.get<double>();
      else if (pv.member("max"))
        ok = false;
      if (p.min && p.max && *p.min > *p.max) {
        diags_.error(DiagCode::InvalidParameter, ref(pv.member("min")->at),
                     "the range of " + what + " is empty: min " + formatNumber(*p.min) + " is greater than max " +
                         formatNumber(*p.max));
      } else if (ok) {
        checkRange(p, p.defaultValue, def->at, "the default of " + what);
      }

      if (auto* v = field(pv, "hint", json::value_t::string, "'hint' of " + what)) {
        p.hint = v->value.get<std::string>();
        if (!isColorHint(p.hint)) {
          diags_.error(DiagCode::InvalidParameter, ref(v->at),
                       "unknown hint '" + p.hint + "' on " + what + " (the hints are \"color\" and \"hdr_color\")");
          p.hint.clear();
        } else if (typeOk && p.type != Type::Vec3 && p.type != Type::Vec4) {
          diags_.error(DiagCode::InvalidParameter, ref(v->at),
                       "the \"" + p.hint + "\" hint on " + what + " needs type vec3 or vec4, not " + std::string(typeName(p.type)));
        } else if (ok) {  // an sRGB colour's default and range lie within [0, 1]
          checkColor(p, p.defaultValue, def->at, "the default of " + what);
          for (const char* bound : {"min", "max"})
            if (const DraftValue* b = pv.member(bound))
              checkColor(p, {b->value.get<double>()}, b->at, "'" + std::string(bound) + "' of " + what);
        }
      }
      if (auto* v = field(pv, "description", json::value_t::string, "'description' of " + what))
        p.description = v->value.get<std::string>();
      if (auto* v = field(pv, "static", json::value_t::boolean, "'static' of " + what)) p.isStatic = v->value.get<bool>();

      g.parameters.push_back(std::move(p));
    }
  }

  // The "type" member of `obj` (`what`, a `kind`): float, vec2, vec3 or vec4 into `type`;
  // false after reporting it missing, not a string, or another type (WG011).
  bool readValueType(const DraftValue& obj, const std::string& what, const char* kind, Type& type) {
    if (!obj.member("type")) {
      missing(obj, what + " is missing \"type\"");
      return false;
    }
    auto* t = field(obj, "type", json::value_t::string, "'type' of " + what);
    if (!t) return false;
    const auto& typeText = t->value.get_ref<const std::string&>();
    auto parsed = parseType(typeText);
    if (!parsed || !isFloatScalarOrVector(*parsed)) {
      diags_.error(DiagCode::InvalidParameter, ref(t->at),
                   what + " has type '" + typeText + "'; " + kind + " is float, vec2, vec3 or vec4");
      return false;
    }
    type = *parsed;
    return true;
  }

  // A value for parameter `p`: a number for float, an array of n numbers for vecN; WG011
  // naming `label` otherwise.
  std::optional<std::vector<double>> readValue(const Parameter& p, const DraftValue& dv, const std::string& label) {
    const json& d = dv.value;
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
    diags_.error(DiagCode::InvalidParameter, ref(dv.at),
                 label + " must be " + shape + " for " + std::string(typeName(p.type)) + ", found " + describeValue(d));
    return std::nullopt;
  }

  // WG011 when a component of `xs` lies outside the parameter's [min, max].
  void checkColor(const Parameter& p, const std::vector<double>& xs, JsonPosition at, const std::string& label) {
    if (auto problem = colorRangeProblem(p.hint, xs, label)) diags_.error(DiagCode::InvalidParameter, ref(at), *problem);
  }

  void checkRange(const Parameter& p, const std::vector<double>& xs, JsonPosition at, const std::string& label) {
    if (!p.min && !p.max) return;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      double x = xs[i];
      if ((p.min && x < *p.min) || (p.max && x > *p.max)) {
        std::string range = "[" + (p.min ? formatNumber(*p.min) : std::string("-inf")) + ", " +
                            (p.max ? formatNumber(*p.max) : std::string("inf")) + "]";
        std::string comp = xs.size() > 1 ? " (component " + std::to_string(i) + ")" : std::string();
        diags_.error(DiagCode::InvalidParameter, ref(at), label + " " + formatNumber(x) + comp + " lies outside its range " + range);
        return;
      }
    }
  }

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
  std::optional<PresetValue> presetOption(const std::string& preset, const DraftValue& value, NodeIdsOfFile& nodeIds) {
    const std::string& key = value.name;
    size_t dot = key.find('.');
    PresetValue v;
    v.node = key.substr(0, dot);
    v.option = key.substr(dot + 1);
    v.where = ref(value.at);
    v.keyWhere = ref(value.key);
    bool pathValid = true;
    std::string first;  // the node of this graph: the whole path, or the instance it lies in
    for (size_t start = 0;;) {
      size_t slash = v.node.find('/', start);
      std::string segment = v.node.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
      pathValid = pathValid && isIdentifier(segment);
      if (start == 0) first = segment;
      if (slash == std::string::npos) break;
      start = slash + 1;
    }
    if (dot == std::string::npos || !pathValid || !isIdentifier(v.option)) {
      diags_.error(DiagCode::InvalidIdentifier, v.keyWhere,
                   "preset '" + preset + "' sets '" + key +
                       "': a node option is written \"node.option\" (inside a subgraph instance "
                       "\"instance/node.option\"), each an identifier " + kIdentifierRule);
      return std::nullopt;
    }
    if (nodeIds.complete && !nodeIds.ids.count(first)) {
      if (!nodeIds.suggester) nodeIds.suggester.emplace(std::vector<std::string>(nodeIds.ids.begin(), nodeIds.ids.end()));
      diags_.error(DiagCode::DanglingReference, v.keyWhere,
                   "preset '" + preset + "' sets an option of node '" + first + "', which the graph does not have" +
                       nodeIds.suggester->didYouMean(first));
      return std::nullopt;
    }
    v.optionValue = value.value;  // a preset's members are held as written (a Record)
    return v;
  }

  // "presets": {"calm": {"amplitude": 0.1, "detail.octaves": 2, ...}, ...}: each value
  // names a declared parameter and fits its type and range (checked after the parameters
  // are loaded), or names a node's option (checked by resolve against the node's type).
  void loadPresets(const DraftValue& presets, Graph& g) {
    NodeIdsOfFile nodeIds;
    nodeIds.complete = nodeCount() <= kMaxNodes;
    if (nodeIds.complete)
      for (const auto& n : nodes_) nodeIds.ids.insert(n.id);
    std::vector<std::string> paramNames;
    std::unordered_map<std::string_view, const Parameter*> parameterByName;  // not a scan per value
    for (const auto& p : g.parameters) {
      paramNames.push_back(p.name);
      parameterByName.emplace(p.name, &p);
    }
    NameSuggester parameterNames(std::move(paramNames));
    for (const DraftValue& pv : presets.members) {
      const std::string& name = pv.name;
      Preset preset;
      preset.name = name;
      preset.where = ref(pv.key);
      if (!isIdentifier(name))
        diags_.error(DiagCode::InvalidIdentifier, preset.where,
                     "preset name '" + name + "' is not an identifier " + kIdentifierRule);
      if (pv.type != json::value_t::object) {
        diags_.error(DiagCode::WrongJsonType, ref(pv.at),
                     "preset '" + name + "' must be an object of parameter values, found " + jsonTypeName(pv.type));
        continue;
      }
      for (const DraftValue& value : pv.members) {
        const std::string& param = value.name;
        if (param.find('.') != std::string::npos) {
          if (auto option = presetOption(name, value, nodeIds)) preset.values.push_back(std::move(*option));
          continue;
        }
        auto found = parameterByName.find(param);
        const Parameter* p = found == parameterByName.end() ? nullptr : found->second;
        if (!p) {
          diags_.error(DiagCode::UnknownParameter, ref(value.key),
                       "preset '" + name + "' sets parameter '" + param + "', which is not declared" +
                           parameterNames.didYouMean(param));
          continue;
        }
        if (p->defaultValue.empty()) continue;  // the parameter itself is broken (reported)
        const std::string label = "the value of '" + param + "' in preset '" + name + "'";
        auto values = readValue(*p, value, label);
        if (!values) continue;
        checkRange(*p, *values, value.at, label);
        checkColor(*p, *values, value.at, label);
        PresetValue v;
        v.parameter = param;
        v.value = std::move(*values);
        v.where = ref(value.at);
        v.keyWhere = ref(value.key);
        preset.values.push_back(std::move(v));
      }
      g.presets.push_back(std::move(preset));
    }
  }

  // "imports": {"foam": "lib/shore_foam.json"}: names (identifiers) for graph files, which
  // core/graph_imports.h loads; whether a name is free of node types is resolve's to say.
  // "view": {"tonemap": "agx", "exposure": 0.5}, both optional (none, 0 EV).
  void loadView(const DraftValue& vv, Graph& g) {
    checkKeys(vv, "'view'", {"tonemap", "exposure"});
    ViewTransform view;
    if (auto* t = field(vv, "tonemap", json::value_t::string, "the view's 'tonemap'")) {
      const std::string name = t->value.get<std::string>();
      if (auto mapper = parseToneMapper(name)) view.toneMapper = *mapper;
      else
        diags_.error(DiagCode::InvalidView, ref(t->at),
                     "unknown tone mapper '" + name + "' in 'view' (expected " + toneMapperList() + ")");
    }
    if (auto* e = field(vv, "exposure", json::value_t::number_float, "the view's 'exposure'")) {
      view.exposureEv = e->value.get<double>();
      if (!(view.exposureEv >= kMinExposureEv && view.exposureEv <= kMaxExposureEv))
        diags_.error(DiagCode::InvalidView, ref(e->at),
                     "exposure " + formatNumber(view.exposureEv) + " EV in 'view' is outside [" +
                         formatNumber(kMinExposureEv) + ", " + formatNumber(kMaxExposureEv) + "]");
    }
    g.view = view;
  }

  void loadImportList(const DraftValue& imports, Graph& g) {
    for (const DraftValue& iv : imports.members) {
      Import im;
      im.name = iv.name;
      im.where = ref(iv.key);
      im.pathWhere = ref(iv.at);
      if (!isIdentifier(im.name))
        diags_.error(DiagCode::InvalidIdentifier, im.where,
                     "import name '" + im.name + "' is not an identifier " + kIdentifierRule);
      if (iv.type != json::value_t::string) {
        diags_.error(DiagCode::WrongJsonType, ref(iv.at),
                     "import '" + im.name + "' must be a path (a string), found " + jsonTypeName(iv.type));
        continue;
      }
      im.path = iv.value.get<std::string>();
      if (im.path.empty()) {
        diags_.error(DiagCode::ImportMissing, im.pathWhere, "import '" + im.name + "' names no file (an empty path)");
        continue;
      }
      g.imports.push_back(std::move(im));
    }
  }

  // "interface": {"description": "...", "outputs": {"foam": {"type": "float", "source":
  // "mask.out", "description": "..."}}}: what an instance offers; its inputs are the
  // parameters. Sources are checked like output slots' (they refer to this graph's nodes).
  void loadInterface(const DraftValue& iv, Graph& g) {
    GraphInterface itf;
    itf.where = ref(iv.at);
    checkKeys(iv, "the interface", {"description", "options", "outputs"});
    if (auto* v = field(iv, "description", json::value_t::string, "the interface's 'description'"))
      itf.description = v->value.get<std::string>();
    const DraftValue* outs = iv.member("outputs");
    if (!outs) {
      missing(iv, "the interface is missing \"outputs\"");
    } else if (auto* ov = field(iv, "outputs", json::value_t::object, "the interface's 'outputs'")) {
      if (ov->members.empty())
        diags_.error(DiagCode::MissingField, ref(ov->at), "the interface declares no outputs; a subgraph needs at least one");
      for (const DraftValue& o : ov->members) loadInterfaceOutput(o, itf);
    }
    if (auto* ov = field(iv, "options", json::value_t::object, "the interface's 'options'"))
      for (const DraftValue& o : ov->members) loadInterfaceOption(o, g, itf);
    g.interface = std::move(itf);
  }

  // "options": {"pattern": {"type": "choice", "choices": ["lines", "cells"], "default":
  // "lines"}, "layers": {"type": "number", "min": 1, "max": 4}, "debris": {"type":
  // "texture", "default": "builtin:foam"}}: fixed per instance (core/instance_options.h).
  // A name is an identifier that no parameter has (both are read as `$name` inside);
  // a default must be a value the option accepts (WG092).
  void loadInterfaceOption(const DraftValue& o, const Graph& g, GraphInterface& itf) {
    InterfaceOption opt;
    opt.name = o.name;
    opt.where = ref(o.key);
    const std::string what = "interface option '" + o.name + "'";
    if (!isIdentifier(opt.name))
      diags_.error(DiagCode::InvalidIdentifier, opt.where, what + " is not an identifier " + kIdentifierRule);
    else if (g.findParameter(opt.name))
      diags_.error(DiagCode::InvalidParameter, opt.where,
                   what + " has the name of a parameter; both are read as '$" + opt.name + "', so choose another");
    if (o.type != json::value_t::object) {
      diags_.error(DiagCode::WrongJsonType, ref(o.at), what + " must be an object with \"type\", found " + jsonTypeName(o.type));
      return;
    }
    checkKeys(o, what, {"type", "choices", "min", "max", "default", "description"});
    const DraftValue* t = o.member("type");
    if (!t) return missing(o, what + " is missing \"type\" (choice, number or texture)");
    auto* tv = field(o, "type", json::value_t::string, "'type' of " + what);
    if (!tv) return;
    auto kind = parseInterfaceOptionKind(tv->value.get_ref<const std::string&>());
    if (!kind) {
      diags_.error(DiagCode::InvalidParameter, ref(tv->at),
                   what + " has type " + tv->value.dump() + "; an option is a choice, a number or a texture");
      return;
    }
    opt.kind = *kind;
    bool ok = true;
    auto only = [&](std::string_view key, bool allowed) {
      if (allowed || !o.member(key)) return;
      diags_.error(DiagCode::UnknownField, ref(o.member(key)->key),
                   what + ": '" + std::string(key) + "' is not a field of a " + std::string(interfaceOptionKindName(opt.kind)) + " option");
      ok = false;
    };
    only("choices", opt.kind == InterfaceOption::Kind::Choice);
    only("min", opt.kind == InterfaceOption::Kind::Number);
    only("max", opt.kind == InterfaceOption::Kind::Number);
    if (opt.kind == InterfaceOption::Kind::Choice) {
      const DraftValue* c = o.member("choices");
      if (!c) return missing(o, what + " is missing \"choices\" (the names an instance may choose)");
      bool names = c->value.is_array() && !c->value.empty();
      for (const auto& e : c->value) names = names && e.is_string() && isIdentifier(e.get_ref<const std::string&>());
      std::unordered_set<std::string> seen;
      if (names)
        for (const auto& e : c->value) names = seen.insert(e.get<std::string>()).second && names;
      if (!names) {
        diags_.error(DiagCode::InvalidParameter, ref(c->at),
                     "'choices' of " + what + " must be a non-empty array of distinct identifiers");
        return;
      }
      for (const auto& e : c->value) opt.choices.push_back(e.get<std::string>());
    }
    if (auto* v = field(o, "min", json::value_t::number_float, "'min' of " + what)) opt.min = v->value.get<double>();
    if (auto* v = field(o, "max", json::value_t::number_float, "'max' of " + what)) opt.max = v->value.get<double>();
    if (opt.min && opt.max && *opt.min > *opt.max) {
      diags_.error(DiagCode::InvalidParameter, opt.where, what + " has min > max");
      ok = false;
    }
    if (auto* v = field(o, "description", json::value_t::string, "'description' of " + what))
      opt.description = v->value.get<std::string>();
    if (const DraftValue* d = o.member("default")) {
      opt.defaultWhere = ref(d->at);
      if (std::string why = interfaceOptionValueProblem(opt, d->value); !why.empty()) {
        diags_.error(DiagCode::InstanceOptionValue, opt.defaultWhere, "the default of " + what + " " + why);
        ok = false;
      } else {
        opt.defaultValue = d->value;
      }
    }
    if (ok) itf.options.push_back(std::move(opt));
  }

  void loadInterfaceOutput(const DraftValue& o, GraphInterface& itf) {
    InterfaceOutput out;
    out.name = o.name;
    out.where = ref(o.key);
    const std::string what = "interface output '" + o.name + "'";
    if (!isIdentifier(out.name))
      diags_.error(DiagCode::InvalidIdentifier, out.where, what + " is not an identifier " + kIdentifierRule);
    if (o.type != json::value_t::object) {
      diags_.error(DiagCode::WrongJsonType, ref(o.at),
                   what + " must be an object with \"type\" and \"source\", found " + jsonTypeName(o.type));
      return;
    }
    checkKeys(o, what, {"type", "source", "description"});
    bool ok = readValueType(o, what, "an interface output", out.type);
    if (!o.member("source")) {
      missing(o, what + " is missing \"source\"");
      ok = false;
    } else if (const DraftValue* src = o.member("source")) {
      ok = parseSource(src->value, ref(src->at), out.source, {}, [&] { return "output '" + o.name + "'"; }, diags_) && ok;
    }
    if (auto* v = field(o, "description", json::value_t::string, "'description' of " + what))
      out.description = v->value.get<std::string>();
    if (ok) itf.outputs.push_back(std::move(out));
  }

  // "editor": {"frames": {"shore": {"title": "...", "comment": "...", "nodes": ["a", "b"]}}}:
  // the canvas's layout, which compiling never reads. Each frame lists at least one of the
  // graph's nodes, each once, and a node lies in at most one frame (WG013).
  void loadEditorLayout(const DraftValue& ev, Graph& g) {
    checkKeys(ev, "'editor'", {"frames"});
    auto* fv = field(ev, "frames", json::value_t::object, "the editor's 'frames'");
    if (!fv) return;
    // Sets, not scans: a hostile frame may list 10^5 ids.
    std::unordered_set<std::string_view> nodeIds;
    for (const auto& n : g.nodes) nodeIds.insert(n.id);
    std::unordered_map<std::string, std::string> frameOfNode;  // node id -> the frame listing it
    std::optional<NameSuggester> nodeNames;                     // made on the first unknown id
    const bool nodesKnown = nodeCount() <= kMaxNodes;           // else reported in the nodes' turn
    for (const DraftValue& f : fv->members) {
      Frame frame;
      frame.id = f.name;
      frame.where = ref(f.key);
      const std::string what = "frame '" + f.name + "'";
      if (!isIdentifier(frame.id))
        diags_.error(DiagCode::InvalidIdentifier, frame.where, "frame id '" + frame.id + "' is not an identifier " + kIdentifierRule);
      if (f.type != json::value_t::object) {
        diags_.error(DiagCode::WrongJsonType, ref(f.at), what + " must be an object with \"nodes\", found " + jsonTypeName(f.type));
        continue;
      }
      checkKeys(f, what, {"title", "comment", "nodes"});
      if (auto* v = field(f, "title", json::value_t::string, "'title' of " + what)) frame.title = v->value.get<std::string>();
      if (auto* v = field(f, "comment", json::value_t::string, "'comment' of " + what)) frame.comment = v->value.get<std::string>();
      const DraftValue* nv = f.member("nodes");
      if (!nv) {
        missing(f, what + " is missing \"nodes\" (the ids of the nodes it holds)");
        continue;
      }
      frame.nodesWhere = ref(nv->at);
      bool ids = nv->value.is_array();
      for (const auto& e : nv->value) ids = ids && e.is_string();
      if (!ids) {
        diags_.error(DiagCode::WrongJsonType, frame.nodesWhere, "'nodes' of " + what + " must be an array of node ids, found " + describeValue(nv->value));
        continue;
      }
      if (nv->value.empty()) diags_.error(DiagCode::InvalidFrame, frame.nodesWhere, what + " holds no nodes; a frame lists at least one");
      std::unordered_set<std::string_view> listed;
      for (const auto& e : nv->value) {
        const std::string& id = e.get_ref<const std::string&>();
        if (!listed.insert(id).second) {
          diags_.error(DiagCode::InvalidFrame, frame.nodesWhere, what + " lists node '" + id + "' twice");
          continue;
        }
        frame.nodes.push_back(id);
        if (!nodesKnown) continue;
        if (!nodeIds.count(id)) {
          if (!nodeNames) {
            std::vector<std::string> all;
            for (const auto& n : g.nodes) all.push_back(n.id);
            nodeNames.emplace(std::move(all));
          }
          diags_.error(DiagCode::InvalidFrame, frame.nodesWhere,
                       what + " lists node '" + id + "', which the graph does not have" + nodeNames->didYouMean(id));
        } else if (auto [it, fresh] = frameOfNode.emplace(id, frame.id); !fresh) {
          diags_.error(DiagCode::InvalidFrame, frame.nodesWhere,
                       what + " lists node '" + id + "', which frame '" + it->second + "' holds; a node lies in at most one frame");
        }
      }
      g.frames.push_back(std::move(frame));
    }
  }

  // One element of "nodes", as soon as it ends; its diagnostics wait in nodeDiags_ for
  // their turn (after the presets), its Node in nodes_.
  void node(DraftValue& nv) override {
    if (nodeCount() > kMaxNodes) return;  // reported alone in load()
    Diagnostics& out = nodeDiags_;
    if (nv.type != json::value_t::object) {
      out.error(DiagCode::WrongJsonType, ref(nv.at), "each node must be an object, found " + jsonTypeName(nv.type));
      return;
    }
    Node n;
    n.where = ref(nv.at);
    std::string label;  // for diagnostics: the id when it is a valid one
    if (!nv.member("id")) {
      missing(nv, "node is missing \"id\"", {}, &out);
    } else if (auto* v = field(nv, "id", json::value_t::string, "a node's 'id'", {}, &out)) {
      n.id = std::move(v->value.get_ref<std::string&>());
      n.idWhere = ref(v->at);
      if (isIdentifier(n.id))
        label = n.id;
      else
        out.error(DiagCode::InvalidIdentifier, n.idWhere, "node id '" + n.id + "' is not an identifier " + kIdentifierRule);
    }
    checkKeys(nv, "node", {"id", "type", "options", "inputs", "editor"}, label, &out);
    if (!nv.member("type")) {
      missing(nv, "node is missing \"type\"", label, &out);
    } else if (auto* v = field(nv, "type", json::value_t::string, "a node's 'type'", label, &out)) {
      n.type = std::move(v->value.get_ref<std::string&>());
      n.typeWhere = ref(v->at);
    }
    if (auto* v = field(nv, "options", json::value_t::object, "a node's 'options'", label, &out)) {
      n.options.reserve(v->members.size());
      for (DraftValue& o : v->members)
        n.options.push_back(NodeOption{std::move(o.name), std::move(o.value), ref(o.at), ref(o.key)});
    }
    if (auto* v = field(nv, "inputs", json::value_t::object, "a node's 'inputs'", label, &out)) {
      n.inputs.reserve(v->members.size());
      for (DraftValue& e : v->members) {
        NodeInput in;
        in.port = std::move(e.name);
        in.keyWhere = ref(e.key);
        if (parseSource(e.value, ref(e.at), in.source, label, [&] { return "input '" + in.port + "'"; }, out))
          n.inputs.push_back(std::move(in));
      }
    }
    if (auto* v = field(nv, "editor", json::value_t::object, "a node's 'editor'", label, &out)) {
      checkKeys(*v, "a node's editor position", {"x", "y"}, label, &out);
      std::array<double, 2> pos{0, 0};
      bool ok = true;
      const char* axes[2] = {"x", "y"};
      for (int a = 0; a < 2; ++a) {
        if (!v->member(axes[a])) {
          missing(*v, std::string("editor position is missing \"") + axes[a] + "\"", label, &out);
          ok = false;
        } else if (auto* c = field(*v, axes[a], json::value_t::number_float, std::string("'editor.") + axes[a] + "'",
                                   label, &out)) {
          pos[a] = c->value.get<double>();
        } else {
          ok = false;
        }
      }
      if (ok) n.editorPosition = pos;
    }
    nodes_.push_back(std::move(n));
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

  // A graph with nothing connected loads (the editor saves one when the user disconnects
  // every output, and it must open again); resolve refuses to compile it (WG031).
  void loadOutputs(const DraftValue& outputs, Graph& g) {
    const std::string expected(outputSlotList());
    g.outputsWhere = ref(outputs.at);
    for (const DraftValue& sv : outputs.members) {
      const std::string& stage = sv.name;
      bool knownStage = false;
      for (const auto& s : outputSlotTable()) knownStage |= stage == s.stageName;
      if (!knownStage) {
        diags_.error(DiagCode::UnknownOutputSlot, ref(sv.key), "unknown output stage '" + stage + "' " + expected);
        continue;
      }
      if (sv.type != json::value_t::object) {
        diags_.error(DiagCode::WrongJsonType, ref(sv.at),
                     "'outputs." + stage + "' must be an object, found " + jsonTypeName(sv.type));
        continue;
      }
      for (const DraftValue& slot : sv.members) {
        const std::string& name = slot.name;
        const OutputSlotRow* found = nullptr;
        for (const auto& s : outputSlotTable())
          if (stage == s.stageName && name == s.portName) found = &s;
        if (!found) {
          diags_.error(DiagCode::UnknownOutputSlot, ref(slot.key),
                       "unknown output slot '" + stage + "." + name + "' " + expected);
          continue;
        }
        GraphOutput out;
        out.slot = found->id;
        out.keyWhere = ref(slot.key);
        if (parseSource(slot.value, ref(slot.at), out.source, {}, [&] { return "output '" + stage + "." + name + "'"; },
                        diags_))
          g.outputs.push_back(std::move(out));
      }
    }
    std::stable_sort(g.outputs.begin(), g.outputs.end(),
                     [](const GraphOutput& a, const GraphOutput& b) { return a.slot < b.slot; });
  }

  const std::string& file_;
  const FileName fileName_;  // shared by every position of the graph
  Diagnostics& diags_;
  Diagnostics limits_;     // from every value as it comes; reported first
  Diagnostics nodeDiags_;  // from each node as it ends; reported in the nodes' turn
  std::vector<Node> nodes_;
};

}  // namespace

namespace {

// WG035 for a text over the file limit, before anything is copied or parsed.
bool withinFileLimit(std::string_view text, const std::string& file, Diagnostics& diags) {
  if (text.size() <= kMaxFileBytes) return true;
  diags.error(DiagCode::LimitExceeded, SourceRef{file, 0, 0},
              "the file is " + std::to_string(text.size()) + " bytes; the limit is 16 MiB");
  return false;
}

}  // namespace

std::optional<Graph> parseGraph(std::shared_ptr<const std::string> shared, const std::string& file, Diagnostics& diags) {
  std::string_view text = *shared;
  if (!withinFileLimit(text, file, diags)) return std::nullopt;
  // Positions after parsing need the lines (an expression's formula error is placed by the
  // escapes before it; SARIF counts UTF-16 columns): the text parsed is kept, never read twice.
  diags.keepSource(file, std::move(shared));
  Loader loader(file, diags, expectedNodes(text));
  if (!parseJsonEvents(text, file, diags, loader)) return std::nullopt;
  return loader.load();
}

std::optional<Graph> parseGraph(std::string_view text, const std::string& file, Diagnostics& diags) {
  if (!withinFileLimit(text, file, diags)) return std::nullopt;
  return parseGraph(std::make_shared<const std::string>(text), file, diags);
}

std::optional<Graph> loadGraphFile(const std::string& path, Diagnostics& diags) {
  auto text = readGraphFile(path, diags);
  if (!text) return std::nullopt;
  auto graph = parseGraph(std::make_shared<const std::string>(std::move(*text)), path, diags);
  if (graph && !loadImports(*graph, diags)) return std::nullopt;
  return graph;
}

std::optional<std::string> readGraphFile(const std::string& path, Diagnostics& diags) {
  // Opened once and read from that descriptor (core/file_read.h); a graph may come from a
  // pipe, so a FIFO is read too (a folder is refused).
  FileReadRule rule;
  rule.maxBytes = kMaxFileBytes;
  rule.regularOnly = false;
  FileReadFailure failure;
  auto text = readFileChecked(path, rule, &failure);
  if (text) return std::move(text->bytes);
  SourceRef where{path, 0, 0};
  if (failure.kind == FileReadFailure::Kind::TooLarge)
    diags.error(DiagCode::LimitExceeded, where, "'" + path + "' is larger than the limit of 16 MiB");
  else
    diags.error(DiagCode::FileRead, where, "cannot read '" + path + "': " + failure.why());
  return std::nullopt;
}

}  // namespace wg
