#pragma once
// What a node with derived inputs (PortSpec::derived, NodeSpec::derive) sees and decides:
// the values of its other inputs, and the program to append the ops that compute the
// derived ones to. The split is how a node's per-draw part (fract(time * speed), the
// near/far ratio of a depth linearisation, the camera axis) becomes ops of its own that the
// frequency analysis classifies per-draw, while the node's own op keeps the per-pixel rest.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/node_spec.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

struct DeriveContext {
  const NodeSpec& spec;
  const ParsedOptions& options;
  const Registry& registry;
  std::string nodeId;  // every appended op carries it
  SourceRef where;
  // One per input port of the spec, as connected or defaulted (not yet converted to the
  // port's type); derived ports are unset until the node names them.
  std::vector<ValueRef> inputs;
  Program& program;

  const ValueRef& input(std::string_view port) const;
  // Names the value of derived port `port`.
  void set(std::string_view port, ValueRef value);
  // Appends an op of node type `type` (its unconnected inputs take their defaults), typed
  // by the node's own rules, and gives its output `output`. Throws std::logic_error where
  // the registry lacks the type or the inputs do not fit it: a defect of the deriving node.
  ValueRef op(std::string_view type, const std::vector<ValueRef>& opInputs,
              const nlohmann::json& opOptions = nlohmann::json::object(), int output = 0);
};

// Runs spec.derive for an op whose non-derived inputs are set: appends the derived ops to
// `program` and fills the op's derived inputs. Throws std::logic_error if the node leaves a
// derived port unnamed.
void deriveInputs(const NodeSpec& spec, const ParsedOptions& options, const Registry& registry, const std::string& nodeId,
                  const SourceRef& where, std::vector<ValueRef>& inputs, Program& program);

}  // namespace wg
