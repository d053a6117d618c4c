// The node registry: one line per node type.
#include "nodes/registry.h"

#include "nodes/node_library.h"

namespace wg {

const Registry& defaultRegistry() {
  static const Registry registry = [] {
    Registry r;
    using namespace nodes;
    for (auto make : {
             // inputs
             uvNode, worldPositionNode, normalNode, viewDirectionNode, cameraPositionNode, timeNode, screenUvNode, sunDirectionNode,
             // math
             addNode, subNode, mulNode, divNode, mixNode, clampNode, saturateNode, smoothstepNode, powNode, dotNode,
             crossNode, normalizeNode, lengthNode, sinNode, cosNode, absNode, minNode, maxNode, swizzleNode,
             splitNode, combineNode, remapNode,
             // optics
             fresnelNode,
             // depth and colour
             depthTintNode,
             // output
             vertexOutputNode,
             // optics (reflect, refract, lighting)
             reflectDirNode,
             refractDirNode,
             lambertNode,
             blinnPhongNode,
             phongSpecularNode,
             ggxSpecularNode,
             // depth and colour (depth, absorption, haze, colour variation)
             linearizeDepthNode,
             waterDepthNode,
             absorptionNode,
             hazeNode,
             colorVariationNode,
             // scattering
             subsurfaceNode,
             // waves
             gerstnerWavesNode,
             trochoidWaveNode,
             sineNormalsNode,
             rippleNormalsNode,
             normalMapScrollNode,
             normalFromHeightNode,
             dudvDistortionNode,
             // flow
             flowMapNode,
             // noise
             hashNode, valueNoiseNode, voronoiNode, fbmNode,
             // caustics
             voronoiCausticsNode, textureCausticsNode,
             // foam
             edgeFoamNode, crestFoamNode, coastalFoamNode, shoreWavesNode,
             // screen space
             sceneDepthNode, sceneColorNode, planarReflectionNode, planarRefractionNode, cubemapReflectionNode, ssrNode, underwaterNode,
         })
      r.add(make());
    return r;
  }();
  return registry;
}

}  // namespace wg
