#include "core/expand.h"

#include "core/node_options.h"

namespace wg {

std::optional<ExpansionFault> expansionFault(const Registry& registry, const NodeSpec& spec, const nlohmann::json& written) {
  if (!spec.expand || !written.is_object()) return std::nullopt;
  for (auto it = written.begin(); it != written.end(); ++it) {
    int oi = spec.optionIndex(it.key());
    if (oi < 0 || !checkOption(spec.options[static_cast<size_t>(oi)], it.value(), "").empty()) return std::nullopt;
  }
  auto options = parseOptions(spec, completeOptions(spec, written));
  NodePorts ports = spec.portsFor ? spec.portsFor(*options) : NodePorts{spec.inputs, spec.outputs};
  Program scratch;
  std::vector<ValueRef> inputs;
  for (const auto& port : ports.inputs) {
    ProgramParameter p;
    p.name = port.name;
    p.type = port.type;
    p.defaultValue = Value::ofType(port.type);
    inputs.push_back(ValueRef::param(static_cast<int>(scratch.parameters.size())));
    scratch.parameters.push_back(std::move(p));
  }
  ExpandContext ctx{spec, ports, *options, registry, "n", {}, std::move(inputs), scratch,
                    [](std::string_view, std::size_t) { return SourceRef{}; }};
  spec.expand(ctx);
  if (ctx.error.empty()) return std::nullopt;
  return ExpansionFault{ctx.errorOption, ctx.errorOffset, ctx.error};
}

}  // namespace wg
