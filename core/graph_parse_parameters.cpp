// Parsing a graph file: "parameters" (typed values with a default, a range, a colour hint)
// and "presets" (named sets of parameter values and node options).
#include <string>
#include <unordered_map>

#include "core/color_parameters.h"
#include "core/graph_parser.h"
#include "core/load_limits.h"
#include "core/number_format.h"
#include "core/suggest.h"

namespace wg::parsing {

void GraphParser::loadParameters(const DraftValue& params, Graph& g) {
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
bool GraphParser::readValueType(const DraftValue& obj, const std::string& what, const char* kind, Type& type) {
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
std::optional<std::vector<double>> GraphParser::readValue(const Parameter& p, const DraftValue& dv, const std::string& label) {
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
void GraphParser::checkColor(const Parameter& p, const std::vector<double>& xs, JsonPosition at, const std::string& label) {
  if (auto problem = colorRangeProblem(p.hint, xs, label)) diags_.error(DiagCode::InvalidParameter, ref(at), *problem);
}

void GraphParser::checkRange(const Parameter& p, const std::vector<double>& xs, JsonPosition at, const std::string& label) {
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

std::optional<PresetValue> GraphParser::presetOption(const std::string& preset, const DraftValue& value, NodeIdsOfFile& nodeIds) {
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
void GraphParser::loadPresets(const DraftValue& presets, Graph& g) {
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

}  // namespace wg::parsing
