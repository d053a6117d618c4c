// The node registry: every node of nodes/node_list.def, each checked as it is added
// (core/registry.cpp's checkSpec).
#include "nodes/registry.h"

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
         })
      r.add(make());
    return r;
  }();
  return registry;
}

}  // namespace wg
