#include "runtime_test_support.h"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::test {

std::vector<std::string> exampleGraphNames() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(sourcePath("graphs")))
    if (e.is_regular_file() && e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

CompileResult compileExample(const std::string& name, const std::vector<Target>& targets) {
  Diagnostics diags;
  auto graph = loadGraphFile(sourcePath("graphs/" + name + ".json"), diags);
  std::optional<CompileResult> result;
  if (graph) {
    CompileOptions options;
    options.targets = targets;
    result = compileGraph(*graph, defaultRegistry(), options, diags);
  }
  std::string messages;
  for (const auto& d : diags.all()) messages += formatText(d) + "\n";
  if (!result) ADD_FAILURE() << "graphs/" << name << ".json does not compile:\n" << messages;
  return result ? std::move(*result) : CompileResult{};
}

rt::RenderSettings smallSettings() {
  rt::RenderSettings s;
  s.width = 320;
  s.height = 180;
  s.camera = "above";
  s.scene.time = 3.5f;
  s.waterGridQuads = 128;
  return s;
}

namespace {
// A scene sampler by its GLSL name, from the table the runtime reads.
const SceneSamplerRow& samplerInfo(const std::string& name) {
  const SceneSamplerRow* row = findSceneSampler(name);
  if (!row) throw std::invalid_argument("no scene sampler " + name);
  return *row;
}
}  // namespace

std::vector<rt::ShaderSource> handWaterShaders(bool es, const std::vector<std::string>& samplers) {
  std::string header = es ? "#version 300 es\nprecision highp float;\n" : "#version 330 core\n";
  std::string vert = header + R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_view_projection;
out vec3 v_world;
void main() {
  v_world = (u_model * vec4(a_position, 1.0)).xyz;
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
)";
  std::string frag = header + R"(
in vec3 v_world;
uniform vec2 u_viewport_size;
uniform vec3 u_camera_position;
layout(location = 0) out vec4 o_color;
)";
  std::string body;
  float w = 1.0f / static_cast<float>(std::max<size_t>(samplers.size(), 1));
  for (const auto& s : samplers) {
    const auto& info = samplerInfo(s);
    frag += "uniform " + std::string(typeName(info.type)) + " " + s + ";\n";
    std::string weight = std::to_string(w);
    if (s == "u_environment")
      body += "  c += " + weight + " * texture(u_environment, reflect(-view, vec3(0.0, 1.0, 0.0))).rgb;\n";
    else if (s == "u_scene_depth")
      body += "  c += " + weight + " * vec3(pow(texture(u_scene_depth, uv).r, 64.0));\n";
    else
      body += "  c += " + weight + " * texture(" + s + ", uv).rgb;\n";
  }
  frag += "void main() {\n  vec2 uv = gl_FragCoord.xy / u_viewport_size;\n"
          "  vec3 view = normalize(u_camera_position - v_world);\n  vec3 c = vec3(0.0);\n" +
          body + "  o_color = vec4(c, 1.0);\n}\n";
  std::string ext = es ? "es300" : "glsl330";
  return {{GL_VERTEX_SHADER, "hand." + ext + ".vert", vert}, {GL_FRAGMENT_SHADER, "hand." + ext + ".frag", frag}};
}

nlohmann::json handManifest(const std::vector<std::string>& passes, const std::vector<std::string>& samplers) {
  nlohmann::json m;
  m["passes"] = passes;
  m["passes"].push_back("water_surface");
  m["attributes"] = {{{"name", "a_position"}, {"type", "vec3"}, {"location", 0}}};
  m["uniforms"] = nlohmann::json::array({
      {{"name", "u_model"}, {"type", "mat4"}, {"stages", {"vertex"}}, {"builtin", "model"}},
      {{"name", "u_view_projection"}, {"type", "mat4"}, {"stages", {"vertex"}}, {"builtin", "view_projection"}},
      {{"name", "u_viewport_size"}, {"type", "vec2"}, {"stages", {"fragment"}}, {"builtin", "viewport_size"}},
      {{"name", "u_camera_position"}, {"type", "vec3"}, {"stages", {"fragment"}}, {"builtin", "camera_position"}},
  });
  m["textures"] = nlohmann::json::array();
  for (const auto& s : samplers) {
    const auto& info = samplerInfo(s);
    m["textures"].push_back({{"name", s},
                             {"type", std::string(typeName(info.type))},
                             {"binding", static_cast<int>(m["textures"].size()) + 1},
                             {"stages", {"fragment"}},
                             {"resource", std::string(sceneResourceRow(info.resource).name)}});
  }
  return m;
}

}  // namespace wg::test
