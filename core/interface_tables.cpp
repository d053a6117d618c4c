#include "core/interface_tables.h"

#include <stdexcept>

#include "core/node_spec.h"

namespace wg {
namespace {

template <class Row, class Id>
const Row& rowOf(std::span<const Row> table, Id id, const char* what) {
  // Tables list their enum in order (interface_tables_test holds them to it), so the
  // enumerator is the row's index.
  auto at = static_cast<size_t>(id);
  if (at < table.size() && table[at].id == id) return table[at];
  throw std::logic_error(std::string("no row for this ") + what + " at its enumerator's index");
}

template <class Row, class Field>
auto parseBy(std::span<const Row> table, Field field, std::string_view name) -> std::optional<decltype(Row::id)> {
  for (const Row& r : table)
    if (r.*field == name) return r.id;
  return std::nullopt;
}

using E = EvalEnvironment;

const BuiltinRow kBuiltins[] = {
    {Builtin::Uv, "uv", Type::Vec2, BuiltinUniform::ProbeUv, &E::uv},
    {Builtin::WorldPosition, "world_position", Type::Vec3, BuiltinUniform::ProbeWorldPosition, &E::worldPosition},
    {Builtin::Normal, "normal", Type::Vec3, BuiltinUniform::ProbeNormal, &E::normal},
    {Builtin::ViewDirection, "view_direction", Type::Vec3, BuiltinUniform::ProbeViewDirection, &E::viewDirection},
    {Builtin::CameraPosition, "camera_position", Type::Vec3, BuiltinUniform::CameraPosition, &E::cameraPosition},
    {Builtin::Time, "time", Type::Float, BuiltinUniform::Time, &E::time},
    {Builtin::ScreenUv, "screen_uv", Type::Vec2, BuiltinUniform::ProbeScreenUv, &E::screenUv},
    {Builtin::FragDepth, "frag_depth", Type::Float, BuiltinUniform::ProbeFragDepth, &E::fragDepth},
    {Builtin::CameraNearFar, "camera_near_far", Type::Vec2, BuiltinUniform::CameraNearFar, &E::cameraNearFar},
    {Builtin::View, "view", Type::Mat4, BuiltinUniform::View, &E::view},
    {Builtin::Projection, "projection", Type::Mat4, BuiltinUniform::Projection, &E::projection},
    {Builtin::SunDirection, "sun_direction", Type::Vec3, BuiltinUniform::SunDirection, &E::sunDirection},
    {Builtin::PixelAngle, "pixel_angle", Type::Float, BuiltinUniform::ProbePixelAngle, &E::pixelAngle},
};

using U = BuiltinUniform;
const BuiltinUniformRow kBuiltinUniforms[] = {
    {U::Model, "model", "u_model", Type::Mat4, std::nullopt, {}},
    {U::ViewProjection, "view_projection", "u_view_projection", Type::Mat4, std::nullopt, {}},
    {U::View, "view", "u_view", Type::Mat4, Builtin::View, {"view", "camera"}},
    {U::Projection, "projection", "u_projection", Type::Mat4, Builtin::Projection, {"projection", "camera"}},
    {U::CameraPosition, "camera_position", "u_camera_position", Type::Vec3, Builtin::CameraPosition,
     {"camera_position", "camera"}},
    {U::CameraNearFar, "camera_near_far", "u_camera_near_far", Type::Vec2, Builtin::CameraNearFar, {"near_far", "camera"}},
    {U::Time, "time", "u_time", Type::Float, Builtin::Time, {"time"}},
    {U::ViewportSize, "viewport_size", "u_viewport_size", Type::Vec2, std::nullopt, {}},
    {U::ProbeUv, "uv", "u_probe_uv", Type::Vec2, Builtin::Uv, {"uv"}},
    {U::ProbeWorldPosition, "world_position", "u_probe_world_position", Type::Vec3, Builtin::WorldPosition,
     {"world_position"}},
    {U::ProbeNormal, "normal", "u_probe_normal", Type::Vec3, Builtin::Normal, {"normal"}},
    {U::ProbeViewDirection, "view_direction", "u_probe_view_direction", Type::Vec3, Builtin::ViewDirection,
     {"view_direction", "camera", "camera_position", "world_position"}},
    {U::ProbeScreenUv, "screen_uv", "u_probe_screen_uv", Type::Vec2, Builtin::ScreenUv, {"screen_uv"}},
    {U::ProbeFragDepth, "frag_depth", "u_probe_frag_depth", Type::Float, Builtin::FragDepth, {"frag_depth"}},
    {U::ProbeUvGradient, "uv_gradient", "u_probe_uv_gradient", Type::Vec4, std::nullopt, {"uv_dx", "uv_dy"}},
    {U::ProbePixel, "probe_pixel", "u_probe_pixel", Type::Vec2, std::nullopt, {}},
    {U::ProbePixelAngle, "pixel_angle", "u_probe_pixel_angle", Type::Float, Builtin::PixelAngle, {"pixel_angle"}},
    {U::SunDirection, "sun_direction", "u_sun_direction", Type::Vec3, Builtin::SunDirection, {"sun_direction"}},
    {U::TimePhase, "time_phase", "u_phase", Type::Float, std::nullopt, {"time"}},
};

const OutputSlotRow kOutputSlots[] = {
    {OutputSlot::VertexPosition, "vertex", "position", "vertex.position", kVertexStage, Type::Vec3,
     "vec3: the surface point in world space"},
    {OutputSlot::VertexNormal, "vertex", "normal", "vertex.normal", kVertexStage, Type::Vec3, "vec3: the world-space normal"},
    {OutputSlot::FragmentColor, "fragment", "color", "fragment.color", kFragmentStage, Type::Vec3,
     "vec3 (a float splats to grey)"},
    {OutputSlot::FragmentAlpha, "fragment", "alpha", "fragment.alpha", kFragmentStage, Type::Float, "float"},
};

const RenderPassRow kRenderPasses[] = {
    {RenderPass::OceanSimulation, "ocean_simulation"},
    {RenderPass::EnvironmentCubemap, "environment_cubemap"},
    {RenderPass::DepthPrepass, "depth_prepass"},
    {RenderPass::PlanarReflection, "planar_reflection"},
    {RenderPass::Refraction, "refraction"},
    {RenderPass::OpaqueScene, "opaque_scene"},
    {RenderPass::SceneColorCopy, "scene_color_copy"},
    {RenderPass::DeferredWater, "deferred_water"},
    {RenderPass::WaterSurface, "water_surface"},
    {RenderPass::OutputTransform, "output_transform"},
};

const SceneResourceRow kSceneResources[] = {
    {SceneResource::SceneDepth, "scene_depth", RenderPass::DepthPrepass, SceneSampler::SceneDepth, {"scene.depth"}},
    {SceneResource::SceneColor, "scene_color", RenderPass::SceneColorCopy, SceneSampler::SceneColor, {"scene.color"}},
    {SceneResource::PlanarReflection, "planar_reflection", RenderPass::PlanarReflection, SceneSampler::Reflection,
     {"scene.reflection"}},
    {SceneResource::Refraction, "refraction", RenderPass::Refraction, SceneSampler::Refraction, {"scene.refraction"}},
    {SceneResource::Environment, "environment", RenderPass::EnvironmentCubemap, SceneSampler::Environment,
     {"scene.environment"}},
    // The water G-buffer: the surface builtins the deferred fragment shader reads from it.
    {SceneResource::Underwater, "underwater", RenderPass::DeferredWater, SceneSampler::WaterSurface,
     {"world_position", "frag_depth", "normal", "uv"}},
};

std::array<float, 4> rgb1(const Value& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 1.0f};
}

const SceneSamplerRow kSceneSamplers[] = {
    {SceneSampler::SceneDepth, SceneResource::SceneDepth, "u_scene_depth", Type::Sampler2D, "scene_depth", TargetColor::None,
     true, &E::sceneDepth,
     [](const E& e) {
       float d = static_cast<float>(e.sceneDepth[0]);
       return std::array<float, 4>{d, d, d, 1};
     }},
    {SceneSampler::SceneColor, SceneResource::SceneColor, "u_scene_color", Type::Sampler2D, "scene_color",
     TargetColor::FrameFormat, false, &E::sceneColor, [](const E& e) { return rgb1(e.sceneColor); }},
    {SceneSampler::Reflection, SceneResource::PlanarReflection, "u_reflection", Type::Sampler2D, "reflection",
     TargetColor::FrameFormat, true, &E::reflectionColor, [](const E& e) { return rgb1(e.reflectionColor); }},
    {SceneSampler::Refraction, SceneResource::Refraction, "u_refraction", Type::Sampler2D, "refraction",
     TargetColor::FrameFormat, true, &E::refractionColor, [](const E& e) { return rgb1(e.refractionColor); }},
    {SceneSampler::Environment, SceneResource::Environment, "u_environment", Type::SamplerCube, "environment",
     TargetColor::FrameFormat, false, &E::environmentColor, [](const E& e) { return rgb1(e.environmentColor); }},
    // The water G-buffer, RGBA32F (positions need float precision whatever the frame's
    // format), nearest. The upward normal's x and z and the mesh uv; created first, as
    // water_position's framebuffer draws into it too.
    {SceneSampler::WaterNormalUv, SceneResource::Underwater, "u_water_normal_uv", Type::Sampler2D, "water_normal",
     TargetColor::Float32, false, nullptr,
     [](const E& e) {
       return std::array<float, 4>{static_cast<float>(e.normal[0]), static_cast<float>(e.normal[2]),
                                   static_cast<float>(e.uv[0]), static_cast<float>(e.uv[1])};
     }},
    // The surface's world position (xyz) and depth-buffer value (w; 1.0 where no water).
    {SceneSampler::WaterSurface, SceneResource::Underwater, "u_water_surface", Type::Sampler2D, "water_position",
     TargetColor::Float32, true, nullptr,
     [](const E& e) {
       return std::array<float, 4>{static_cast<float>(e.worldPosition[0]), static_cast<float>(e.worldPosition[1]),
                                   static_cast<float>(e.worldPosition[2]), static_cast<float>(e.fragDepth[0])};
     }},
};

static_assert(std::size(kSceneSamplers) == kSceneSamplerCount);

const BuiltinTextureRow kBuiltinTextures[] = {
    {BuiltinTexture::Dudv, "dudv"},
    {BuiltinTexture::Foam, "foam"},
    {BuiltinTexture::Height, "height"},
    {BuiltinTexture::WaterNormal, "water_normal"},
};

}  // namespace

std::span<const BuiltinRow> builtinTable() { return kBuiltins; }
const BuiltinRow& builtinRow(Builtin b) { return rowOf(builtinTable(), b, "builtin"); }
std::optional<Builtin> parseBuiltin(std::string_view name) { return parseBy(builtinTable(), &BuiltinRow::name, name); }
std::string_view builtinName(Builtin b) { return builtinRow(b).name; }
Type builtinType(Builtin b) { return builtinRow(b).type; }

std::span<const BuiltinUniformRow> builtinUniformTable() { return kBuiltinUniforms; }
const BuiltinUniformRow& builtinUniformRow(BuiltinUniform u) { return rowOf(builtinUniformTable(), u, "builtin uniform"); }
std::optional<BuiltinUniform> parseBuiltinUniform(std::string_view meaning) {
  return parseBy(builtinUniformTable(), &BuiltinUniformRow::meaning, meaning);
}

std::span<const OutputSlotRow> outputSlotTable() { return kOutputSlots; }
const OutputSlotRow& outputSlotRow(OutputSlot s) { return rowOf(outputSlotTable(), s, "output slot"); }
std::string_view outputSlotName(OutputSlot slot) { return outputSlotRow(slot).name; }
std::optional<OutputSlot> parseOutputSlot(std::string_view name) {
  return parseBy(outputSlotTable(), &OutputSlotRow::name, name);
}
std::string_view outputSlotList() {
  static const std::string list = [] {
    std::string s = "(";
    std::string_view stage;
    for (const auto& r : kOutputSlots) {
      if (r.stageName != stage) {
        if (!stage.empty()) s += "; ";
        s.append(r.stageName).append(": ");
        stage = r.stageName;
      } else {
        s += ", ";
      }
      s.append(r.portName);
    }
    return s + ")";
  }();
  return list;
}

std::span<const RenderPassRow> renderPassTable() { return kRenderPasses; }
const RenderPassRow& renderPassRow(RenderPass p) { return rowOf(renderPassTable(), p, "render pass"); }
std::optional<RenderPass> parseRenderPass(std::string_view name) {
  return parseBy(renderPassTable(), &RenderPassRow::name, name);
}

std::span<const SceneResourceRow> sceneResourceTable() { return kSceneResources; }
const SceneResourceRow& sceneResourceRow(SceneResource r) { return rowOf(sceneResourceTable(), r, "scene resource"); }
std::optional<SceneResource> parseSceneResource(std::string_view name) {
  return parseBy(sceneResourceTable(), &SceneResourceRow::name, name);
}

std::span<const SceneSamplerRow> sceneSamplerTable() { return kSceneSamplers; }
const SceneSamplerRow& sceneSamplerRow(SceneSampler s) { return rowOf(sceneSamplerTable(), s, "scene sampler"); }
const SceneSamplerRow* findSceneSampler(std::string_view glslName) {
  for (const auto& r : kSceneSamplers)
    if (r.glslName == glslName) return &r;
  return nullptr;
}

std::span<const BuiltinTextureRow> builtinTextureTable() { return kBuiltinTextures; }
std::optional<BuiltinTexture> parseBuiltinTexture(std::string_view name) {
  return parseBy(builtinTextureTable(), &BuiltinTextureRow::name, name);
}

}  // namespace wg
