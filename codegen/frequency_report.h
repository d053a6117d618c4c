#pragma once
// What the frequency analysis (codegen/frequency.h) finds in one final Program, for people
// (`watergraph compile|validate --explain-frequency`): how many ops run at each
// frequency, and the per-draw values the fragment stage recomputes for every pixel — work
// a graph or node author may want to move into a parameter or a per-draw split of the
// node (core/derive.h) — with their estimated cost per pixel: the operations the planner
// counted for the fragment lines it wrote for them (PlannedStatement::cost, counted from the
// values as they were built by the rules of core/glsl_operation_count.h).
#include <array>
#include <string>
#include <vector>

#include "codegen/frequency.h"
#include "core/program.h"

namespace wg {

// A maximal per-draw subexpression of the fragment stage: its root is a per-draw op whose
// value a per-fragment op or a fragment output reads.
struct PerDrawRoot {
  int op = -1;             // the root
  std::vector<int> ports;  // the root's outputs read per pixel
  std::vector<int> ops;    // the per-draw ops the fragment stage computes for it, root included, in program order
  int cost = 0;            // their estimated operations per pixel
};

struct FrequencyReport {
  std::vector<Frequency> ops;     // per op
  std::array<int, 4> counts{};    // ops per Frequency
  std::vector<int> fragmentCost;  // per op: estimated operations per pixel of the fragment lines it writes
  int perDrawInFragment = 0;      // per-draw ops the fragment stage computes
  int perDrawCost = 0;            // their estimated operations per pixel, each op once
  int fragmentTotalCost = 0;      // the whole fragment stage's (locals and output lines included)
  // Roots whose subexpression costs more than a uniform read (cost > 0), in program order.
  std::vector<PerDrawRoot> roots;
};

// `program` must have been through the pass recipe (stages decided).
FrequencyReport frequencyReport(const Program& program);

// The report as text: a line of counts, then one line per root. Every line but the
// first is indented by two spaces; ends with '\n'.
std::string formatFrequencyReport(const Program& program, const FrequencyReport& report);

}  // namespace wg
