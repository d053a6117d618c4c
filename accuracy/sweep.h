#pragma once
// Dense sweeps of one node input (`watergraph probe --node TYPE --sweep AXIS`): a base case
// repeated with one input stepped evenly over a range, so the float32 error can be drawn
// against that input. An axis is `NAME:FROM:TO:COUNT`:
//   angle           degrees between the normal (0, 1, 0) and the view (sin a, cos a, 0),
//                   set as the "normal"/"view" inputs and the normal/view builtins;
//   PORT or PORT.c  an input port of the node (all its components, or component x/y/z/w),
//                   or a builtin key of the cases file (time, world_position.x, uv.y, ...).
#include <optional>
#include <string>
#include <vector>

#include "accuracy/probe.h"
#include "core/node_options.h"

namespace wg::accuracy {

struct SweepAxis {
  std::string name;  // "angle", "depth", "world_position"
  int component = -1;  // -1: every component
  double from = 0, to = 0;
  int count = 0;
  double at(int i) const { return count < 2 ? from : from + (to - from) * i / (count - 1); }
};

// nullopt and `error` set when the text is not NAME[.c]:FROM:TO:COUNT with COUNT >= 1.
std::optional<SweepAxis> parseSweepAxis(const std::string& text, std::string& error);

// Whether `key` names a builtin a sweep can step (time, world_position, near_far, ...: the
// builtin keys of a cases file).
bool isSweepBuiltinKey(const std::string& key);

// The cases of the sweep: `base` with the axis value i at position i (named "NAME=value").
// An input port the base case does not set starts from the port's default (zero when none).
// Values are rounded to float32, as in a cases file. `ports` are the node's for its options
// (portsOfNode: an expression's inputs are those its options declare).
std::vector<ProbeCase> sweepCases(const NodePorts& ports, const SweepAxis& axis, const ProbeCase& base);

// The swept value of each case, as written: "x gpu reference abs_error bound" per line,
// one output component (the one the report names: the closest to its bound).
std::string sweepTable(const SweepAxis& axis, const ProbeReport& report);

}  // namespace wg::accuracy
