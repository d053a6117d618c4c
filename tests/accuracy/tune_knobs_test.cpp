// The knobs tune searches (accuracy/tune_knobs.h): those of the graph's own nodes and of the
// nodes inside its subgraph instances ("a/fresnel.model"); only the levels that change what
// the graph compiles to (a wave count above the list's length, a tessellation factor on an
// untessellated surface stand for nothing); a configuration applied changes the shaders.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "accuracy/tune_knobs.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

// Three Gerstner waves on a surface tessellated by distance (or not).
std::string wavesGraph(const std::string& tessellation) {
  return R"({"version": 1, "name": "waves", "nodes": [
    {"id": "waves", "type": "gerstner_waves", "options": {"waves": [
      {"direction": [1, 0.2], "steepness": 0.4, "wavelength": 8},
      {"direction": [0.3, 1], "steepness": 0.3, "wavelength": 5},
      {"direction": [-0.7, 0.6], "steepness": 0.2, "wavelength": 3}]}},
    {"id": "surface", "type": "vertex_output", "options": {"tessellation": ")" + tessellation + R"("},
     "inputs": {"position": "waves.position", "normal": "waves.normal"}},
    {"id": "n", "type": "normal"}],
    "outputs": {"vertex": {"position": "surface.position", "normal": "surface.normal"},
                "fragment": {"color": "n.out"}}})";
}

Graph parse(const std::string& text) {
  Diagnostics d;
  auto g = parseGraph(text, "waves.json", d);
  EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  return *g;
}

const TuneKnob* find(const std::vector<TuneKnob>& knobs, const std::string& name) {
  auto it = std::find_if(knobs.begin(), knobs.end(), [&](const TuneKnob& k) { return k.name() == name; });
  return it == knobs.end() ? nullptr : &*it;
}

// Every knob at its most exact level (the reference tune measures against).
TuneConfig mostExact(const std::vector<TuneKnob>& knobs) {
  TuneConfig config(knobs.size());
  for (size_t k = 0; k < knobs.size(); ++k) config[k] = static_cast<int>(knobs[k].levels.size()) - 1;
  return config;
}

// `config` with knob `knob` (a pointer into `knobs`) at `level`.
TuneConfig withLevel(TuneConfig config, const std::vector<TuneKnob>& knobs, const TuneKnob* knob, int level) {
  config[static_cast<size_t>(knob - knobs.data())] = level;
  return config;
}

std::string fileOf(const Graph& g, const std::string& suffix) {
  Diagnostics d;
  CompileOptions o;
  o.targets = {Target::Glsl330};
  o.validate = false;
  auto r = compileGraph(g, defaultRegistry(), o, d);
  EXPECT_TRUE(r) << (d.all().empty() ? "" : formatText(d.all().front()));
  for (const auto& f : r->files)
    if (f.name.ends_with(suffix)) return f.contents;
  return "";
}

TEST(TuneKnobs, WaveCountAndTessellationFactorAreKnobsWithTheirDistinctLevels) {
  Graph g = parse(wavesGraph("distance"));
  std::vector<TuneKnob> declared = graphKnobs(g);
  ASSERT_TRUE(find(declared, "waves.max_waves"));
  ASSERT_TRUE(find(declared, "surface.factor"));
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, declared, Target::Glsl330, unchanged);
  EXPECT_TRUE(unchanged.empty());
  // Three waves: 3, 4, ... 12 waves are the whole list, as the most exact level (16) is.
  const TuneKnob* waves = find(knobs, "waves.max_waves");
  ASSERT_TRUE(waves);
  EXPECT_EQ(nlohmann::json(waves->levels).dump(), "[1,2,16]");
  const TuneKnob* factor = find(knobs, "surface.factor");
  ASSERT_TRUE(factor);
  EXPECT_EQ(nlohmann::json(factor->levels).dump(), "[1,2,4,8,16]");

  // A level changes the shaders: the first wave only; a factor of 4 in the control stage.
  const TuneConfig exact = mostExact(knobs);
  const TuneConfig cheap = withLevel(withLevel(exact, knobs, waves, 0), knobs, factor, 2);
  Graph exactGraph = withKnobLevels(g, knobs, exact), cheapGraph = withKnobLevels(g, knobs, cheap);
  EXPECT_EQ(test::glslCalls(fileOf(exactGraph, ".glsl330.tese"), "wg_gerstner_wave_add"), 3u) << fileOf(exactGraph, ".glsl330.tese");
  EXPECT_EQ(test::glslCalls(fileOf(cheapGraph, ".glsl330.tese"), "wg_gerstner_wave_add"), 1u);
  EXPECT_NE(fileOf(exactGraph, ".glsl330.tesc").find(", 16.0);"), std::string::npos) << fileOf(exactGraph, ".glsl330.tesc");
  EXPECT_NE(fileOf(cheapGraph, ".glsl330.tesc").find(", 4.0);"), std::string::npos) << fileOf(cheapGraph, ".glsl330.tesc");
}

TEST(TuneKnobs, AKnobNoLevelOfWhichChangesTheShadersIsNotTuned) {
  Graph g = parse(wavesGraph("none"));
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, graphKnobs(g), Target::Glsl330, unchanged);
  EXPECT_EQ(unchanged, std::vector<std::string>{"surface.factor"});
  EXPECT_FALSE(find(knobs, "surface.factor"));
  EXPECT_TRUE(find(knobs, "waves.max_waves"));
}

// The scene-pass resolution changes no shader, only the manifest's pass sizes: tune still
// sees each level as distinct, and a configuration applied sizes the passes.
TEST(TuneKnobs, SceneResolutionIsTunedThoughItChangesNoShader) {
  Graph g = parse(R"({"version": 1, "name": "scene", "nodes": [
    {"id": "d", "type": "scene_depth"}, {"id": "c", "type": "scene_color"},
    {"id": "m", "type": "mul", "inputs": {"a": "c.color", "b": "d.linear"}}],
    "outputs": {"fragment": {"color": "m.out"}}})");
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, graphKnobs(g), Target::Glsl330, unchanged);
  EXPECT_TRUE(unchanged.empty()) << unchanged.front();
  const TuneKnob* depth = find(knobs, "d.resolution");
  const TuneKnob* color = find(knobs, "c.resolution");
  ASSERT_TRUE(depth && color);
  EXPECT_EQ(nlohmann::json(depth->levels).dump(), "[0.25,0.5,0.75,1.0]");
  const TuneConfig config = withLevel(withLevel(mostExact(knobs), knobs, depth, 1), knobs, color, 0);
  std::string manifest = fileOf(withKnobLevels(g, knobs, config), ".manifest.json");
  EXPECT_NE(manifest.find(R"("depth_prepass": 0.5,)"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find(R"("scene_color_copy": 0.25)"), std::string::npos) << manifest;
  EXPECT_EQ(fileOf(withKnobLevels(g, knobs, config), ".glsl330.frag"), fileOf(g, ".glsl330.frag"));
}

// A spectral ocean's foam_step changes no shader (the foam's steps run in the simulation
// passes, from the manifest's ocean options), yet each level is another foam and another
// cost: tune keeps it. fft_size changes the readers' texel scale, a shader change.
// cascade_sizes' levels follow the node's own fft_size and cascade count: every cascade but
// the finest at N/4, then N/2, then none (every cascade at fft_size, the reference). A sea of
// one cascade has no such knob.
TEST(TuneKnobs, TheOceansCascadeSizesLevelsFollowItsCascades) {
  Graph g = parse(R"({"version": 1, "name": "sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [120, 24, 5], "fft_size": 128}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": [0, 0, 0]}}],
    "outputs": {"fragment": {"color": "detail.normal"}}})");
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, graphKnobs(g), Target::Glsl330, unchanged);
  const TuneKnob* sizes = find(knobs, "sea.cascade_sizes");
  ASSERT_TRUE(sizes);
  EXPECT_EQ(nlohmann::json(sizes->levels).dump(), "[[32,32,128],[64,64,128],[]]");
  // A level changes the shaders (the readers' texel scales) and the manifest's options.
  const TuneConfig exact = mostExact(knobs);
  const TuneConfig config = withLevel(exact, knobs, sizes, 0);
  Graph cheap = withKnobLevels(g, knobs, config);
  EXPECT_NE(fileOf(cheap, ".glsl330.frag"), fileOf(withKnobLevels(g, knobs, exact), ".glsl330.frag"));
  EXPECT_NE(fileOf(cheap, ".manifest.json").find(R"("cascade_sizes": [)"), std::string::npos);

  Graph one = parse(R"({"version": 1, "name": "sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [40]}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": [0, 0, 0]}}],
    "outputs": {"fragment": {"color": "detail.normal"}}})");
  EXPECT_FALSE(find(graphKnobs(one), "sea.cascade_sizes"));
}

// cascade_count's levels follow the tiles the node lists: the longest alone, then one more a
// level, to all of them (the reference). A level below reads fewer cascades' maps: the
// shaders and the manifest's options change. A sea of one tile has no such knob.
TEST(TuneKnobs, TheOceansCascadeCountLevelsFollowItsTiles) {
  Graph g = parse(R"({"version": 1, "name": "sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [120, 24, 5], "fft_size": 64}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": [0, 0, 0]}}],
    "outputs": {"fragment": {"color": "detail.normal"}}})");
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, graphKnobs(g), Target::Glsl330, unchanged);
  const TuneKnob* count = find(knobs, "sea.cascade_count");
  ASSERT_TRUE(count);
  EXPECT_EQ(nlohmann::json(count->levels).dump(), "[1,2,3]");
  const TuneConfig exact = mostExact(knobs);
  const TuneConfig config = withLevel(exact, knobs, count, 0);
  Graph cheap = withKnobLevels(g, knobs, config);
  const std::string cheapFrag = fileOf(cheap, ".glsl330.frag"), exactFrag = fileOf(withKnobLevels(g, knobs, exact), ".glsl330.frag");
  EXPECT_NE(cheapFrag, exactFrag);
  // The reference reads the three cascades' slopes, the cheapest level the longest one's only.
  EXPECT_NE(exactFrag.find("u_ocean0_slopes2"), std::string::npos);
  EXPECT_NE(cheapFrag.find("u_ocean0_slopes0"), std::string::npos);
  EXPECT_EQ(cheapFrag.find("u_ocean0_slopes1"), std::string::npos);
  EXPECT_NE(fileOf(cheap, ".manifest.json").find(R"("cascade_count": 1)"), std::string::npos);

  Graph one = parse(R"({"version": 1, "name": "sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [40]}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": [0, 0, 0]}}],
    "outputs": {"fragment": {"color": "detail.normal"}}})");
  EXPECT_FALSE(find(graphKnobs(one), "sea.cascade_count"));
}

TEST(TuneKnobs, TheOceansFoamStepIsTunedThoughItChangesNoShader) {
  Graph g = parse(R"({"version": 1, "name": "sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [40], "fft_size": 64}},
    {"id": "foam", "type": "ocean_foam", "inputs": {"ocean": "sea.ocean", "position": [0, 0, 0]}}],
    "outputs": {"fragment": {"color": "foam.foam"}}})");
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(g, graphKnobs(g), Target::Glsl330, unchanged);
  EXPECT_TRUE(unchanged.empty()) << unchanged.front();
  const TuneKnob* step = find(knobs, "sea.foam_step");
  const TuneKnob* size = find(knobs, "sea.fft_size");
  ASSERT_TRUE(step && size);
  EXPECT_EQ(nlohmann::json(step->levels).dump(), "[0.2,0.1]");
  EXPECT_EQ(nlohmann::json(size->levels).dump(), "[64,128,256]");
  const TuneConfig exact = mostExact(knobs);
  const TuneConfig config = withLevel(exact, knobs, step, 0);
  Graph cheap = withKnobLevels(g, knobs, config);
  EXPECT_EQ(fileOf(cheap, ".glsl330.frag"), fileOf(withKnobLevels(g, knobs, exact), ".glsl330.frag"));
  EXPECT_NE(fileOf(cheap, ".manifest.json").find(R"("foam_step": 0.2)"), std::string::npos) << fileOf(cheap, ".manifest.json");

  // Without ocean_foam no foam is computed: its step changes nothing, and is not tuned.
  Graph noFoam = parse(R"({"version": 1, "name": "sea", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [40], "fft_size": 64}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": [0, 0, 0]}}],
    "outputs": {"fragment": {"color": "detail.normal"}}})");
  unchanged.clear();
  knobs = distinctKnobLevels(noFoam, graphKnobs(noFoam), Target::Glsl330, unchanged);
  EXPECT_EQ(unchanged, std::vector<std::string>{"sea.foam_step"});
  EXPECT_TRUE(find(knobs, "sea.fft_size"));
}

TEST(TuneKnobs, KnobsInsideSubgraphInstancesAreNamedByTheInstance) {
  std::string dir = test::makeTempDir("wg_tune_knobs");
  std::filesystem::create_directories(dir + "/lib");
  test::writeFile(dir + "/lib/blend.json", R"({"version": 1, "name": "blend",
    "interface": {"outputs": {"color": {"type": "vec3", "source": "m.out"}}},
    "nodes": [{"id": "f", "type": "fresnel"},
              {"id": "m", "type": "mix", "inputs": {"a": [0, 0.2, 0.3], "b": [0.6, 0.7, 0.9], "t": "f.reflectance"}}]})");
  test::writeFile(dir + "/g.json", R"({"version": 1, "name": "g", "imports": {"blend": "lib/blend.json"},
    "nodes": [{"id": "own", "type": "fresnel"}, {"id": "near", "type": "blend"},
              {"id": "sum", "type": "add", "inputs": {"a": "near.color", "b": "own.reflectance"}}],
    "outputs": {"fragment": {"color": "sum.out"}}})");
  Diagnostics d;
  auto g = loadGraphFile(dir + "/g.json", d);
  ASSERT_TRUE(g);
  std::vector<TuneKnob> knobs = graphKnobs(*g);
  ASSERT_EQ(knobs.size(), 2u);
  EXPECT_EQ(knobs[0].name(), "own.model");
  EXPECT_EQ(knobs[1].name(), "near/f.model");
  // Applied: the instance's Fresnel takes Schlick (power < schlick < exact), the graph's own
  // stays exact.
  TuneConfig config{static_cast<int>(knobs[0].levels.size()) - 1, 1};
  std::string frag = fileOf(withKnobLevels(*g, knobs, config), ".glsl330.frag");
  EXPECT_EQ(test::glslCalls(frag, "wg_fresnel_exact"), 1u) << frag;
  EXPECT_EQ(test::glslCalls(frag, "wg_fresnel_schlick"), 1u) << frag;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg::accuracy
