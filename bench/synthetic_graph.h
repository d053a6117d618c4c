#pragma once
// Deterministic synthetic graphs for the compile benchmarks: a realistic mix of node types
// (inputs, arithmetic, water nodes with GLSL library functions, parameters, a displaced
// vertex stage) wired as a DAG with skip links and fan-out, not a chain. Some nodes are
// unreachable (prune), some duplicate others (CSE) and some read only constants (fold), so
// every pass has work at every size.
#include <string>

namespace wg::bench {

// The graph file text of about `nodes` nodes (exactly `nodes` for nodes >= 10). The same
// `nodes` always gives the same bytes.
std::string syntheticGraphJson(int nodes);

}  // namespace wg::bench
