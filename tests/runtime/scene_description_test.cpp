// `watergraph scene`'s description of the built-in scene (runtime/scene_description.h):
// what another renderer builds the scene from must be exactly what the runtime draws.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/interface_tables.h"
#include "runtime/ocean_gpu_shaders.h"
#include "runtime/renderer.h"
#include "runtime/scene_description.h"

namespace wg::rt {
namespace {

nlohmann::json described(const SceneOptions& o = {}) { return nlohmann::json::parse(sceneDescriptionJson(o)); }

glm::vec3 vec3Of(const nlohmann::json& j) { return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()}; }

// Every float of the mesh comes back bit for bit (floats are written as their exact doubles).
TEST(SceneDescription, HoldsTheOpaqueMeshExactly) {
  const nlohmann::json d = described();
  const Mesh mesh = buildSceneMesh();
  const auto& m = d["mesh"];
  int stride = 0;
  for (const auto& a : m["attributes"]) stride += a["components"].get<int>();
  EXPECT_EQ(stride, mesh.floatsPerVertex);
  EXPECT_EQ(m["attributes"].back()["location"], kSceneMaterialLocation);
  ASSERT_EQ(m["vertices"].size(), mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) ASSERT_EQ(m["vertices"][i].get<float>(), mesh.vertices[i]) << i;
  EXPECT_EQ(m["indices"].get<std::vector<unsigned>>(), mesh.indices);
}

TEST(SceneDescription, HoldsTheRuntimesEsShadersCamerasAndSun) {
  SceneOptions o;
  o.sunAzimuthDegrees = 40;
  o.sunElevationDegrees = 12;
  const nlohmann::json d = described(o);
  EXPECT_EQ(d["format"], std::string(kSceneDescriptionFormat));
  const SceneShaderSources s = sceneShaderSources(true);
  EXPECT_EQ(d["shaders"]["sky_vertex"], s.skyVertex);
  EXPECT_EQ(d["shaders"]["sky_fragment"], s.skyFragment);
  EXPECT_EQ(d["shaders"]["opaque_vertex"], s.opaqueVertex);
  EXPECT_EQ(d["shaders"]["opaque_fragment"], s.opaqueFragment);
  EXPECT_EQ(d["shaders"]["fullscreen_vertex"], s.fullscreenVertex);
  EXPECT_EQ(d["shaders"]["water_gbuffer_fragment"], s.waterGbufferFragment);
  // The spectral ocean's passes, each the very text the runtime links on ES (the web
  // clients run them; ThreeClient's open_ocean frames show they work).
  for (int i = 0; i < oceangpu::kOceanPassShaderCount; ++i) {
    const auto shader = static_cast<oceangpu::OceanPassShader>(i);
    EXPECT_EQ(d["shaders"][oceangpu::oceanPassShaderName(shader)], oceangpu::oceanPassFragment(SceneShaderApi::Es300, shader))
        << oceangpu::oceanPassShaderName(shader);
  }
  EXPECT_EQ(vec3Of(d["sun_direction"]), sunDirection(o));
  ASSERT_EQ(d["cameras"].size(), cameraPresetNames().size());
  for (const auto& name : cameraPresetNames()) {
    const Camera c = *cameraPreset(name);
    const auto& j = d["cameras"][name];
    EXPECT_EQ(vec3Of(j["position"]), c.position) << name;
    EXPECT_EQ(vec3Of(j["target"]), c.target) << name;
    EXPECT_EQ(vec3Of(j["up"]), c.up()) << name;
    EXPECT_EQ(j["fov_y_degrees"].get<float>(), c.fovYDegrees) << name;
    EXPECT_EQ(j["near"].get<float>(), c.nearPlane) << name;
    EXPECT_EQ(j["far"].get<float>(), c.farPlane) << name;
  }
  ASSERT_EQ(d["environment"]["faces"].size(), 6u);
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(vec3Of(d["environment"]["faces"][f]["direction"]), environmentFaces()[f].direction) << f;
    EXPECT_EQ(vec3Of(d["environment"]["faces"][f]["up"]), environmentFaces()[f].up) << f;
  }
  EXPECT_EQ(d["environment"]["size"], RenderSettings{}.environmentSize);
  EXPECT_EQ(d["water"]["half_size"].get<float>(), kWaterHalfSize);
  EXPECT_EQ(d["water"]["grid_quads"], RenderSettings{}.waterGridQuads);
}

// The three.js forms: every ES shader of "shaders" again as its version and its body, which
// put back together ("#version " + version + "\n" + body) are the text the test above ties
// to the runtime's own: three.js writes the version line itself (RawShaderMaterial's
// glslVersion, THREE.GLSL3 = "300 es") and takes the body as it is.
TEST(SceneDescription, HoldsEachEsShaderAsVersionAndBodyForThreeJs) {
  const nlohmann::json d = described();
  const nlohmann::json& forms = d["three"]["shaders"];
  ASSERT_EQ(forms.size(), d["shaders"].size());
  EXPECT_EQ(forms.size(), 7u + static_cast<size_t>(oceangpu::kOceanPassShaderCount));
  for (const auto& [name, text] : d["shaders"].items()) {
    ASSERT_TRUE(forms.contains(name)) << name;
    const nlohmann::json& form = forms[name];
    EXPECT_EQ(form.size(), 2u) << name << ": glsl_version and body alone";
    EXPECT_EQ(form["glsl_version"], "300 es") << name;
    EXPECT_EQ("#version " + form["glsl_version"].get<std::string>() + "\n" + form["body"].get<std::string>(),
              text.get<std::string>())
        << name;
  }
  // The bodies are the runtime's own: the ES texts after their version line.
  EXPECT_EQ(forms["sky_vertex"]["body"], sceneShaderBodies(SceneShaderApi::Es300).skyVertex);
  EXPECT_EQ(forms["ocean_pack_filtered"]["body"],
            oceangpu::oceanPassFragmentBody(SceneShaderApi::Es300, oceangpu::OceanPassShader::PackFiltered));
}

// The pass planner's tables, in the runtime's order (clients/three plans from these).
TEST(SceneDescription, HoldsThePlannersTables) {
  const nlohmann::json d = described();
  std::vector<std::string> passes;
  for (const auto& p : renderPassTable()) passes.emplace_back(p.name);
  EXPECT_EQ(d["render_passes"].get<std::vector<std::string>>(), passes);
  ASSERT_EQ(d["render_targets"].size(), sceneSamplerTable().size());
  size_t i = 0;
  for (const auto& row : sceneSamplerTable()) {
    const auto& t = d["render_targets"][i++];
    EXPECT_EQ(t["sampler"], std::string(row.glslName));
    EXPECT_EQ(t["target"], std::string(row.target));
    EXPECT_EQ(t["resource"], std::string(sceneResourceRow(row.resource).name));
    EXPECT_EQ(t["pass"], std::string(renderPassRow(sceneResourceRow(row.resource).pass).name));
    EXPECT_EQ(t["depth"], row.depth);
    EXPECT_EQ(t["cube"], row.type == Type::SamplerCube);
    EXPECT_EQ(t["color"], std::string(row.color == TargetColor::None ? "none" : row.color == TargetColor::Float32 ? "float32" : "frame"));
  }
}

}  // namespace
}  // namespace wg::rt
