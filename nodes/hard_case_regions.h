#pragma once
// The region or branch each node's own hard case (NodeSpec::hardCases) exercises, in the
// vocabulary of the suite's cases (tests/hardcases/suite.json, "region"), and the input
// ports the region concerns. tests/accuracy/node_hard_case_regions_test.cpp proves each
// case reaches its region, with checks written independently of the node code. Kept
// beside NodeSpec, keyed by node type and case name (as nodes/rounded_intermediates.h):
// a member of HardCase would recompile nearly every file; it reads like one.
#include <string_view>
#include <vector>

namespace wg::nodes {

struct HardCaseRegion {
  std::string_view type;      // node type
  std::string_view hardCase;  // HardCase::name
  std::string_view region;    // e.g. total_internal_reflection, zero_vector, sky_depth, huge_coordinates
  std::string_view ports;     // the input ports (or builtins) the region concerns, space-separated; may be empty
  // outside_domain: the documented domain [lo, hi] of the port (the node clamps to it).
  double lo = 0, hi = 0;
};

const std::vector<HardCaseRegion>& hardCaseRegions();

// The entry for (type, case name), or null.
const HardCaseRegion* hardCaseRegion(std::string_view type, std::string_view hardCase);

}  // namespace wg::nodes
