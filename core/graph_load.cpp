// A graph file and the graphs it imports: parse, then follow the imports. Nothing below
// (the parser, the import loader) calls back up into this file.
#include "core/graph_load.h"

#include <utility>

#include "core/graph_imports.h"
#include "core/graph_parse.h"

namespace wg {

std::optional<Graph> loadGraphText(std::shared_ptr<const std::string> text, const std::string& file, Diagnostics& diags) {
  auto graph = parseGraph(std::move(text), file, diags);
  if (graph && !loadImports(*graph, diags)) return std::nullopt;
  return graph;
}

std::optional<Graph> loadGraphFile(const std::string& path, Diagnostics& diags) {
  auto text = readGraphFile(path, diags);
  if (!text) return std::nullopt;
  return loadGraphText(std::make_shared<const std::string>(std::move(*text)), path, diags);
}

std::vector<std::string> graphFilesToWatch(const std::string& path) {
  Diagnostics ignored;
  auto text = readGraphFile(path, ignored);
  if (!text) return {path};
  auto graph = parseGraph(*text, path, ignored);
  if (!graph) return {path};
  loadImports(*graph, ignored);
  return graphFilesRead(*graph);
}

}  // namespace wg
