// Parsing a graph file: a function graph's "interface", what an instance of it offers
// (its outputs, and the options fixed per instance).
#include <string>
#include <unordered_set>

#include "core/graph_parser.h"
#include "core/instance_options.h"

namespace wg::parsing {

// "interface": {"description": "...", "outputs": {"foam": {"type": "float", "source":
// "mask.out", "description": "..."}}}: what an instance offers; its inputs are the
// parameters. Sources are checked like output slots' (they refer to this graph's nodes).
void GraphParser::loadInterface(const DraftValue& iv, Graph& g) {
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
void GraphParser::loadInterfaceOption(const DraftValue& o, const Graph& g, GraphInterface& itf) {
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

void GraphParser::loadInterfaceOutput(const DraftValue& o, GraphInterface& itf) {
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

}  // namespace wg::parsing
