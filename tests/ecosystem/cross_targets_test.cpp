// --target msl / hlsl: SPIRV-Cross translates the vk450 SPIR-V of every example graph.
// What is checked (docs/ecosystem.md): the translation succeeds, files are named
// <graph>.{msl,hlsl}.{vert,frag}, non-empty, deterministic and listed in the manifest with
// their entry points; HLSL compiles again with glslang's HLSL front end (in watergraph and
// here with glslangValidator), and that SPIR-V passes spirv-val and goes back through
// spirv-cross to GLSL that glslang accepts (a round trip). MSL cannot be compiled on Linux.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "codegen/compile.h"
#include "eco_support.h"

namespace wg {
namespace {

using test::shellQuote;

// The example graphs, and a graph with vertex waves, a texture and time phases.
std::vector<std::string> crossGraphs() {
  auto graphs = test::exampleGraphs();
  graphs.push_back(test::sourcePath("tests/ecosystem/data/textured_waves.json"));
  return graphs;
}

std::string compileTo(const std::string& graph, const std::string& dir, const std::string& targets) {
  auto r = eco::wgRun("compile " + shellQuote(graph) + " -o " + shellQuote(dir) + " --target " + targets);
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  return r.err;
}

TEST(CrossTargets, EveryExampleGraphBecomesMslAndHlsl) {
  for (const auto& graph : crossGraphs()) {
    eco::TempDir tmp;
    compileTo(graph, tmp / "out", "msl,hlsl");
    std::string base = graphBaseName(graph);
    auto manifest = nlohmann::json::parse(test::readFile(tmp / "out/" + base + ".manifest.json"));
    // A tessellated graph keeps its tessellation stages in MSL; SPIRV-Cross writes no HLSL
    // hull or domain shaders, so HLSL gets the graph without tessellation.
    const bool tessellated = manifest.contains("tessellation");
    std::vector<std::string> expected{base + ".hlsl.frag", base + ".hlsl.vert", base + ".manifest.json",
                                      base + ".msl.frag", base + ".msl.vert"};
    if (tessellated) {
      expected.insert(expected.begin() + 4, {base + ".msl.tesc", base + ".msl.tese"});
      EXPECT_EQ(manifest["tessellation"]["targets"], nlohmann::json({"msl"})) << base;
      EXPECT_NE(manifest["targets"]["hlsl"]["from"].get<std::string>().find("without tessellation"),
                std::string::npos);
    }
    EXPECT_EQ(test::listFiles(tmp / "out"), expected);
    for (const char* ext : {".msl.vert", ".msl.frag"}) {
      std::string msl = test::readFile(tmp / "out/" + base + ext);
      EXPECT_NE(msl.find("#include <metal_stdlib>"), std::string::npos) << base << ext;
      EXPECT_NE(msl.find(std::string(ext) == ".msl.vert" ? "vertex main0_out main0(" : "fragment main0_out main0("),
                std::string::npos)
          << msl;
    }
    for (const char* ext : {".hlsl.vert", ".hlsl.frag"}) {
      std::string hlsl = test::readFile(tmp / "out/" + base + ext);
      EXPECT_NE(hlsl.find("SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)"), std::string::npos) << hlsl;
      EXPECT_NE(hlsl.find("cbuffer WgUniforms : register(b0)"), std::string::npos) << hlsl;
    }
    const auto& targets = manifest["targets"];
    EXPECT_FALSE(targets.contains("vk450"));  // only the input, not asked for
    EXPECT_EQ(targets["msl"]["vert"], base + ".msl.vert");
    EXPECT_EQ(targets["msl"]["entry_points"]["frag"], "main0");
    EXPECT_EQ(targets["hlsl"]["frag"], base + ".hlsl.frag");
    EXPECT_EQ(targets["hlsl"]["entry_points"]["vert"], "main");
  }
}

TEST(CrossTargets, OutputIsDeterministic) {
  for (const auto& graph : crossGraphs()) {
    eco::TempDir a, b;
    compileTo(graph, a / "out", "msl,hlsl,vk450");
    compileTo(graph, b / "out", "hlsl,vk450,msl");
    auto files = test::listFiles(a / "out");
    ASSERT_EQ(files, test::listFiles(b / "out"));
    for (const auto& f : files)
      EXPECT_TRUE(test::readFile(a / ("out/" + f)) == test::readFile(b / ("out/" + f))) << f << " differs between runs";
  }
}

TEST(CrossTargets, WithVk450TheSpirvFilesStay) {
  eco::TempDir tmp;
  compileTo(test::sourcePath("graphs/lake.json"), tmp / "out", "vk450,msl");
  auto files = test::listFiles(tmp / "out");
  for (const char* f : {"lake.vk450.vert.spv", "lake.vk450.frag.spv", "lake.msl.vert", "lake.msl.frag"})
    EXPECT_NE(std::find(files.begin(), files.end(), f), files.end()) << f;
  auto manifest = nlohmann::json::parse(test::readFile(tmp / "out/lake.manifest.json"));
  EXPECT_TRUE(manifest["targets"].contains("vk450"));
  EXPECT_TRUE(manifest["targets"].contains("msl"));
}

TEST(CrossTargets, UnknownTargetIsAUsageError) {
  eco::TempDir tmp;
  auto r = eco::wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(tmp / "o") +
                      " --target glsl460");  // no such target (wgsl is one since issue 45)
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("msl, hlsl"), std::string::npos) << r.err;
}

// HLSL -> SPIR-V (glslangValidator's HLSL front end) -> spirv-val -> GLSL (spirv-cross)
// -> glslangValidator again.
TEST(CrossTargets, HlslRoundTripsThroughGlslangAndSpirvCross) {
  for (const char* tool : {"glslangValidator", "spirv-val", "spirv-cross"})
    if (!eco::haveTool(tool)) GTEST_FAIL() << tool << " is missing: scripts/setup.sh installs it";
  for (const auto& graph : crossGraphs()) {
    eco::TempDir tmp;
    compileTo(graph, tmp / "out", "hlsl");
    std::string base = graphBaseName(graph);
    for (const char* stage : {"vert", "frag"}) {
      std::string hlsl = tmp / ("out/" + base + ".hlsl." + stage);
      std::string spv = tmp / (std::string(stage) + ".spv");
      std::string glsl = tmp / (std::string("back.") + stage);
      auto r = eco::sh("glslangValidator -D -V -e main -S " + std::string(stage) + " " + shellQuote(hlsl) + " -o " +
                       shellQuote(spv));
      ASSERT_EQ(r.exit, 0) << hlsl << "\n" << r.out << r.err;
      r = eco::sh("spirv-val --target-env vulkan1.0 " + shellQuote(spv));
      EXPECT_EQ(r.exit, 0) << r.out << r.err;
      r = eco::sh("spirv-cross --version 450 " + shellQuote(spv) + " --output " + shellQuote(glsl));
      ASSERT_EQ(r.exit, 0) << r.out << r.err;
      // spirv-cross writes OpenGL GLSL (a combined sampler without a binding): check it as such.
      r = eco::sh("glslangValidator -S " + std::string(stage) + " " + shellQuote(glsl));
      EXPECT_EQ(r.exit, 0) << test::readFile(glsl) << r.out << r.err;
    }
  }
}

// MSL has no compiler here: at least SPIRV-Cross's MSL output keeps every uniform of the
// vk450 block, by name, so a Metal runtime can bind what the manifest lists.
TEST(CrossTargets, ResourceSlotsFollowTheVk450Bindings) {
  eco::TempDir tmp;
  compileTo(test::sourcePath("tests/ecosystem/data/textured_waves.json"), tmp / "out", "msl,hlsl");
  std::string hlsl = test::readFile(tmp / "out/textured_waves.hlsl.frag");
  // The one texture is vk450 binding 1 (binding 0 is the uniform block).
  EXPECT_NE(hlsl.find("Texture2D<float4> "), std::string::npos) << hlsl;
  EXPECT_NE(hlsl.find(" : register(t1);"), std::string::npos) << hlsl;
  EXPECT_NE(hlsl.find(" : register(s1);"), std::string::npos) << hlsl;
  std::string msl = test::readFile(tmp / "out/textured_waves.msl.frag");
  EXPECT_NE(msl.find("[[buffer(0)]]"), std::string::npos) << msl;
  EXPECT_NE(msl.find("[[texture(0)]]"), std::string::npos) << msl;
  EXPECT_NE(msl.find("[[sampler(0)]]"), std::string::npos) << msl;
}

TEST(CrossTargets, MslKeepsTheManifestUniforms) {
  eco::TempDir tmp;
  compileTo(test::sourcePath("graphs/lake.json"), tmp / "out", "msl");
  auto manifest = nlohmann::json::parse(test::readFile(tmp / "out/lake.manifest.json"));
  std::string msl = test::readFile(tmp / "out/lake.msl.vert") + test::readFile(tmp / "out/lake.msl.frag");
  ASSERT_FALSE(manifest["uniforms"].empty());
  for (const auto& u : manifest["uniforms"]) {
    std::string name = u["name"];
    EXPECT_NE(msl.find(name), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace wg
