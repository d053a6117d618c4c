#pragma once
// Function graphs used as node types (docs/graph-format.md, "Subgraphs"): loading what a
// graph imports (each file parsed with core/graph_parse.h), and what follows from the whole
// tree of files. A graph file with its imports in one call: core/graph_load.h.
#include <cstddef>
#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/node_spec.h"

namespace wg {

// Loads every graph that `graph` imports, and the ones they import, into Import::graph:
// each file once however many imports reach it. A path is relative to the file that
// writes it and must stay inside the folder of `graph`'s file (after symbolic links);
// an imported graph must declare an interface. Cycles, missing files, paths that leave
// the folder, chains deeper than kMaxImportDepth, more than kMaxNodes nodes with every
// instance inlined and an inlined size over kMaxInlinedBytes are errors (WG070-WG075,
// WG035: predicted, nothing is inlined), as are the faults of each imported
// file, which carry a note naming the import. False after reporting.
bool loadImports(Graph& graph, Diagnostics& diags);

// The files `graph` is made of: its own, then every imported one, each once, in the order
// first reached (a build system's dependencies; what a watcher follows). Paths as the
// diagnostics name them. An import that failed to load is listed by the path it names,
// so that a watcher sees it repaired.
std::vector<std::string> graphFilesRead(const Graph& graph);

// The ports a function graph has as a node type: an input per parameter (fixed to the
// parameter's type, its default the parameter's), an output per interface output.
NodePorts interfacePorts(const Graph& functionGraph);

// Nodes with every subgraph instance replaced by the subgraph's nodes, counted up to
// kMaxNodes + 1 (larger graphs report that).
std::size_t inlinedNodeCount(const Graph& graph);

// What inlining every subgraph instance of a graph would make, from the import tree alone
// (each file's nodes counted once, multiplied by its instances): the nodes (up to
// kMaxNodes + 1) and the inlined size of kMaxInlinedBytes (up to kMaxInlinedBytes + 1).
struct InlinedSize {
  std::size_t nodes = 0;
  std::size_t bytes = 0;
};
InlinedSize inlinedSize(const Graph& graph);

}  // namespace wg
