#pragma once
// A Make/Ninja depfile (`watergraph compile --depfile`): for each compiled graph, the files
// written depend on every file the graph was made from — its own, every imported graph,
// every PNG texture — so that a build system recompiles when any of them changes.
#include <string>
#include <vector>

namespace wg {

struct DepfileRule {
  std::vector<std::string> outputs;  // the files written
  std::vector<std::string> inputs;   // the files read
};

// One line per rule, `out1 out2: in1 in2`, paths escaped the way Make and Ninja read them
// (a space, '#' and '\' before them with '\', '$' doubled).
std::string depfileText(const std::vector<DepfileRule>& rules);

}  // namespace wg
