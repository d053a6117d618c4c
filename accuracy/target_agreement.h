#pragma once
// `watergraph check` for a graph with a node that has no double reference (a glsl_function
// node without a `reference` formula): nothing says what its pixels should be, so the
// targets are held to each other instead. Each target's frames over the sweep are kept
// (CheckOptions::keepFrames) and compared pixel by pixel with the first target's: two
// results that each lie within the graph's tolerance of the truth lie within twice it of
// each other, so a pixel component further apart than
//   2 * tolerance * max(1, |first|)
// (tolerance: the largest of the graph's ops, accuracy/error_bound.h) shows that one
// target computes something else — a precision rule of es300, a Vulkan difference. The
// NaN and Inf count over the sweep stays each target's own.
#include <string>
#include <vector>

#include "accuracy/check.h"

namespace wg::accuracy {

// The node with no double reference, as check names it ("node 'light' (glsl_function)"),
// or "" when every op has one.
std::string nodeWithoutReference(const Program& program);

struct TargetAgreement {
  Target first = Target::Glsl330, other = Target::Glsl330;
  long compared = 0;      // pixel components compared over every view (finite on both)
  long overBound = 0;     // of those, further apart than the bound
  double maxDifference = 0;
  double worstRatio = 0;  // largest difference / bound
  std::string worstView;  // the view of the worst ratio
  bool failed() const { return overBound > 0; }
};

// `first` and `other` are reports of one graph on two targets with their frames kept
// (the same sweep, the same size); throws std::invalid_argument when they are not.
TargetAgreement compareTargets(const CheckReport& first, const CheckReport& other, double tolerance);

// "  es300 against glsl330: 518400 values, max difference 1.19e-07, worst difference/bound 0.006, over the bound 0"
std::string formatTargetAgreement(const TargetAgreement& agreement);

}  // namespace wg::accuracy
