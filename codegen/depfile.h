#pragma once
// A Make/Ninja depfile (`watergraph compile --depfile`): for each compiled graph, the files
// written depend on every file the graph was made from — its own, every imported graph,
// every PNG texture — so that a build system recompiles when any of them changes.
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace wg {

struct DepfileRule {
  std::vector<std::string> outputs;  // the files written
  std::vector<std::string> inputs;   // the files read
};

// "" when `path` can be written into a depfile so that both GNU Make and Ninja read it back
// as the same path; else why not (a line break, a tab, a character one of them takes for
// syntax, a backslash before '#' or at the end).
std::string depfilePathProblem(const std::string& path);

// One line per rule, `out1 out2: in1 in2`, each path escaped the way GNU Make and Ninja both
// read it back: '$' doubled; a space, '#' and ':' after a backslash; backslashes just before
// an escaped space doubled (the gcc convention). nullopt, with an error (WG051) at
// `depfile`, when a path cannot be written so (depfilePathProblem).
std::optional<std::string> depfileText(const std::vector<DepfileRule>& rules, const std::string& depfile,
                                       Diagnostics& diags);

}  // namespace wg
