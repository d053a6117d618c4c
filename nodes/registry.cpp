// The node registry: every node of nodes/node_list.def, each checked as it is added
// (core/registry.cpp's checkSpec, and checkGlslCalls against the GLSL library).
#include "nodes/registry.h"

#include "nodes/glsl_function_node.h"

#include "nodes/glsl_call_check.h"
#include "nodes/node_library.h"

namespace wg {

const Registry& defaultRegistry() {
  static const Registry registry = [] {
    Registry r;
    using namespace nodes;
    for (auto make : {
#define WG_NODE(factory) factory,
#include "nodes/node_list.def"
#undef WG_NODE
         }) {
      NodeSpec spec = make();
      std::string type = spec.type;
      r.add(std::move(spec));  // checkSpec first: the call check parses the hard cases' options
      checkGlslCalls(*r.find(type), GlslLibrary::builtin());
    }
    // Function nodes: each node's spec is made from its .glsl file when it is resolved.
    r.addFileNodeType(kGlslFunctionType, makeGlslFunctionNode);
    return r;
  }();
  return registry;
}

}  // namespace wg
