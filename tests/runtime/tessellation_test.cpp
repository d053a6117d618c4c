// Distance-based tessellation (vertex_output, the stylized water shader): glsl330 and vk450 get control and
// evaluation stages, es300 (no tessellation in GLSL ES 3.00) draws the mesh as it is, and
// the runtime draws patches: more triangles near the camera, the same picture otherwise.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime_test_support.h"

namespace wg {
namespace {

std::string wavesGraph(const std::string& tessellation) {
  return R"({
  "version": 1,
  "name": "tess",
  "nodes": [
    {"id": "waves", "type": "gerstner_waves",
     "options": {"waves": [{"direction": [1, 0.2], "steepness": 0.5, "wavelength": 6}]}},
    {"id": "surface", "type": "vertex_output",
     "options": {"tessellation": ")" + tessellation + R"(", "factor": 8},
     "inputs": {"position": "waves.position", "normal": "waves.normal"}},
    {"id": "fresnel", "type": "fresnel"},
    {"id": "tint", "type": "mix", "inputs": {"a": [0.0, 0.3, 0.5], "b": [0.8, 0.9, 1.0], "t": "fresnel.reflectance"}}
  ],
  "outputs": {"vertex": {"position": "surface.position", "normal": "surface.normal"},
              "fragment": {"color": "tint.out"}}
})";
}

CompileResult compile(const std::string& text) {
  Diagnostics diags;
  auto graph = parseGraph(text, "tess.json", diags);
  EXPECT_TRUE(graph);
  auto result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  std::string messages;
  for (const auto& d : diags.all()) messages += formatText(d) + "\n";
  EXPECT_TRUE(result) << messages;
  return *result;
}

bool hasFile(const CompileResult& r, const std::string& name) {
  for (const auto& f : r.files)
    if (f.name == name) return true;
  return false;
}

TEST(Tessellation, StagesPerTarget) {
  CompileResult r = compile(wavesGraph("distance"));
  for (const char* t : {"glsl330", "vk450"}) {
    EXPECT_TRUE(hasFile(r, std::string("tess.") + t + ".tesc")) << t;
    EXPECT_TRUE(hasFile(r, std::string("tess.") + t + ".tese")) << t;
  }
  EXPECT_TRUE(hasFile(r, "tess.vk450.tese.spv"));
  EXPECT_FALSE(hasFile(r, "tess.es300.tesc"));
  EXPECT_FALSE(hasFile(r, "tess.es300.tese"));
  ASSERT_TRUE(r.manifest.tessellation);
  EXPECT_EQ(r.manifest.toJson()["tessellation"]["patch_vertices"], 3);
  EXPECT_EQ(r.manifest.tessellation->settings.factor, 8.0);
  EXPECT_EQ(r.manifest.tessellation->targets, (std::vector<std::string>{"glsl330", "vk450"}));

  CompileResult flat = compile(wavesGraph("none"));
  EXPECT_FALSE(hasFile(flat, "tess.glsl330.tesc"));
  EXPECT_FALSE(flat.manifest.tessellation);
}

TEST(Tessellation, WavesRunInTheEvaluationStage) {
  CompileResult r = compile(wavesGraph("distance"));
  for (const auto& f : r.files) {
    if (f.name == "tess.glsl330.tese") {
      EXPECT_NE(f.contents.find("wg_gerstner"), std::string::npos);
    }
    if (f.name == "tess.glsl330.vert") {
      EXPECT_EQ(f.contents.find("wg_gerstner"), std::string::npos);
    }
    if (f.name == "tess.glsl330.tesc") {
      EXPECT_NE(f.contents.find("#extension GL_ARB_tessellation_shader : require"), std::string::npos);
      EXPECT_NE(f.contents.find("wg_tess_distance_factor"), std::string::npos);
    }
  }
}

TEST(Tessellation, RendersLikeTheUntessellatedSurface) {
  rt::RenderSettings s = test::smallSettings();
  rt::Preview tess = rt::renderPreview(compile(wavesGraph("distance")), Target::Glsl330, s);
  rt::Preview flat = rt::renderPreview(compile(wavesGraph("none")), Target::Glsl330, s);
  rt::Preview es = rt::renderPreview(compile(wavesGraph("distance")), Target::Es300, s);
  s.floatColor = true;
  rt::Preview tessFloat = rt::renderPreview(compile(wavesGraph("distance")), Target::Glsl330, s);
  EXPECT_EQ(rt::countNonFinite(tessFloat.image), 0u);
  // Finer geometry moves the wave silhouettes a little; the picture is the same water.
  EXPECT_GT(rt::psnrRgb8(tess.image, flat.image), 25.0);
  EXPECT_GT(rt::psnrRgb8(es.image, flat.image), 40.0);  // es300 falls back to the mesh
}

}  // namespace
}  // namespace wg
