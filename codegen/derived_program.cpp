#include "codegen/derived_program.h"

#include <algorithm>
#include <new>
#include <stdexcept>

#include "codegen/cpu_backend.h"
#include "codegen/derived_vocabulary.h"
#include "codegen/frequency.h"
#include "core/interface_tables.h"
#include "core/node_options.h"
#include "core/port_typing.h"

namespace wg {
namespace {

nlohmann::json valueRefJson(const Program& p, const ValueRef& r) {
  switch (r.kind) {
    case ValueRef::Kind::Op: return {{"op", r.index}, {"port", r.port}};
    case ValueRef::Kind::Param: return {{"parameter", p.parameters[static_cast<size_t>(r.index)].name}};
    case ValueRef::Kind::Builtin: return {{"builtin", std::string(builtinName(static_cast<Builtin>(r.index)))}};
    case ValueRef::Kind::Const: {
      nlohmann::json c = nlohmann::json::array();
      for (int i = 0; i < r.constant().size(); ++i) c.push_back(r.constant()[i]);
      return {{"constant", c}, {"type", std::string(typeName(r.constant().type))}};
    }
    case ValueRef::Kind::None: break;
  }
  throw std::logic_error("derivedToJson: unset value reference");
}

std::optional<Type> typeOfJson(const nlohmann::json& j) {
  if (!j.is_string()) return std::nullopt;
  return parseType(j.get<std::string>());
}

}  // namespace

DerivedValue extractDerived(const Program& program, int root, int port) {
  const std::vector<Frequency> f = analyseFrequency(program);
  const size_t n = program.ops.size();
  std::vector<bool> in(n, false);
  in[static_cast<size_t>(root)] = true;
  for (size_t i = static_cast<size_t>(root) + 1; i-- > 0;) {
    if (!in[i]) continue;
    const Op& op = program.ops[i];
    if (f[i] > Frequency::PerDraw || (op.spec->isSource && !op.spec->isUniformSource))
      throw std::logic_error("extractDerived: op '" + op.nodeId + "' is not per-draw");
    for (const auto& v : op.inputs)
      if (v.kind == ValueRef::Kind::Op) in[static_cast<size_t>(v.index)] = true;
  }
  DerivedValue d;
  d.program.graphName = program.graphName;
  d.program.file = program.file;
  d.program.directory = program.directory;
  d.program.parameters = program.parameters;
  std::vector<int> renumber(n, -1);
  for (size_t i = 0; i < n; ++i) {
    if (!in[i]) continue;
    Op op = program.ops[i];
    for (auto& v : op.inputs)
      if (v.kind == ValueRef::Kind::Op) v.index = renumber[static_cast<size_t>(v.index)];
    op.stage = 0;
    renumber[i] = static_cast<int>(d.program.ops.size());
    d.program.ops.push_back(std::move(op));
  }
  d.value = ValueRef::op(renumber[static_cast<size_t>(root)], port);
  d.type = program.ops[static_cast<size_t>(root)].outputTypes.at(static_cast<size_t>(port));
  return d;
}

Value evaluateDerived(const DerivedValue& d, const EvalEnvironment& env, const std::vector<Value>& parameters) {
  CpuResult r = evaluateProgram(d.program, env, parameters);
  return r.opOutputs.at(static_cast<size_t>(d.value.index)).at(static_cast<size_t>(d.value.port));
}

nlohmann::json derivedToJson(const DerivedValue& d) {
  nlohmann::json ops = nlohmann::json::array();
  for (const Op& op : d.program.ops) {
    nlohmann::json inputs = nlohmann::json::array(), inTypes = nlohmann::json::array(),
                   outTypes = nlohmann::json::array();
    for (const auto& v : op.inputs) inputs.push_back(valueRefJson(d.program, v));
    for (Type t : op.inputTypes) inTypes.push_back(std::string(typeName(t)));
    for (Type t : op.outputTypes) outTypes.push_back(std::string(typeName(t)));
    ops.push_back({{"node", op.nodeId},
                   {"type", op.spec->type},
                   {"options", op.options()},
                   {"inputs", inputs},
                   {"input_types", inTypes},
                   {"output_types", outTypes}});
  }
  return {{"type", std::string(typeName(d.type))},
          {"value", {{"op", d.value.index}, {"port", d.value.port}}},
          {"ops", ops}};
}

namespace {

// The type of what an input reads, for checking the op as the compiler typed it.
Type sourceType(const DerivedValue& d, const ValueRef& r) {
  switch (r.kind) {
    case ValueRef::Kind::Op: return d.program.ops[static_cast<size_t>(r.index)].outputTypes[static_cast<size_t>(r.port)];
    case ValueRef::Kind::Param: return d.program.parameters[static_cast<size_t>(r.index)].type;
    case ValueRef::Kind::Builtin: return builtinType(static_cast<Builtin>(r.index));
    case ValueRef::Kind::Const: return r.constant().type;
    case ValueRef::Kind::None: break;
  }
  return Type::Invalid;
}

std::optional<DerivedValue> readDerived(const nlohmann::json& j, const Registry& registry,
                                        const std::vector<ProgramParameter>& parameters, std::string& error) {
  auto fail = [&](std::string why) -> std::optional<DerivedValue> {
    error = std::move(why);
    return std::nullopt;
  };
  if (!j.is_object() || !j.contains("ops") || !j["ops"].is_array() || !j.contains("value") || !j["value"].is_object())
    return fail("a derived value needs \"ops\" and \"value\"");
  DerivedValue d;
  d.program.parameters = parameters;
  auto type = typeOfJson(j.value("type", nlohmann::json()));
  if (!type) return fail("unknown type of the derived value");
  d.type = *type;
  for (const auto& jo : j["ops"]) {
    if (!jo.is_object()) return fail("an op is not an object");
    Op op;
    op.nodeId = jo.value("node", "");
    op.spec = registry.find(jo.value("type", ""));
    if (!op.spec || !op.spec->eval) return fail("unknown node type '" + jo.value("type", "") + "'");
    if (!isDerivedNodeType(op.spec->type)) return fail("node type '" + op.spec->type + "' is not allowed in a derived value");
    const nlohmann::json options = jo.value("options", nlohmann::json::object());
    if (!options.is_object()) return fail("the options of '" + op.nodeId + "' are not an object");
    for (auto it = options.begin(); it != options.end(); ++it) {
      const std::string& name = it.key();
      auto spec = std::find_if(op.spec->options.begin(), op.spec->options.end(),
                               [&](const OptionSpec& o) { return o.name == name; });
      if (spec == op.spec->options.end()) return fail("'" + op.nodeId + "' has no option '" + name + "'");
      std::string why = checkOption(*spec, *it, "");
      if (!why.empty()) return fail("option '" + name + "' of '" + op.nodeId + "': " + why);
    }
    try {
      op.setOptions(completeOptions(*op.spec, options));
      op.parsedOptions = parseOptions(*op.spec, op.options());
    } catch (const std::bad_alloc&) {
      throw;  // out of memory is the command's to report, not a fault of the manifest
    } catch (const std::exception& e) {
      return fail("options of '" + op.nodeId + "': " + e.what());
    }
    for (const auto& t : jo.value("input_types", nlohmann::json::array())) {
      auto ty = typeOfJson(t);
      if (!ty) return fail("an input type of '" + op.nodeId + "' does not parse");
      op.inputTypes.push_back(*ty);
    }
    for (const auto& t : jo.value("output_types", nlohmann::json::array())) {
      auto ty = typeOfJson(t);
      if (!ty) return fail("an output type of '" + op.nodeId + "' does not parse");
      op.outputTypes.push_back(*ty);
    }
    for (const auto& ji : jo.value("inputs", nlohmann::json::array())) {
      if (ji.contains("op")) {
        int k = ji.value("op", -1), p = ji.value("port", 0);
        if (k < 0 || static_cast<size_t>(k) >= d.program.ops.size() || p < 0 ||
            static_cast<size_t>(p) >= d.program.ops[static_cast<size_t>(k)].outputTypes.size())
          return fail("an input of '" + op.nodeId + "' reads no earlier op output");
        op.inputs.push_back(ValueRef::op(k, p));
      } else if (ji.contains("parameter")) {
        std::string name = ji.value("parameter", "");
        int at = -1;
        for (size_t i = 0; i < parameters.size(); ++i)
          if (parameters[i].name == name) at = static_cast<int>(i);
        if (at < 0) return fail("unknown parameter '" + name + "'");
        op.inputs.push_back(ValueRef::param(at));
      } else if (ji.contains("builtin")) {
        auto b = parseBuiltin(ji.value("builtin", ""));
        if (!b || !isPerDrawBuiltin(*b)) return fail("'" + ji.value("builtin", "") + "' is no per-draw builtin");
        op.inputs.push_back(ValueRef::builtin(*b));
      } else if (ji.contains("constant")) {
        auto ty = typeOfJson(ji.value("type", nlohmann::json()));
        const auto& c = ji["constant"];
        if (!ty || !c.is_array() || static_cast<int>(c.size()) != componentCount(*ty))
          return fail("a constant input of '" + op.nodeId + "' does not parse");
        Value v = Value::ofType(*ty);
        for (int i = 0; i < v.size(); ++i) v[i] = c[static_cast<size_t>(i)].get<double>();
        op.inputs.push_back(ValueRef::constant_(v));
      } else {
        return fail("an input of '" + op.nodeId + "' is none of op, parameter, builtin, constant");
      }
    }
    // The op must be what the compiler wrote: one input per port of its type, and the port
    // types its type gives those inputs. Anything else would be evaluated with values of
    // the wrong size at the first draw.
    if (op.inputs.size() != op.spec->inputs.size())
      return fail("'" + op.nodeId + "' (" + op.spec->type + ") has " + std::to_string(op.inputs.size()) + " inputs; its type has " +
                  std::to_string(op.spec->inputs.size()));
    std::vector<Type> sources;
    for (const ValueRef& r : op.inputs) sources.push_back(sourceType(d, r));
    PortTyping typed = typePorts(*op.spec, *op.parsedOptions, sources, [](int i) { return "input " + std::to_string(i); });
    if (!typed.error.empty()) return fail("'" + op.nodeId + "' (" + op.spec->type + "): " + typed.error);
    if (op.inputTypes != typed.inputTypes || op.outputTypes != typed.outputTypes)
      return fail("'" + op.nodeId + "' (" + op.spec->type + ") declares port types its inputs do not give");
    d.program.ops.push_back(std::move(op));
  }
  int k = j["value"].value("op", -1), p = j["value"].value("port", 0);
  if (k < 0 || static_cast<size_t>(k) >= d.program.ops.size() || p < 0 ||
      static_cast<size_t>(p) >= d.program.ops[static_cast<size_t>(k)].outputTypes.size())
    return fail("the derived value is no op output");
  d.value = ValueRef::op(k, p);
  if (d.program.ops[static_cast<size_t>(k)].outputTypes[static_cast<size_t>(p)] != d.type)
    return fail("the derived value's op output is not of its type");
  return d;
}

}  // namespace

std::optional<DerivedValue> derivedFromJson(const nlohmann::json& j, const Registry& registry,
                                            const std::vector<ProgramParameter>& parameters, std::string& error) {
  // A member of the wrong JSON kind (a number where a name goes) is an error like any other.
  try {
    return readDerived(j, registry, parameters, error);
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();
    auto close = what.find("] ");
    error = "a member has the wrong kind: " + (close == std::string::npos ? what : what.substr(close + 2));
    return std::nullopt;
  }
}

}  // namespace wg
