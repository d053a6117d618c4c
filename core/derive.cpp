#include "core/derive.h"

#include <stdexcept>

#include "core/node_options.h"
#include "core/port_typing.h"

namespace wg {

const ValueRef& DeriveContext::input(std::string_view port) const {
  int i = spec.inputIndex(port);
  if (i < 0) throw std::logic_error("node type '" + spec.type + "' derives from an input '" + std::string(port) + "' it lacks");
  return inputs[static_cast<size_t>(i)];
}

void DeriveContext::set(std::string_view port, ValueRef value) {
  int i = spec.inputIndex(port);
  if (i < 0 || !spec.inputs[static_cast<size_t>(i)].derived)
    throw std::logic_error("node type '" + spec.type + "' sets '" + std::string(port) + "', which is not a derived input");
  inputs[static_cast<size_t>(i)] = std::move(value);
}

ValueRef DeriveContext::op(std::string_view type, const std::vector<ValueRef>& opInputs, const nlohmann::json& opOptions,
                           int output) {
  const NodeSpec* s = registry.find(type);
  if (!s) throw std::logic_error("node type '" + spec.type + "' derives through '" + std::string(type) + "', not in the registry");
  Op o;
  o.spec = s;
  o.nodeId = nodeId;
  o.where = where;
  o.setOptions(completeOptions(*s, opOptions));
  o.parsedOptions = parseOptions(*s, o.options());
  size_t n = s->inputs.size();
  o.inputs.assign(n, ValueRef{});
  std::vector<Type> sourceTypes(n, Type::Invalid);
  for (size_t k = 0; k < n; ++k) {
    const PortSpec& p = s->inputs[k];
    if (k < opInputs.size()) o.inputs[k] = opInputs[k];
    else if (p.defaultValue) o.inputs[k] = ValueRef::constant_(*p.defaultValue);
    else if (p.defaultBuiltin) o.inputs[k] = ValueRef::builtin(*p.defaultBuiltin);
    else throw std::logic_error("node type '" + spec.type + "' derives through '" + s->type + "' without its input '" + p.name + "'");
    sourceTypes[k] = program.typeOf(o.inputs[k]);
  }
  PortTyping t = typePorts(*s, *o.parsedOptions, sourceTypes, [](int) { return std::string("the derived value"); });
  if (!t.error.empty()) throw std::logic_error("node type '" + spec.type + "' derives through '" + s->type + "': " + t.error);
  o.inputTypes = std::move(t.inputTypes);
  o.outputTypes = std::move(t.outputTypes);
  program.ops.push_back(std::move(o));
  return ValueRef::op(static_cast<int>(program.ops.size()) - 1, output);
}

void deriveInputs(const NodeSpec& spec, const ParsedOptions& options, const Registry& registry, const std::string& nodeId,
                  const SourceRef& where, std::vector<ValueRef>& inputs, Program& program) {
  if (!spec.derive) return;
  DeriveContext ctx{spec, options, registry, nodeId, where, inputs, program};
  spec.derive(ctx);
  for (size_t i = 0; i < spec.inputs.size(); ++i)
    if (spec.inputs[i].derived && ctx.inputs[i].kind == ValueRef::Kind::None)
      throw std::logic_error("node type '" + spec.type + "' leaves its derived input '" + spec.inputs[i].name + "' unset");
  inputs = std::move(ctx.inputs);
}

}  // namespace wg
