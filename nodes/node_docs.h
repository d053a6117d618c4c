#pragma once
// The node reference generated from the registry: docs/nodes.md and `watergraph nodes --json`.
#include <string>

#include <nlohmann/json.hpp>

#include "core/registry.h"

namespace wg {

nlohmann::json nodesJson(const Registry& registry);
std::string nodesMarkdown(const Registry& registry);

}  // namespace wg
