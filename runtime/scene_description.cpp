#include "runtime/scene_description.h"

#include <map>
#include <utility>
#include <vector>
#include <nlohmann/json.hpp>

#include "core/interface_tables.h"
#include "runtime/floating_buoys.h"
#include "runtime/ocean_gpu_shaders.h"
#include "runtime/output_transform.h"
#include "runtime/renderer.h"
#include "runtime/webgpu_shader_form.h"

namespace wg::rt {
namespace {

using nlohmann::json;

// Floats go in as their exact doubles, so a reader gets every bit back.
json vec3(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

json camera(const Camera& c) {
  return {{"position", vec3(c.position)}, {"target", vec3(c.target)}, {"up", vec3(c.up())},
          {"fov_y_degrees", c.fovYDegrees}, {"near", c.nearPlane}, {"far", c.farPlane}};
}

const char* colorName(TargetColor c) {
  switch (c) {
    case TargetColor::None: return "none";
    case TargetColor::FrameFormat: return "frame";
    case TargetColor::Float32: return "float32";
  }
  return "none";
}

}  // namespace

std::string sceneDescriptionJson(const SceneOptions& options) {
  json d;
  d["format"] = kSceneDescriptionFormat;
  for (const auto& name : cameraPresetNames()) d["cameras"][name] = camera(*cameraPreset(name));
  d["sun_direction"] = vec3(sunDirection(options));
  // Every pass clears its colour to opaque black before drawing (renderer.cpp bindTarget).
  d["clear_color"] = json::array({0.0, 0.0, 0.0, 1.0});

  json faces = json::array();
  for (const EnvironmentFace& f : environmentFaces()) faces.push_back({{"direction", vec3(f.direction)}, {"up", vec3(f.up)}});
  d["environment"] = {{"faces", faces}, {"fov_y_degrees", 90.0}, {"near", kEnvironmentNear}, {"far", kEnvironmentFar},
                      {"size", RenderSettings{}.environmentSize}};
  d["water"] = {{"grid_quads", RenderSettings{}.waterGridQuads}, {"half_size", kWaterHalfSize}};

  const Mesh mesh = buildSceneMesh();
  d["mesh"] = {{"attributes", json::array({{{"name", "a_position"}, {"location", 0}, {"components", 3}},
                                           {{"name", "a_normal"}, {"location", 1}, {"components", 3}},
                                           {{"name", "a_material"}, {"location", kSceneMaterialLocation}, {"components", 1}}})},
               {"vertices", mesh.vertices},
               {"indices", mesh.indices}};

  // The floating buoys (runtime/floating_buoys.h): where they rest on the water, and one
  // buoy in its own space (up +y, the water line at y = 0) in the mesh's layout. A renderer
  // places it each frame where the surface query puts each rest point, rotating positions
  // and normals as the runtime does: x and z turned with the up axis, the heading fixed.
  json rests = json::array();
  for (const glm::dvec2& p : buoyRestPoints()) rests.push_back(json::array({p.x, p.y}));
  const Mesh buoy = buoyMesh({FloatingPose{}});
  d["buoys"] = {{"rest_points", rests}, {"vertices", buoy.vertices}, {"indices", buoy.indices}};

  // The pass planner's inputs (runtime/pass_plan.cpp): passes in execution order, and per
  // scene sampler its render target, the pass and resource that make it and its format
  // ("frame": the frame's colour format; "float32": RGBA32F; "none": depth only).
  json passes = json::array(), targets = json::array();
  for (const auto& pass : renderPassTable()) passes.push_back(pass.name);
  for (const auto& row : sceneSamplerTable()) {
    const SceneResourceRow& resource = sceneResourceRow(row.resource);
    targets.push_back({{"sampler", row.glslName}, {"target", row.target}, {"resource", resource.name},
                       {"pass", renderPassRow(resource.pass).name}, {"color", colorName(row.color)},
                       {"depth", row.depth}, {"cube", row.type == Type::SamplerCube}});
  }
  d["render_passes"] = passes;
  // Colour: "frame" targets hold linear radiance in RGBA16F (RGBA32F for accuracy work);
  // the output transform pass turns the frame into the displayed image (its fragment
  // shader below: u_frame, u_exposure_scale = 2^EV, u_tone_mapper = the index of the
  // tone mapper in "tone_mappers").
  d["color"] = {{"frame_format", "rgba16f"}, {"display_format", "rgba8"},
                {"tone_mappers", json(std::vector<std::string>(toneMapperNames().begin(), toneMapperNames().end()))},
                {"exposure_range", json::array({kMinExposureEv, kMaxExposureEv})}};
  d["render_targets"] = targets;

  // The runtime's ES 3.00 shaders, each its version line and body (runtime/scene.h): the
  // text under "shaders"; and under "three", the version and the body apart, as a host
  // that writes the version line itself takes them (three.js's RawShaderMaterial with
  // glslVersion "300 es", whose #defines follow that line).
  const SceneShaderSources s = sceneShaderBodies(SceneShaderApi::Es300);
  std::vector<std::pair<std::string, std::string>> bodies = {
      {"sky_vertex", s.skyVertex},           {"sky_fragment", s.skyFragment},
      {"opaque_vertex", s.opaqueVertex},     {"opaque_fragment", s.opaqueFragment},
      {"fullscreen_vertex", s.fullscreenVertex}, {"water_gbuffer_fragment", s.waterGbufferFragment},
      {"output_transform_fragment", outputTransformFragmentBody(SceneShaderApi::Es300)}};
  // The spectral ocean's simulation passes (runtime/ocean_gpu_shaders.h), each drawn with
  // fullscreen_vertex into N x N float targets.
  for (int i = 0; i < oceangpu::kOceanPassShaderCount; ++i) {
    const auto shader = static_cast<oceangpu::OceanPassShader>(i);
    bodies.emplace_back(oceangpu::oceanPassShaderName(shader), oceangpu::oceanPassFragmentBody(SceneShaderApi::Es300, shader));
  }
  const std::string versionLine = glslVersionLine(SceneShaderApi::Es300);
  json threeForms;
  for (const auto& [name, body] : bodies) {
    d["shaders"][name] = versionLine + body;
    threeForms[name] = {{"glsl_version", glslVersion(SceneShaderApi::Es300)}, {"body", body}};
  }
  d["three"] = {{"shaders", threeForms}};

  // The same shaders in the form a WebGPU host hands naga unchanged, each with its
  // declaration table, from which the host lays out bind groups and uniform buffers
  // (runtime/webgpu_shader_form.h; docs/webgpu.md says what each field means).
  const SceneShaderSources w = sceneShaderSources(SceneShaderApi::WebGpu450);
  const std::map<std::string, std::string> texts = {
      {"sky_vertex", w.skyVertex},         {"sky_fragment", w.skyFragment},
      {"opaque_vertex", w.opaqueVertex},   {"opaque_fragment", w.opaqueFragment},
      {"fullscreen_vertex", w.fullscreenVertex}, {"water_gbuffer_fragment", w.waterGbufferFragment}};
  json forms;
  for (const SceneShaderInterface& i : sceneShaderInterfaces())
    forms[i.name] = webgpuShaderTable(i.stage, texts.at(i.name), i.interface);
  forms["output_transform_fragment"] =
      webgpuShaderTable("fragment", outputTransformFragment(SceneShaderApi::WebGpu450), outputTransformInterface());
  for (int i = 0; i < oceangpu::kOceanPassShaderCount; ++i) {
    const auto shader = static_cast<oceangpu::OceanPassShader>(i);
    forms[oceangpu::oceanPassShaderName(shader)] = webgpuShaderTable(
        "fragment", oceangpu::oceanPassFragment(SceneShaderApi::WebGpu450, shader), oceangpu::oceanPassInterface(shader));
  }
  d["webgpu"] = {{"shaders", forms}};
  return d.dump() + "\n";
}

}  // namespace wg::rt
