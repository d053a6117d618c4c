#pragma once
// Reading a graph file (with positions, duplicate keys reported) and writing the one
// canonical form that `watergraph fmt` produces.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg {

// Parses `text` as a graph file named `file` (used in diagnostics). On any error, the
// diagnostics say why and the result is empty.
std::optional<Graph> parseGraph(std::string_view text, const std::string& file, Diagnostics& diags);
// The same for a text the caller already holds as a shared string: the diagnostics keep
// this one (positions after parsing need the lines) instead of a copy of it, so a file is
// in memory once. A 10,000-node graph's text is about 0.9 MiB.
std::optional<Graph> parseGraph(std::shared_ptr<const std::string> text, const std::string& file, Diagnostics& diags);
// Reads and parses a file, and the graphs it imports (core/graph_imports.h); an unreadable
// file is WG050.
std::optional<Graph> loadGraphFile(const std::string& path, Diagnostics& diags);
// The whole file, read once (WG050 unreadable, WG035 over 16 MiB). loadGraphFile parses
// this one snapshot; a caller that also needs the bytes (fmt) reads them here, never twice.
std::optional<std::string> readGraphFile(const std::string& path, Diagnostics& diags);

// The canonical text: fixed key order, 2-space indent, shortest round-trip numbers, a
// container on one line where it fits within 100 columns (core/graph_save.cpp),
// LF line endings, a final newline. saveGraph(parseGraph(saveGraph(g))) == saveGraph(g).
std::string saveGraph(const Graph& graph);

}  // namespace wg
