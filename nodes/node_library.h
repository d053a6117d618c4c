#pragma once
// Every node type's spec factory, declared from the one list of nodes (nodes/node_list.def).
#include "core/node_spec.h"

namespace wg::nodes {

#define WG_NODE(factory) NodeSpec factory();
#include "nodes/node_list.def"
#undef WG_NODE

}  // namespace wg::nodes
