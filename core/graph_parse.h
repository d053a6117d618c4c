#pragma once
// Reading and parsing one graph file: its text, with positions and duplicate keys
// reported, into a Graph. The graphs it imports are not followed here: core/graph_load.h
// loads a graph with its imports (parse the file, then core/graph_imports.h), above both.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg {

// Parses `text` as a graph file named `file` (used in diagnostics). On any error, the
// diagnostics say why and the result is empty. Import::graph stays unset.
std::optional<Graph> parseGraph(std::string_view text, const std::string& file, Diagnostics& diags);
// The same for a text the caller already holds as a shared string: the diagnostics keep
// this one (positions after parsing need the lines) instead of a copy of it, so a file is
// in memory once. A 10,000-node graph's text is about 0.9 MiB.
std::optional<Graph> parseGraph(std::shared_ptr<const std::string> text, const std::string& file, Diagnostics& diags);
// The whole file, read once (WG050 unreadable, WG035 over 16 MiB). loadGraphFile parses
// this one snapshot; a caller that also needs the bytes (fmt) reads them here, never twice.
std::optional<std::string> readGraphFile(const std::string& path, Diagnostics& diags);

}  // namespace wg
