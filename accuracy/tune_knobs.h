#pragma once
// The quality knobs `watergraph tune` and `watergraph bench GRAPH` search: those of the
// graph file's own nodes and those of the nodes inside its subgraph instances, named by the
// node's qualified id ("foam/edge.bypass", as a preset writes them), and the graph with a
// configuration of them applied.
#include <string>
#include <vector>

#include "accuracy/tune_search.h"
#include "codegen/target.h"
#include "core/graph.h"

namespace wg::accuracy {

// Every quality knob (options whose levels a node declares, `bypass` included) in file
// order, an instance's knobs where the instance stands, with the levels its spec declares.
std::vector<TuneKnob> graphKnobs(const Graph& graph);

// `knobs` with only the levels that change what this graph compiles to for `target`: a level
// whose shaders are those of the next more exact level (every other knob at
// its most exact) stands for nothing of its own and is left out (a wave count of 12 on a
// list of three waves, a tessellation factor on an untessellated surface). A knob left with
// one level is dropped and its name added to `unchanged`; the search would otherwise time
// identical shaders against each other and take noise for a saving.
std::vector<TuneKnob> distinctKnobLevels(const Graph& graph, std::vector<TuneKnob> knobs, Target target,
                                         std::vector<std::string>& unchanged);

// Switching a node off (its `bypass` knob) drops what it draws: a decision for the graph's
// author, so `tune --keep NODE,...` forbids it for the named nodes (qualified ids, as
// graphKnobs names them) and `--no-bypass` (keepAll) for every node. Removes those knobs
// from `knobs` and returns the names in `keep` that are no node's bypass knob (the caller
// refuses them).
std::vector<std::string> dropBypassKnobs(std::vector<TuneKnob>& knobs, const std::vector<std::string>& keep,
                                         bool keepAll);

// The nodes `config` switches off (bypass at true), qualified ids in knob order.
std::vector<std::string> bypassedNodes(const std::vector<TuneKnob>& knobs, const TuneConfig& config);

// `graph` with each knob at its level in `config` (nested nodes through
// Graph::instanceOptions, as an applied preset sets them).
Graph withKnobLevels(const Graph& graph, const std::vector<TuneKnob>& knobs, const TuneConfig& config);

}  // namespace wg::accuracy
