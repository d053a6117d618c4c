#pragma once
// One table per concept of the contract between a graph, its shaders and whoever runs
// them: builtins, builtin uniforms, output slots, scene resources with the samplers and
// render passes behind them, and builtin textures. Each is an enum plus one row per
// entry; every place that names one (loader, schema, editor, emitter, manifest, runtime,
// probe, hard-case suite) iterates its table, so a new entry is one row here and the code
// that produces its value (docs/architecture.md, "Adding a scene resource or a builtin
// uniform"). Rows are in the order the output lists them: reordering changes goldens.
#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "core/types.h"

namespace wg {

struct EvalEnvironment;
struct Value;

enum StageBits : unsigned { kVertexStage = 1u, kFragmentStage = 2u, kAnyStage = 3u };

// Keys of a probe case file that set what a row carries (accuracy/probe_cases.cpp); a
// node whose shader reads the row is probed with every case that gives one of them.
using CaseKeys = std::array<std::string_view, 4>;

// --- Builtins: values a shader stage provides without a node computing them. Input nodes
// expose them; the emitter declares only the attributes, varyings and uniforms the used
// ones need (how each stage computes one is the emitter's builtinExpr).
enum class Builtin {
  Uv,              // vec2, mesh texture coordinate
  WorldPosition,   // vec3, the surface point (after vertex displacement, in fragment)
  Normal,          // vec3, unit world normal (the vertex normal output, in fragment)
  ViewDirection,   // vec3, unit vector from the surface to the camera
  CameraPosition,  // vec3 uniform
  Time,            // float uniform, seconds
  ScreenUv,        // vec2 in [0,1], fragment stage only
  FragDepth,       // float, the surface's depth-buffer value gl_FragCoord.z (fragment only)
  CameraNearFar,   // vec2 uniform: the projection's near and far planes (far may be inf)
  View,            // mat4 uniform: world -> view
  Projection,      // mat4 uniform: view -> clip
  SunDirection,    // vec3 uniform: unit vector towards the sun (the scene's sun)
  PixelAngle,      // float: the angle a pixel subtends at the image centre, 2 / (projection[1][1] viewport.y)
};

// --- Builtin uniforms: what the runtime (or the probe) sets each frame. Declared only when
// used, in this order (shaders use Model..ViewportSize and SunDirection, probe shaders
// View..SunDirection; time phases follow, then parameters).
enum class BuiltinUniform {
  Model,               // mat4, object -> world
  ViewProjection,      // mat4, world -> clip
  View,                // mat4, world -> view
  Projection,          // mat4, view -> clip
  CameraPosition,      // vec3, world
  CameraNearFar,       // vec2, near and far planes
  Time,                // float, seconds
  ViewportSize,        // vec2, pixels
  ProbeUv,             // probe shaders: the per-pixel builtins, set from each case
  ProbeWorldPosition,
  ProbeNormal,
  ProbeViewDirection,
  ProbeScreenUv,
  ProbeFragDepth,
  // Probe shaders: the uv builtin's screen-space derivatives (du/dx, dv/dx, du/dy, dv/dy)
  // and the case's pixel centre; uv varies by them across the pixel's quad, so implicit
  // derivatives (a mipmapped texture()) see the case's gradient (EvalEnvironment::uvDx).
  ProbeUvGradient,
  ProbePixel,
  ProbePixelAngle,     // probe shaders: the pixel angle builtin, set from each case
  SunDirection,        // vec3, unit, towards the sun
  TimePhase,           // float, mod(omega * time, 2 pi) in double; "u_phase<k>", one per omega
};

struct BuiltinRow {
  Builtin id;
  std::string_view name;  // in graph files, docs and manifests: "world_position"
  Type type;
  // The uniform that carries it: in a probe shader every builtin is one, set from the
  // case; a drawn shader reads the uniform builtins (camera, time, ...) from the same
  // one and computes the per-vertex ones (the emitter's builtinExpr).
  BuiltinUniform uniform;
  Value EvalEnvironment::*environment;  // what the CPU reference reads
};
std::span<const BuiltinRow> builtinTable();
const BuiltinRow& builtinRow(Builtin b);
std::optional<Builtin> parseBuiltin(std::string_view name);
std::string_view builtinName(Builtin b);  // "uv", "world_position", ...
Type builtinType(Builtin b);

struct BuiltinUniformRow {
  BuiltinUniform id;
  std::string_view meaning;   // the manifest's "builtin": "model", "time_phase", ...
  std::string_view glslName;  // "u_model" ("u_phase" + k for TimePhase)
  Type type;
  std::optional<Builtin> carries;  // the builtin whose value it holds, if one
  CaseKeys caseKeys;
};
std::span<const BuiltinUniformRow> builtinUniformTable();
const BuiltinUniformRow& builtinUniformRow(BuiltinUniform u);
std::optional<BuiltinUniform> parseBuiltinUniform(std::string_view meaning);

// --- Output slots of a graph ("outputs": {"vertex": {"position": ...}}).
enum class OutputSlot { VertexPosition, VertexNormal, FragmentColor, FragmentAlpha };

struct OutputSlotRow {
  OutputSlot id;
  std::string_view stageName;  // "vertex"
  std::string_view portName;   // "position"
  std::string_view name;       // "vertex.position"
  StageBits stage;
  Type type;                   // what the slot takes (a float splats to a vec3 slot)
  std::string_view doc;        // for the JSON schema
};
std::span<const OutputSlotRow> outputSlotTable();
const OutputSlotRow& outputSlotRow(OutputSlot s);
std::string_view outputSlotName(OutputSlot slot);  // "vertex.position", ...
std::optional<OutputSlot> parseOutputSlot(std::string_view name);  // "vertex.position"
// "(vertex: position, normal; fragment: color, alpha)", for messages.
std::string_view outputSlotList();

// --- Render passes, in the order the runtime runs them: everything the water samples
// first, then the frame itself.
enum class RenderPass {
  // The spectral oceans' maps (ocean_spectrum): evolution, inverse FFT and packing passes
  // per cascade, into float textures the ocean_* readers sample.
  OceanSimulation,
  EnvironmentCubemap,
  DepthPrepass,
  PlanarReflection,
  Refraction,
  OpaqueScene,  // sky + scene into the frame; always runs, not listed in manifests
  SceneColorCopy,
  DeferredWater,  // the water G-buffer; water_surface then runs full-screen
  WaterSurface,
  // The view: the frame's linear radiance through exposure, a tone mapper and the sRGB
  // encoding into the 8-bit image (core/view_transform.h). Runs last in every frame that is
  // shown or written as a picture; not listed in manifests (it is the viewer's, not the
  // graph's) and not run by accuracy renders, which read the linear frame.
  OutputTransform,
};
inline constexpr size_t kRenderPassCount = static_cast<size_t>(RenderPass::OutputTransform) + 1;

struct RenderPassRow {
  RenderPass id;
  std::string_view name;  // in manifests' "passes"
};
std::span<const RenderPassRow> renderPassTable();
const RenderPassRow& renderPassRow(RenderPass p);
std::optional<RenderPass> parseRenderPass(std::string_view name);

// --- Scene resources: what a node samples that the runtime renders. Each makes the
// runtime run the pass that produces it; the manifest lists resources and their passes
// in this order, and the emitter declares their samplers in it.
enum class SceneResource { SceneDepth, SceneColor, PlanarReflection, Refraction, Environment, Underwater };

// The samplers behind the resources (the water G-buffer has two). A sampler is one
// render target of its resource's pass; targets are created in this order.
enum class SceneSampler { SceneDepth, SceneColor, Reflection, Refraction, Environment, WaterNormalUv, WaterSurface };
inline constexpr size_t kSceneSamplerCount = 7;

struct SceneResourceRow {
  SceneResource id;
  std::string_view name;  // "scene_depth", in NodeSpec docs and manifests
  RenderPass pass;        // the pass that produces it
  SceneSampler sampler;   // what EmitContext::sceneTexture(name) gives a node
  CaseKeys caseKeys;
};
std::span<const SceneResourceRow> sceneResourceTable();
const SceneResourceRow& sceneResourceRow(SceneResource r);
std::optional<SceneResource> parseSceneResource(std::string_view name);

// How a render target stores colour: none (depth only), the frame's format (RGBA8, or
// RGBA32F for accuracy renders), or always RGBA32F.
enum class TargetColor { None, FrameFormat, Float32 };

struct SceneSamplerRow {
  SceneSampler id;
  SceneResource resource;
  std::string_view glslName;  // "u_scene_depth"
  Type type;                  // sampler2D or samplerCube (a cube map of the sky)
  std::string_view target;    // the runtime's render target: "scene_depth"
  TargetColor color;
  bool depth;                 // has a DEPTH_COMPONENT32F attachment
  // The reference's value of a look-up at this pixel; null for the water G-buffer, which
  // the reference reads as the surface builtins (world position, depth, normal, uv).
  Value EvalEnvironment::*environment;
  // What every texel holds in a probe case (the probe binds 1x1 textures of it).
  std::array<float, 4> (*caseTexel)(const EvalEnvironment& env);
};
std::span<const SceneSamplerRow> sceneSamplerTable();
const SceneSamplerRow& sceneSamplerRow(SceneSampler s);
const SceneSamplerRow* findSceneSampler(std::string_view glslName);

// --- Builtin textures: deterministic procedural images a Texture option names as
// "builtin:<name>" (nodes/builtin_textures.cpp generates each), so graphs need no assets.
enum class BuiltinTexture { Dudv, Foam, Height, WaterNormal };

struct BuiltinTextureRow {
  BuiltinTexture id;
  std::string_view name;  // after "builtin:"
};
std::span<const BuiltinTextureRow> builtinTextureTable();  // listed in name order
std::optional<BuiltinTexture> parseBuiltinTexture(std::string_view name);

}  // namespace wg
