#pragma once
// A probe cases file (docs/accuracy.md): named input sets for `watergraph probe`. Each
// case fixes what the probed shader sees — the surface builtins, time, camera, the scene
// textures' values, the graph's parameters — and may state the expected range of the
// result and a tolerance. Numbers may be written "inf" or "-inf" (an infinite far plane).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/diagnostic.h"
#include "core/node_spec.h"
#include "core/source_ref.h"

namespace wg::accuracy {

struct ProbeCase {
  std::string name;
  std::string expect;       // the safe behaviour it checks, in words
  // The region or branch of the maths it exercises ("total_internal_reflection",
  // "gerstner_cusp", ...); the suite's region test (tests/accuracy) proves each is reached.
  std::string region;
  EvalEnvironment env;      // every value already rounded to float32: what the GPU sees
  std::vector<std::pair<std::string, Value>> parameters;  // graph parameter -> value (float32)
  std::optional<std::pair<double, double>> range;  // every component of the result within
  std::optional<double> tolerance;                 // overrides the file's and the graph's
  SourceRef where;                                 // the case object
  // What the case sets explicitly: "uv", "time", "camera", "scene.depth", ... (the
  // hard-case suite runs a case against the nodes that read one of these).
  std::set<std::string> given;
  // Node probes only (`watergraph probe --node`, the hard-case suite):
  std::vector<std::pair<std::string, Value>> inputs;  // input port -> value (float32)
  nlohmann::json options = nlohmann::json::object();  // node type -> options for it
  std::map<std::string, std::pair<double, double>> ranges;  // "type.output" -> [lo, hi]
  std::vector<std::string> nodes;  // the suite runs the case only on these types (empty: all)
};

struct ProbeCaseFile {
  std::string file;
  std::optional<double> tolerance;  // "tolerance" at the top level
  std::vector<ProbeCase> cases;
};

// The default camera of a case (above the origin, looking down at 45 degrees); the
// environment's view and projection matrices come from it unless the case sets its own.
EvalEnvironment defaultProbeEnvironment();

// Parses `text` (named `file` in diagnostics). Errors are WG001-WG003 for JSON problems and
// WG060 for the rest, each at the offending key or value; nothing is returned then.
std::optional<ProbeCaseFile> parseProbeCases(const std::string& text, const std::string& file, Diagnostics& diags);
std::optional<ProbeCaseFile> loadProbeCases(const std::string& path, Diagnostics& diags);

// Column-major GLSL matrices of a look-at camera and a perspective projection (far may be
// infinite: the limit matrix), computed in double.
Value lookAtMatrix(const Value& eye, const Value& target);
Value perspectiveMatrix(double fovYDegrees, double aspect, double nearPlane, double farPlane);

// A float32 rounding of every component (infinities stay).
Value toFloat32(const Value& v);

}  // namespace wg::accuracy
