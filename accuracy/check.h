#pragma once
// `watergraph check`: a compiled graph rendered into an RGBA32F frame over a sweep of
// views — camera elevation from grazing to top-down, under water when the graph has the
// deferred underwater pass, times up to 1e6 s, sun positions — counting NaN and Inf
// pixels. Where the graph has a full CPU reference (no vertex outputs, no scene
// resources, an opaque colour) the frame is compared, on a grid of sampled pixels where
// the flat water is visible, with the double reference evaluated at that pixel's surface
// point (desktop GL only: the visibility test reads the depth buffer back).
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "runtime/renderer.h"

namespace wg::accuracy {

struct CheckView {
  std::string label;  // "elevation 2 deg", "time 1e6 s", ...
  rt::Camera camera;
  rt::SceneOptions scene;
};

// The sweep; `underwater` adds views from below the surface.
std::vector<CheckView> checkSweep(bool underwater);

struct CheckViewResult {
  std::string label;
  long pixels = 0, nan = 0, inf = 0;
  int referenceSamples = 0;  // pixels compared with the CPU reference (0: none)
  double maxError = 0, meanError = 0;
};

struct CheckReport {
  std::string graph;
  Target target = Target::Glsl330;
  int width = 0, height = 0;
  std::string reference;  // "cpu" when compared, else why not
  std::vector<CheckViewResult> views;
  long nanInf() const;
  double maxError() const;
};

// Why the graph has no full CPU reference, or "" when it has one.
std::string referenceUnavailable(const CompileResult& result);

// Renders every view on the current context (API matching `target`). Throws
// rt::RuntimeError for driver or manifest problems.
CheckReport checkGraph(const CompileResult& result, const std::string& graphFile, Target target, int width, int height,
                       int referenceStride = 8);

std::string formatCheckText(const CheckReport& report);

}  // namespace wg::accuracy
