#pragma once
#include "core/registry.h"

namespace wg {

// Every node type watergraph ships, built once.
const Registry& defaultRegistry();

}  // namespace wg
