#include "core/color_parameters.h"

#include <stdexcept>

#include "core/node_options.h"
#include "core/number_format.h"
#include "core/port_typing.h"
#include "core/color_space.h"

namespace wg {

bool isColorHint(std::string_view hint) { return hint == kColorHint || hint == kHdrColorHint; }

std::string_view parameterColorSpace(std::string_view hint) { return isColorHint(hint) ? "srgb" : ""; }

std::optional<std::string> colorRangeProblem(std::string_view hint, const std::vector<double>& xs,
                                             const std::string& label) {
  if (hint != kColorHint) return std::nullopt;
  for (size_t i = 0; i < xs.size(); ++i) {
    if (xs[i] >= 0 && xs[i] <= 1) continue;
    std::string comp = xs.size() > 1 ? " (component " + std::to_string(i) + ")" : std::string();
    return label + " " + formatNumber(xs[i]) + comp +
           " lies outside [0, 1], the range of an sRGB colour (hint \"color\"); a colour brighter than white "
           "takes the hint \"hdr_color\"";
  }
  return std::nullopt;
}

Value linearColor(const Value& srgb) { return srgbToLinear(srgb); }

ValueRef appendParameterLinearisation(Program& program, const Registry& registry, int param) {
  const NodeSpec* spec = registry.find(kLinearisationNode);
  if (!spec) throw std::logic_error("the registry has no '" + std::string(kLinearisationNode) + "' node");
  const ProgramParameter& p = program.parameters.at(static_cast<size_t>(param));
  Op op;
  op.spec = spec;
  op.nodeId = "$" + p.name;
  op.where = p.where;
  op.setOptions(completeOptions(*spec, nlohmann::json::object()));
  op.parsedOptions = parseOptions(*spec, op.options());
  op.inputs = {ValueRef::param(param)};
  PortTyping t = typePorts(*spec, *op.parsedOptions, {p.type}, [](int) { return std::string("the parameter"); });
  if (!t.error.empty()) throw std::logic_error("linearising parameter '" + p.name + "': " + t.error);
  op.inputTypes = std::move(t.inputTypes);
  op.outputTypes = std::move(t.outputTypes);
  program.ops.push_back(std::move(op));
  return ValueRef::op(static_cast<int>(program.ops.size()) - 1, 0);
}

}  // namespace wg
