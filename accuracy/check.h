#pragma once
// `watergraph check`: a compiled graph rendered into an RGBA32F frame over a sweep of
// views — camera elevation from grazing to top-down, under water when the graph has the
// deferred underwater pass, times up to 1e6 s, sun positions — counting NaN and Inf
// pixels. On glsl330, vk450 and wgsl the frame is compared, on a grid of sampled water pixels, with the
// double reference of the graph's fragment stage evaluated on the inputs the GPU's
// fragment shader had there, read back (accuracy/readback.h: varyings of the displaced
// surface, depth, scene and node texture look-ups), and each sample is held to the
// graph's error bound (accuracy/error_bound.h), as the probe holds a case: the largest
// tolerance of its ops plus the conditioning of the pixel's float32 inputs. A graph whose
// inputs cannot be read back that way (deferred water) is only checked for NaN and Inf.
#include <string>
#include <vector>

#include "accuracy/probe.h"
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

struct CheckOptions {
  int width = 160, height = 90;
  int referenceStride = 8;  // every Nth pixel in each direction is compared
  bool errorMaps = false;   // keep every view's per-pixel errors (CheckViewResult::errors)
  bool keepFrames = false;  // keep every view's frame (CheckViewResult::frame), to compare targets
  ShaderMutation mutation;  // applied to the water shaders: a wrong node, for tests
};

struct CheckViewResult {
  std::string label;
  long pixels = 0, nan = 0, inf = 0;
  int referenceSamples = 0;  // pixels compared with the CPU reference (0: none)
  double maxError = 0, meanError = 0;
  int overBound = 0;          // samples with a component over its error bound
  double worstRatio = 0;      // largest error / bound over the samples
  // With CheckOptions::errorMaps, per pixel (rows top to bottom): the largest error over
  // R, G and B, and the largest error / bound; -1 where the pixel was not compared.
  std::vector<float> errors, ratios;
  std::vector<float> frame;  // with errorMaps or keepFrames: the frame's linear RGBA (rows top to bottom)
};

struct CheckReport {
  std::string graph;
  Target target = Target::Glsl330;
  std::string targetLabel;  // what the report names: the target's name, or "wgsl" (whose target is es300's plan)
  int width = 0, height = 0;
  std::string reference;  // "cpu" when compared, else why not
  // The graph's scene passes below the frame's size ("depth_prepass at 0.5"): check renders
  // them at the frame's size (the read-back reads scene images a texel per frame pixel).
  std::vector<std::string> scaledPasses;
  std::vector<CheckViewResult> views;
  long nanInf() const;
  int samples() const;     // compared pixels over every view
  double maxError() const;
  double meanError() const;  // over every compared component of every view
  int overBound() const;
  double worstRatio() const;
  bool failed() const { return nanInf() > 0 || overBound() > 0; }
};

// Why the graph's colour cannot be compared at all (none, or blended by alpha), or "";
// checkGraph adds the read-back's reasons (planReadback).
std::string referenceUnavailable(const CompileResult& result);

class GpuExecutor;

// Renders every view on `executor` (accuracy/gpu_executor.h; `result` compiled for its
// target). Throws rt::RuntimeError for driver or manifest problems (on vk450 with
// validation, any message of the layer), std::invalid_argument for a mutation whose text
// is not in the water shaders.
CheckReport checkGraph(const CompileResult& result, const std::string& graphFile, GpuExecutor& executor,
                       const CheckOptions& options = {});
// The same on the current GL context, whose API must match `target` (glsl330 or es300).
CheckReport checkGraph(const CompileResult& result, const std::string& graphFile, Target target,
                       const CheckOptions& options = {});

// The error image of the view with the largest error/bound (the first compared view when
// none has an error): per compared pixel a grey level on a log scale, black at 1e-8 or
// less, white at 1e-3; red where the pixel is over its error bound; dark blue where the
// pixel was not compared (not water, near a silhouette, or no reference). Empty (0 x 0)
// without error maps or compared pixels.
// Pixels not compared show the frame through `view` (core/view_transform.h) darkened and
// tinted blue (red and green below 64, blue from 64), so the compared ones stand out over a
// picture of the scene.
rt::Image errorMapImage(const CheckReport& report, const ViewTransform& view = {});

std::string formatCheckText(const CheckReport& report);

}  // namespace wg::accuracy
