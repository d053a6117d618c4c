#pragma once
// Loading a graph with every graph it imports: the file is parsed (core/graph_parse.h),
// then its imports are followed (core/graph_imports.h), each imported file parsed in turn.
// Two steps, and this sits above both: parsing one file never follows imports, so core has
// no loop between the parser and the import loader.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg {

// Reads and parses the file at `path`, then loads the graphs it imports; an unreadable
// file is WG050. On any error, in the file or in one it imports, the result is empty.
std::optional<Graph> loadGraphFile(const std::string& path, Diagnostics& diags);
// The same for a graph file's text already in memory, named `file` (imports are relative
// to its folder).
std::optional<Graph> loadGraphText(std::shared_ptr<const std::string> text, const std::string& file, Diagnostics& diags);

// The files a watcher follows for the graph file at `path`, read afresh, whatever its
// faults: graphFilesRead (core/graph_imports.h) of it with its imports (at least `path`
// itself, even when it cannot be read).
std::vector<std::string> graphFilesToWatch(const std::string& path);

}  // namespace wg
