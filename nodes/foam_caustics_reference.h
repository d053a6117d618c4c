#pragma once
// The double-precision formulas of the caustics and foam nodes, shared by their evals and
// tests (each mirrors its nodes/glsl/*.glsl function operation for operation).
#include "core/value.h"

namespace wg::nodes {

// voronoi_caustics: one layer's (1 - clamp(F1, 0, 1))^3.
double voronoiCausticsIntensity(double f1);
// texture_caustics: clamp(1 - |a + b - 1|, 0, 1)^9.
double textureCausticsShape(double a, double b);
// edge_foam: the depth mask (smooth: the advanced shaders tutorial, else the stylized water shader's linear) and the cut-off.
double edgeFoamMask(bool smooth, double depth, double width);
double edgeFoamCut(double tex, double mask, double cutoff, double softness, double strength);
// crest_foam: the top-down water plan's calculateFoam (y up), drifts already wrapped.
double crestFoamReference(double height, const Value& normal, double x, double z, double drift1, double drift2,
                          double threshold, double intensity, double coverage, double sharpness);
// coastal_foam: the amount before the texture, and the specular scale.
double coastalFoamAmount(double depth, double maxDepth, double intensity, double crest);
double coastalFoamSpecular(double foam, double k, bool cubic);
// shore_waves, phase = mod(speed t, 2 pi).
double shoreWavesReference(double depth, double frequency, double phase, double amplitude, double distance);

}  // namespace wg::nodes
