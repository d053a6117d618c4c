#pragma once
// What resolve knows of every node's outputs (resolveGraph's second form, core/resolve.h):
// its own header so that the resolver's class (core/resolver.h) can name it without
// including the entry point that it implements.
#include <map>
#include <string>
#include <vector>

#include "core/program.h"

namespace wg {

// One output of a node as the resolved program holds it: an op's output, or the value an
// expanded node's output stands for (an expression's `out`). Invalid type: the output
// does not exist for the node's input types (split.w of a vec3).
struct NodeOutputValue {
  std::string port;
  ValueRef value;
  Type type = Type::Invalid;
};
// By node id, every output of every node that resolved: what a probe of "node.port" reads.
// Indices are those of the program resolve returns, before any pass renumbers its ops.
using NodeOutputValues = std::map<std::string, std::vector<NodeOutputValue>, std::less<>>;

}  // namespace wg
