#pragma once
// A JSON Schema (draft-07) for graph files (format v1, docs/graph-format.md), generated from
// the node registry: `watergraph schema` writes docs/watergraph.schema.json. Editors that
// read "$schema" (VS Code and others) complete and check node types, their input ports
// (per port type: "node.port", "$parameter", a number, or an array of the right length)
// and their options (enum choices, numeric ranges, texture sources).
//
// What the schema cannot say, resolve still checks: that a referenced node, port or
// parameter exists, types through Gen/Custom ports, cycles, stages, texture files on disk.
#include <string>

#include <nlohmann/json.hpp>

#include "core/registry.h"

namespace wg {

// The schema as an ordered JSON value (keys in a readable, stable order).
nlohmann::ordered_json graphSchema(const Registry& registry);
// graphSchema(...).dump(2) plus a final newline: the bytes of docs/watergraph.schema.json.
std::string graphSchemaText(const Registry& registry);

}  // namespace wg
