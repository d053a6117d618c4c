#pragma once
// What a node that expands into ops (NodeSpec::expand: an expression) sees and decides.
// resolve and the CPU backend's evaluateNode build one per such node; the node appends
// ops to the program and names the value of each of its outputs, or refuses with a
// diagnostic that points at the place it is about.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.h"
#include "core/node_spec.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

struct ExpandContext {
  const NodeSpec& spec;            // the registry's
  const NodePorts& ports;          // the ports the node's options give (NodeSpec::portsFor)
  const ParsedOptions& options;
  const Registry& registry;        // the node types the expansion is made of
  std::string nodeId;              // every appended op carries it
  SourceRef where;                 // the node in the file
  // One per input port: its source, already of the port's type.
  std::vector<ValueRef> inputs;
  Program& program;
  // Where byte `offset` of Text option `option`'s string is in the file (escapes counted).
  std::function<SourceRef(std::string_view option, std::size_t offset)> optionWhere;

  std::vector<ValueRef> outputs;   // to fill: one per output port

  // To refuse: set `error`, and where the fault is: byte `errorOffset` of the string of
  // Text option `errorOption` (resolve turns it into the file's column), or no option for
  // the node as a whole. What was appended to the program is dropped.
  DiagCode errorCode = DiagCode::InvalidOption;
  std::string error;
  std::string errorOption;
  std::size_t errorOffset = 0;
};

// The fault an expanding node's expansion finds with these options (as written), without
// a graph around it: its inputs stand for values of their ports' types. For an editor that
// shows a formula's fault as it is typed. None when the expansion succeeds, and when the
// options themselves are not valid (checkOption says why).
struct ExpansionFault {
  std::string option;  // "" for the node as a whole
  std::size_t offset = 0;
  std::string message;
};
std::optional<ExpansionFault> expansionFault(const Registry& registry, const NodeSpec& spec, const nlohmann::json& written);

}  // namespace wg
