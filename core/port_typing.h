#pragma once
// The port type rules of a node, in one place: Gen ports unify to one float-or-vector
// type (a float splats), Fixed ports keep theirs, then the node's `infer`, then every
// source must convert implicitly. resolve uses it for graphs; the CPU reference uses it
// to evaluate a node on its own (tests, hard cases).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/node_spec.h"
#include "core/type_list.h"

namespace wg {

struct PortTyping {
  TypeList inputTypes;
  TypeList outputTypes;  // Invalid where infer says the output does not exist
  std::string error;              // "" when the sources fit
  int errorInput = -1;            // the input the error is about, or -1
};

// `sourceTypes[i]` is the type input i receives; `describe(i)` names that source in
// messages ("'n.out'", "its default").
PortTyping typePorts(const NodeSpec& spec, const ParsedOptions& options, const std::vector<Type>& sourceTypes,
                     const std::function<std::string(int)>& describe);

}  // namespace wg
