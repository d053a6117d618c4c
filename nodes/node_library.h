#pragma once
// Every node type's spec factory. Each is defined in its family's file in nodes/ and
// listed once in nodes/registry.cpp.
#include "core/node_spec.h"

namespace wg::nodes {

// inputs.cpp
NodeSpec uvNode();
NodeSpec worldPositionNode();
NodeSpec normalNode();
NodeSpec viewDirectionNode();
NodeSpec cameraPositionNode();
NodeSpec timeNode();
NodeSpec screenUvNode();
NodeSpec sunDirectionNode();
// math.cpp
NodeSpec addNode();
NodeSpec subNode();
NodeSpec mulNode();
NodeSpec divNode();
NodeSpec mixNode();
NodeSpec clampNode();
NodeSpec saturateNode();
NodeSpec smoothstepNode();
NodeSpec powNode();
NodeSpec dotNode();
NodeSpec crossNode();
NodeSpec normalizeNode();
NodeSpec lengthNode();
NodeSpec sinNode();
NodeSpec cosNode();
NodeSpec absNode();
NodeSpec minNode();
NodeSpec maxNode();
NodeSpec swizzleNode();
NodeSpec splitNode();
NodeSpec combineNode();
NodeSpec remapNode();
// fresnel.cpp
NodeSpec fresnelNode();
// depth_tint.cpp
NodeSpec depthTintNode();
// vertex_output.cpp
NodeSpec vertexOutputNode();
// optics_directions.cpp
NodeSpec reflectDirNode();
NodeSpec refractDirNode();
// lighting.cpp
NodeSpec lambertNode();
NodeSpec blinnPhongNode();
NodeSpec phongSpecularNode();
NodeSpec ggxSpecularNode();
// water_depth.cpp
NodeSpec linearizeDepthNode();
NodeSpec waterDepthNode();
// absorption.cpp
NodeSpec absorptionNode();
NodeSpec hazeNode();
// color_variation.cpp
NodeSpec colorVariationNode();
// subsurface.cpp
NodeSpec subsurfaceNode();

// gerstner_waves.cpp
NodeSpec gerstnerWavesNode();
// trochoid_wave.cpp
NodeSpec trochoidWaveNode();
// analytic_normals.cpp
NodeSpec sineNormalsNode();
NodeSpec rippleNormalsNode();
// texture_normals.cpp
NodeSpec normalMapScrollNode();
NodeSpec normalFromHeightNode();
NodeSpec dudvDistortionNode();
// flow_map.cpp
NodeSpec flowMapNode();

// noise.cpp
NodeSpec hashNode();
NodeSpec valueNoiseNode();
NodeSpec fbmNode();
// voronoi.cpp
NodeSpec voronoiNode();
// voronoi_caustics.cpp
NodeSpec voronoiCausticsNode();
// texture_caustics.cpp
NodeSpec textureCausticsNode();
// edge_foam.cpp
NodeSpec edgeFoamNode();
// crest_foam.cpp
NodeSpec crestFoamNode();
// coastal_foam.cpp
NodeSpec coastalFoamNode();
// shore_waves.cpp
NodeSpec shoreWavesNode();

// screen_space.cpp
NodeSpec sceneDepthNode();
NodeSpec sceneColorNode();
NodeSpec planarReflectionNode();
NodeSpec planarRefractionNode();
NodeSpec cubemapReflectionNode();
NodeSpec ssrNode();
// underwater.cpp
NodeSpec underwaterNode();

}  // namespace wg::nodes
