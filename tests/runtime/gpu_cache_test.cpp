// The GpuCache an editor keeps across Renderer rebuilds: identical shader texts reuse the
// linked program, a parameter-default edit renders exactly what a fresh Renderer renders,
// changed texts link only what changed, a PNG saved again is uploaded again, and unused
// entries are dropped beyond the limit.
#include <filesystem>

#include <gtest/gtest.h>

#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/gpu_cache.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

CompileResult compileGlsl330(const Graph& graph) {
  Diagnostics diags;
  CompileOptions options;
  options.targets = {Target::Glsl330};
  auto result = compileGraph(graph, defaultRegistry(), options, diags);
  if (!result) {
    ADD_FAILURE() << graph.file << " does not compile";
    return CompileResult{};
  }
  return std::move(*result);
}

Graph loadExample(const std::string& name) {
  Diagnostics diags;
  auto g = loadGraphFile(test::sourcePath("graphs/" + name + ".json"), diags);
  if (!g) throw std::runtime_error(name + " does not load");
  return std::move(*g);
}

std::unique_ptr<Renderer> makeRenderer(const CompileResult& r, GpuCache* cache) {
  return std::make_unique<Renderer>(r.manifest, waterShaderSources(r, Target::Glsl330), test::smallSettings(), false,
                                    textureOrigins(r), cache);
}

Image renderOnce(Renderer& r) {
  r.renderFrame();
  return r.readRgba8();
}

TEST(GpuCache, IdenticalTextsReuseEveryProgram) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  GpuCache cache;
  CompileResult lake = compileGlsl330(loadExample("lake"));
  auto first = makeRenderer(lake, &cache);
  Image a = renderOnce(*first);
  EXPECT_EQ(cache.stats().programLinks, 4u);  // sky, opaque scene, output transform, water
  first.reset();
  auto second = makeRenderer(lake, &cache);
  EXPECT_EQ(cache.stats().programLinks, 4u);
  EXPECT_EQ(cache.stats().programHits, 4u);
  Image b = renderOnce(*second);
  EXPECT_EQ(a.rgba8, b.rgba8);
}

TEST(GpuCache, ParameterDefaultEditKeepsTheProgramAndShowsTheNewValue) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  GpuCache cache;
  Graph graph = loadExample("lake");
  CompileResult before = compileGlsl330(graph);
  Image shown = renderOnce(*makeRenderer(before, &cache));

  // The shallow colour made red: a uniform default, so no shader text changes.
  bool edited = false;
  for (auto& p : graph.parameters)
    if (p.name == "shallow") p.defaultValue = {0.9, 0.05, 0.05}, edited = true;
  ASSERT_TRUE(edited) << "lake has no 'shallow' parameter";
  CompileResult after = compileGlsl330(graph);
  size_t links = cache.stats().programLinks;
  Image cached = renderOnce(*makeRenderer(after, &cache));
  EXPECT_EQ(cache.stats().programLinks, links) << "a default edit must not relink";
  Image fresh = renderOnce(*makeRenderer(after, nullptr));
  EXPECT_EQ(cached.rgba8, fresh.rgba8) << "the cached program must show the edited default";
  EXPECT_NE(cached.rgba8, shown.rgba8) << "the edit must show";
}

TEST(GpuCache, ChangedWaterTextLinksOnlyTheWater) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  GpuCache cache;
  auto lake = makeRenderer(compileGlsl330(loadExample("lake")), &cache);
  size_t links = cache.stats().programLinks;
  auto shelf = makeRenderer(compileGlsl330(loadExample("shelf")), &cache);
  EXPECT_EQ(cache.stats().programLinks, links + 1);  // the sky, opaque scene and output transform are shared
  EXPECT_EQ(cache.stats().programs, 5u);             // both water programs are in use
}

TEST(GpuCache, PngSavedAgainIsUploadedAgain) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  std::string dir = test::makeTempDir("wg_gpu_cache");
  auto writeFoam = [&](unsigned char grey, int secondsLater) {
    Image img;
    img.width = img.height = 4;
    img.rgba8.assign(4 * 4 * 4, grey);
    writePng(dir + "/foam.png", img);
    // File times can be coarse: make the second save visibly later.
    auto t = std::filesystem::file_time_type::clock::now() + std::chrono::seconds(secondsLater);
    std::filesystem::last_write_time(dir + "/foam.png", t);
  };
  test::writeFile(dir + "/g.json", R"({
  "version": 1,
  "name": "foam_texture",
  "nodes": [
    {"id": "f", "type": "edge_foam", "options": {"texture": "foam.png"}, "inputs": {"depth": 0.2}}
  ],
  "outputs": {"fragment": {"color": "f.foam"}}
})");
  writeFoam(40, 0);
  Diagnostics diags;
  auto graph = loadGraphFile(dir + "/g.json", diags);
  ASSERT_TRUE(graph) << "the test graph does not load";
  CompileResult r = compileGlsl330(*graph);
  GpuCache cache;
  Image dark = renderOnce(*makeRenderer(r, &cache));
  Image again = renderOnce(*makeRenderer(r, &cache));
  EXPECT_EQ(cache.stats().textureUploads, 1u);
  EXPECT_EQ(cache.stats().textureHits, 1u);
  EXPECT_EQ(dark.rgba8, again.rgba8);
  writeFoam(250, 5);
  Image light = renderOnce(*makeRenderer(r, &cache));
  EXPECT_EQ(cache.stats().textureUploads, 2u);
  EXPECT_NE(dark.rgba8, light.rgba8);
  std::filesystem::remove_all(dir);
}

TEST(GpuCache, DropsUnusedEntriesBeyondTheLimitAndKeepsHeldOnes) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  GpuCache cache(1);
  auto shaders = [](const std::string& value) {
    return std::vector<ShaderSource>{
        {GL_VERTEX_SHADER, "t.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n"},
        {GL_FRAGMENT_SHADER, "t.frag", "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(" + value + "); }\n"}};
  };
  auto held = cache.program(shaders("0.1"), "held");
  cache.program(shaders("0.2"), "dropped at the fourth link");
  cache.program(shaders("0.3"), "kept: the newest unused one then");
  EXPECT_EQ(cache.stats().programs, 3u);  // counted when a program is linked: 0.2 alone was unused
  cache.program(shaders("0.4"), "fourth");
  EXPECT_EQ(cache.stats().programs, 3u);  // held, 0.3, 0.4: 0.2 was dropped
  EXPECT_EQ(cache.program(shaders("0.1"), "held").get(), held.get());
  EXPECT_EQ(cache.stats().programLinks, 4u);
  cache.program(shaders("0.3"), "still cached");
  EXPECT_EQ(cache.stats().programLinks, 4u);
  cache.program(shaders("0.2"), "linked again");
  EXPECT_EQ(cache.stats().programLinks, 5u);
}

}  // namespace
}  // namespace wg::rt
