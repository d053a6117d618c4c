// The manifest value and its JSON: what the compiler writes reads back into the same value
// (toJson after fromJson gives the file byte for byte), for every example graph, with a
// preset and with the SPIRV-Cross targets; and fromJson refuses what the compiler would not
// write, naming the entry.
#include <gtest/gtest.h>

#include <functional>
#include <optional>

#include "codegen/compile.h"
#include "codegen/manifest.h"
#include "codegen/spirv_cross_targets.h"
#include "core/ocean_settings.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

std::optional<Graph> loadExample(const std::string& path) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  EXPECT_TRUE(graph) << path;
  return graph;
}

const OutputFile& manifestFile(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name.ends_with(".manifest.json")) return f;
  throw std::logic_error("the compile wrote no manifest");
}

// The manifest file of a compile, read back as a runtime reading it from disk would, is the
// value the compile returned: written again, it is the same bytes.
void expectRoundTrip(const CompileResult& r) {
  const std::string& text = manifestFile(r).contents;
  EXPECT_EQ(r.manifest.toJson().dump(2) + "\n", text) << "CompileResult::manifest is what the file says";
  Manifest read = Manifest::fromJson(nlohmann::json::parse(text));
  EXPECT_EQ(read.toJson().dump(2) + "\n", text);
}

TEST(Manifest, EveryExampleGraphReadsBackByteForByte) {
  for (const auto& path : test::exampleGraphs()) {
    SCOPED_TRACE(path);
    auto graph = loadExample(path);
    ASSERT_TRUE(graph);
    CompileOptions options;
    options.validate = false;  // the manifest does not depend on glslang
    Diagnostics diags;
    auto r = compileGraph(*graph, defaultRegistry(), options, diags);
    ASSERT_TRUE(r);
    expectRoundTrip(*r);
  }
}

TEST(Manifest, PresetAndCrossTargetsReadBack) {
  auto graph = loadExample(test::sourcePath("graphs/stylized.json"));  // tessellated: HLSL gets the flat mesh
  ASSERT_TRUE(graph);
  Diagnostics diags;
  CompileOptions options;
  options.targets = {Target::Glsl330};
  auto r = compileGraphWithCross(*graph, defaultRegistry(), options, allCrossTargets(), diags);
  ASSERT_TRUE(r);
  const ManifestTarget* msl = r->manifest.target("msl");
  ASSERT_TRUE(msl);
  EXPECT_FALSE(msl->from.empty());
  EXPECT_EQ(msl->files.front().entryPoint, "main0");
  EXPECT_FALSE(r->manifest.target("vk450")) << "vk450 was only the cross targets' input";
  expectRoundTrip(*r);

  auto topdown = loadExample(test::sourcePath("graphs/topdown.json"));
  ASSERT_TRUE(topdown);
  CompileOptions calm;
  calm.preset = "calm";
  calm.validate = false;
  auto withPreset = compileGraph(*topdown, defaultRegistry(), calm, diags);
  ASSERT_TRUE(withPreset);
  EXPECT_EQ(withPreset->manifest.preset, "calm");
  expectRoundTrip(*withPreset);
}

// The stylized graph's manifest (textures, time phases, parameters, tessellation) as JSON.
nlohmann::json stylizedManifest() {
  return nlohmann::json::parse(test::readFile(test::sourcePath("tests/golden/stylized/stylized.manifest.json")));
}

nlohmann::json& firstWith(nlohmann::json& list, const std::string& key, const nlohmann::json& value = nullptr) {
  for (auto& e : list)
    if (e.contains(key) && (value.is_null() || e[key] == value)) return e;
  throw std::logic_error("no entry with " + key);
}

TEST(Manifest, MergedNodesReadBack) {
  nlohmann::json m = stylizedManifest();
  m["nodes"]["kept"][0]["merged"] = {"twin", "triplet"};
  EXPECT_EQ(Manifest::fromJson(m).toJson(), m);
  EXPECT_EQ(Manifest::fromJson(m).kept[0].merged, (std::vector<std::string>{"twin", "triplet"}));
}

struct BadManifest {
  const char* what;
  std::function<void(nlohmann::json&)> edit;
  const char* message;  // a part of the error
};

TEST(Manifest, FromJsonNamesWhatIsWrong) {
  const std::vector<BadManifest> cases = {
      {"not an object", [](auto& m) { m = nlohmann::json::array(); }, "not a JSON object"},
      {"no passes", [](auto& m) { m.erase("passes"); }, "no \"passes\" list"},
      {"unknown pass", [](auto& m) { m["passes"].push_back("ssao"); }, "unknown pass 'ssao'"},
      {"unknown member", [](auto& m) { m["shaders"] = 1; }, "the manifest has an unknown member \"shaders\""},
      {"other format", [](auto& m) { m["format"] = 2; }, "format 2"},
      {"uniforms not a list", [](auto& m) { m["uniforms"] = nlohmann::json::object(); }, "\"uniforms\" is not a list"},
      {"unknown builtin", [](auto& m) { firstWith(m["uniforms"], "builtin")["builtin"] = "wind"; },
       "uniform u_model asks for builtin 'wind'"},
      // What the removed --derived-uniforms wrote: refused, saying what to do.
      {"derived uniform",
       [](auto& m) {
         auto& u = firstWith(m["uniforms"], "builtin");
         u["builtin"] = "derived";
         u["derived"] = nlohmann::json::object();
       },
       "uniform u_model is a derived uniform (\"builtin\": \"derived\"), which watergraph no longer has: compile the graph again"},
      {"unknown type", [](auto& m) { firstWith(m["uniforms"], "builtin")["type"] = "vec5"; }, "unknown type 'vec5'"},
      {"no stages", [](auto& m) { firstWith(m["uniforms"], "builtin").erase("stages"); }, "lacks the list \"stages\""},
      {"unknown stage", [](auto& m) { firstWith(m["uniforms"], "builtin")["stages"] = {"geometry"}; },
       "unknown stage \"geometry\""},
      {"time phase without frequency",
       [](auto& m) { firstWith(m["uniforms"], "builtin", "time_phase").erase("angular_frequency"); },
       "lacks the number \"angular_frequency\""},
      {"frequency on another builtin", [](auto& m) { firstWith(m["uniforms"], "builtin")["angular_frequency"] = 1.0; },
       "unknown member \"angular_frequency\""},
      {"default not numeric", [](auto& m) { firstWith(m["uniforms"], "parameter")["default"] = "blue"; },
       "no numeric \"default\""},
      {"texture without origin", [](auto& m) { firstWith(m["textures"], "source").erase("source"); },
       "neither a \"source\" nor a \"resource\""},
      {"node texture without its file", [](auto& m) { firstWith(m["textures"], "source").erase("file"); },
       "lacks the string \"file\""},
      {"texture file in another folder",
       [](auto& m) { firstWith(m["textures"], "source")["file"] = "../secret.png"; },
       "not a file name beside the manifest"},
      {"scene texture with a file", [](auto& m) { firstWith(m["textures"], "resource")["file"] = "x.png"; },
       "has a \"file\" but no \"source\""},
      {"unknown resource", [](auto& m) { firstWith(m["textures"], "resource")["resource"] = "ssao"; },
       "unknown scene resource 'ssao'"},
      {"sampler of another resource", [](auto& m) { firstWith(m["textures"], "resource")["resource"] = "refraction"; },
       "is not a sampler of scene resource 'refraction'"},
      {"patches of four", [](auto& m) { m["tessellation"]["patch_vertices"] = 4; }, "patches of other than 3"},
      {"target member", [](auto& m) { m["targets"]["glsl330"]["geom"] = "x.geom"; }, "not a shader stage"},
      {"a body file without its version", [](auto& m) { m["three"]["vertex"].erase("glsl_version"); },
       "\"three\"'s \"vertex\" lacks the string \"glsl_version\""},
      {"one stage without its body", [](auto& m) { m["three"].erase("fragment"); }, "no \"fragment\" object"},
      {"a body file of a stage es300 lacks", [](auto& m) { m["three"]["tess_control"] = m["three"]["vertex"]; },
       "unknown member \"tess_control\""},
      {"two versions", [](auto& m) { m["three"]["vertex"]["glsl_version"] = "100"; }, "two versions"},
      {"body files without es300", [](auto& m) { m["targets"].erase("es300"); }, "which \"targets\" does not list"},
      {"entry points without from", [](auto& m) { m["targets"]["glsl330"]["entry_points"] = nlohmann::json::object(); },
       "without the other"},
      {"resource list", [](auto& m) { m["resources"].push_back("ssao"); }, "unknown scene resource 'ssao'"},
      {"kept node", [](auto& m) { m["nodes"]["kept"][0].erase("type"); }, "kept node waves lacks the string \"type\""},
      {"scale of an unlisted pass", [](auto& m) { m["pass_scales"]["refraction"] = 0.5; },
       "'refraction' names a pass \"passes\" does not list"},
      {"scale of 1", [](auto& m) { m["pass_scales"]["depth_prepass"] = 1.0; }, "must be a number >= 0.25 and < 1"},
      {"scale below a quarter", [](auto& m) { m["pass_scales"]["depth_prepass"] = 0.1; }, "must be a number >= 0.25"},
      {"scaled water surface", [](auto& m) { m["pass_scales"]["water_surface"] = 0.5; },
       "only a frame-sized scene pass can be scaled"},
      {"scale of an unknown pass", [](auto& m) { m["pass_scales"]["ssao"] = 0.5; }, "names an unknown pass 'ssao'"},
      {"pass scales not an object", [](auto& m) { m["pass_scales"] = 0.5; }, "\"pass_scales\" is not an object"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    nlohmann::json m = stylizedManifest();
    c.edit(m);
    try {
      Manifest::fromJson(m);
      ADD_FAILURE() << "no error";
    } catch (const ManifestError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
}

// The es300 stages' bodies (for a host that writes the version line itself: three.js): the
// manifest names a body file per stage and the version, and each body file is the stage's
// text after that version's line, so the two put together are the stage file byte for byte.
TEST(Manifest, Es300StagesComeWithTheirBodiesAndVersion) {
  for (const char* name : {"lake", "deferred_underwater", "stylized"}) {
    SCOPED_TRACE(name);
    auto graph = loadExample(test::sourcePath(std::string("graphs/") + name + ".json"));
    ASSERT_TRUE(graph);
    CompileOptions options;
    options.validate = false;
    Diagnostics diags;
    auto r = compileGraph(*graph, defaultRegistry(), options, diags);
    ASSERT_TRUE(r);
    auto contents = [&r](const std::string& file) -> const std::string* {
      for (const auto& f : r->files)
        if (f.name == file) return &f.contents;
      return nullptr;
    };
    size_t bodies = 0;
    for (const ManifestTarget& t : r->manifest.targets) {
      if (t.name != "es300") {
        EXPECT_EQ(t.glslVersion, "") << t.name;
        for (const auto& f : t.files) EXPECT_EQ(f.body, "") << f.file;
        continue;
      }
      EXPECT_EQ(t.glslVersion, "300 es");
      ASSERT_EQ(t.files.size(), 2u);
      for (const auto& f : t.files) {
        EXPECT_EQ(f.body, f.file + ".body");
        const std::string* stage = contents(f.file);
        const std::string* body = contents(f.body);
        ASSERT_TRUE(stage && body) << f.file;
        EXPECT_EQ("#version " + t.glslVersion + "\n" + *body, *stage) << f.body;
        ++bodies;
      }
    }
    EXPECT_EQ(bodies, 2u);
    // In the "three" section; the targets' members stay their files, as before.
    const nlohmann::json m = r->manifest.toJson();
    const nlohmann::json three = {
        {"fragment", {{"body_file", std::string(name) + ".es300.frag.body"}, {"glsl_version", "300 es"}}},
        {"vertex", {{"body_file", std::string(name) + ".es300.vert.body"}, {"glsl_version", "300 es"}}}};
    EXPECT_EQ(m["three"], three);
    EXPECT_EQ(m["targets"]["es300"], nlohmann::json({{"frag", std::string(name) + ".es300.frag"},
                                                     {"vert", std::string(name) + ".es300.vert"}}));
    expectRoundTrip(*r);
  }
}

// "filtered" on an ocean is the compiler's decision, from the maps its shaders sample:
// open_ocean's ocean_surface filters (it reads every cascade's moments map); with its filter
// off nothing reads a moments map and the ocean is not filtered.
TEST(Manifest, AnOceanSaysWhetherItIsFiltered) {
  for (const bool filter : {true, false}) {
    SCOPED_TRACE(filter ? "filtered" : "point sampled");
    auto graph = loadExample(test::sourcePath("graphs/open_ocean.json"));
    ASSERT_TRUE(graph);
    bool found = false;
    for (Node& n : graph->nodes)
      if (n.id == "detail") {
        n.options.push_back({"filter", filter, {}, {}});
        found = true;
      }
    ASSERT_TRUE(found) << "open_ocean has no node 'detail'";
    CompileOptions options;
    options.validate = false;
    Diagnostics diags;
    auto r = compileGraph(*graph, defaultRegistry(), options, diags);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->manifest.oceans.size(), 1u);
    size_t moments = 0;
    for (const TextureInfo& t : r->manifest.textures) moments += t.ocean && t.ocean->map == ocean::kMomentsMap ? 1 : 0;
    EXPECT_EQ(moments, filter ? 3u : 0u) << "one moments map per cascade when filtered";
    EXPECT_EQ(r->manifest.oceans[0].filtered, filter);
    EXPECT_EQ(r->manifest.toJson()["oceans"][0]["filtered"], filter);
    expectRoundTrip(*r);

    // A manifest whose "filtered" is missing or disagrees with its moments maps is refused.
    nlohmann::json m = r->manifest.toJson();
    m["oceans"][0]["filtered"] = !filter;
    EXPECT_THROW(Manifest::fromJson(m), ManifestError);
    m["oceans"][0].erase("filtered");
    try {
      Manifest::fromJson(m);
      ADD_FAILURE() << "no error";
    } catch (const ManifestError& e) {
      EXPECT_NE(std::string(e.what()).find("no \"filtered\" true or false"), std::string::npos) << e.what();
    }
  }
}

// Lists other than "passes" may be left out of a hand-written manifest: it has none.
TEST(Manifest, OnlyPassesAreRequired) {
  Manifest m = Manifest::fromJson({{"passes", {"planar_reflection", "water_surface"}}});
  EXPECT_EQ(m.passes, (std::vector<RenderPass>{RenderPass::PlanarReflection, RenderPass::WaterSurface}));
  EXPECT_TRUE(m.uniforms.empty());
  EXPECT_TRUE(m.textures.empty());
  EXPECT_FALSE(m.tessellation);
}

}  // namespace
}  // namespace wg
