#pragma once
// The built-in, deterministic scene every graph is previewed in: a physical daylight sky
// and sun (runtime/sky_model.h: Preetham et al.'s clear sky at turbidity 2.5, a sun disc
// reddened by its air mass), a tiled pool floor (3.5 m deep) rising into a sloping sandy shore towards -x (so
// depth grows with x, as graphs/shelf.json assumes), pool walls on the other sides, and pillars and rocks crossing the water plane (y = 0), so depth tint,
// edge foam, caustics, reflection and refraction all have something to show. The water
// itself is a 40 x 40 m grid at y = 0 centred on the origin, uv (0,0) at (-20, -20) and
// (1,1) at (20, 20). Everything here is CPU data and GLSL text; nothing calls GL.
//
// Colour: the sky, the sun and the lit scene are linear Rec.709 radiance in one scene
// unit, 1 = 12000 cd/m^2 (sky_model.h, kRadianceUnitCdPerM2): at exposure 0 a daylight sky
// reads ~0.3 to 1.5, a white surface in full sun ~1 to 3, and the sun disc up to
// 30000 (its physical ~9.7e4 at 30 deg is capped, hue kept, below half-float's 65504;
// the opaque scene is lit by the uncapped sun, irradiance = radiance x 6.8e-5 sr). The
// opaque scene is Lambertian: albedo x (sun irradiance x cos + the sky's irradiance) / pi.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/webgpu_shader_form.h"

namespace wg::rt {

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f};
  float fovYDegrees = 55.0f;
  float nearPlane = 0.1f;
  float farPlane = 200.0f;
  glm::vec3 up() const;  // +y, or -z when looking (nearly) straight up or down
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

// "above", "grazing", "underwater", "topdown".
const std::vector<std::string>& cameraPresetNames();
std::optional<Camera> cameraPreset(std::string_view name);

// An object floating on the water: where it is and which way its up axis points (the
// surface normal there). runtime/floating_buoys.h computes them from a graph.
struct FloatingPose {
  glm::vec3 position{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  bool operator==(const FloatingPose&) const = default;
};

struct SceneOptions {
  double time = 3.5;              // seconds (u_time is its float; phases take it in double)
  float sunAzimuthDegrees = 110;  // from +x towards +z
  float sunElevationDegrees = 30; // above the horizon; any value in [-90, 90] (below 0: twilight, then night)
  // false: none of the built-in scene (sky, floor, shore, pillars, rocks) is drawn in any
  // pass; the frame and every scene target keep their clear colour, opaque black. Only the
  // water is drawn: for comparing the water alone with another renderer (clients/three).
  bool drawScene = true;
  // The built-in scene's buoys, where they float this frame (none: no buoys). Drawn with the
  // opaque scene in every pass that draws it (GL runtime only).
  std::vector<FloatingPose> buoys;
};
glm::vec3 sunDirection(const SceneOptions& o);  // unit vector towards the sun

// Interleaved vertices and triangle indices.
struct Mesh {
  std::vector<float> vertices;
  std::vector<unsigned> indices;
  int floatsPerVertex = 0;
  size_t vertexCount() const { return floatsPerVertex ? vertices.size() / static_cast<size_t>(floatsPerVertex) : 0; }
};

// Opaque scene: position (location 0), normal (1), material id as float (3).
// Materials: 0 terrain (tiles / sand by position), 1 pillar stone, 2 rock, 3 and 4 a buoy's
// red body and white top (runtime/floating_buoys.h).
inline constexpr int kSceneMaterialLocation = 3;
Mesh buildSceneMesh();
float terrainHeight(float x, float z);  // the floor / shore height field

// The environment_cubemap pass: six 90-degree views from the origin, one per cube face in
// GL's face order (+x, -x, +y, -y, +z, -z), with GL's up vector for each face, and the
// projection's near and far planes. Only the sky is drawn into them.
struct EnvironmentFace {
  glm::vec3 direction, up;
};
const std::vector<EnvironmentFace>& environmentFaces();
inline constexpr float kEnvironmentNear = 0.1f, kEnvironmentFar = 10.0f;

// Water grid: a_position (0), a_normal (1), a_uv (2) per codegen/shader_interface.h.
inline constexpr float kWaterHalfSize = 20.0f;
Mesh buildWaterGrid(int quadsPerSide = 128);

// GLSL for the runtime's own passes. `es` picks "#version 300 es" with highp defaults
// (clip planes by discard) or "#version 330 core" (clip planes by gl_ClipDistance).
struct SceneShaderSources {
  std::string skyVertex, skyFragment;      // full-screen triangle at the far plane
  std::string opaqueVertex, opaqueFragment;  // lit scene, optional clip plane
  // Deferred water: a full-screen triangle (no outputs, for the graph's fragment shader)
  // and the G-buffer fragment shader behind the graph's vertex shader.
  std::string fullscreenVertex, waterGbufferFragment;
};
SceneShaderSources sceneShaderSources(bool es);
// The same bodies for any API. Vulkan (GLSL 450, compiled to SPIR-V by the Vulkan runtime):
// every in/out has a location, the uniforms of the sky and the opaque scene are push
// constants (sky: mat4 u_inverse_view_projection at 0, vec3 u_sun_direction at 64;
// opaque: mat4 u_view_projection at 0, vec4 u_clip_plane at 64, vec3 u_sun_direction at
// 80), and the G-buffer fragment shader reads the graph's varyings at the locations its
// vertex shader writes them (the manifest's varyings order). WebGpu450: the form naga reads
// for a WebGPU host (runtime/webgpu_shader_form.h): one std140 uniform block at group 0
// binding 0, separate textures and one sampler, clip planes by discard as on ES, and vertex
// stages converting gl_Position to WebGPU's clip space.
enum class SceneShaderApi { Gl330, Es300, Vulkan450, WebGpu450 };
struct GbufferInputLocations {
  int worldPosition = 0, normal = 1, uv = 2;
};
SceneShaderSources sceneShaderSources(SceneShaderApi api, const GbufferInputLocations& gbuffer = {});
// Every runtime shader's text is its version line and a body. The body alone, with the
// version apart, is the form a host that writes the version line itself takes (three.js's
// RawShaderMaterial puts its own #defines right after the line it writes from its
// glslVersion): the scene description carries the ES 3.00 bodies so ("three").
// sceneShaderSources(api) is sceneShaderBodies(api) with glslVersionLine(api) before each.
SceneShaderSources sceneShaderBodies(SceneShaderApi api, const GbufferInputLocations& gbuffer = {});
// What follows "#version " on the first line: "330 core", "300 es", "450".
std::string_view glslVersion(SceneShaderApi api);
// "#version " + glslVersion(api) + "\n".
std::string glslVersionLine(SceneShaderApi api);
// The first lines of every runtime shader's body for `api`: ES precision defaults, and the
// WG_LOCATION / WG_VERTEX_ID / WG_CLIP_DISTANCE macros the bodies use.
std::string sceneShaderPreamble(SceneShaderApi api);
// Each scene shader's interface, by its name in the scene description: what its WebGPU form
// declares and its declaration table describes (runtime/webgpu_shader_form.h).
struct SceneShaderInterface {
  const char* name;
  const char* stage;  // "vertex" or "fragment"
  ShaderInterface interface;
};
std::vector<SceneShaderInterface> sceneShaderInterfaces(const GbufferInputLocations& gbuffer = {});

}  // namespace wg::rt
