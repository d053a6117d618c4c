#pragma once
// The node reference generated from the registry: docs/nodes.md and `watergraph nodes --json`.
#include <string>

#include <nlohmann/json.hpp>

#include "core/graph.h"
#include "core/registry.h"

namespace wg {

nlohmann::json nodesJson(const Registry& registry);
std::string nodesMarkdown(const Registry& registry);

// A function graph as a node type named `type` (`watergraph nodes --graph`): its file, its
// interface's description, its inputs (the parameters: type, default, range) and outputs,
// as JSON with the keys nodesJson uses, or as text.
nlohmann::json functionGraphJson(const std::string& type, const Graph& functionGraph);
std::string functionGraphText(const std::string& type, const Graph& functionGraph);

}  // namespace wg
