#pragma once
// What a node that expands into ops (NodeSpec::expand: an expression) sees and decides.
// resolve and the CPU backend's evaluateNode build one per such node; the node appends
// ops to the program and names the value of each of its outputs, or refuses with a
// diagnostic that points at the place it is about.
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.h"
#include "core/node_spec.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

struct ExpandContext {
  const NodeSpec& spec;            // with the ports the options give (withPorts)
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

  // To refuse: set `error` (and leave the program as it was).
  DiagCode errorCode = DiagCode::InvalidOption;
  SourceRef errorWhere;
  std::string error;
  std::string errorPort;           // the label: "option 'formula'", "input 'k'"
};

}  // namespace wg
