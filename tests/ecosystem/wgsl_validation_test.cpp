// The WGSL target checked by the two WGSL compilers of the web: naga (npm naga-wasm, pinned
// in clients/webgpu/package-lock.json) and Tint (Chromium's WebGPU on SwiftShader). Every
// example graph and the whole function library must pass both; a rejection maps back to the
// node that wrote the line; `validate --target wgsl` says which check it could not run.
// Without Node.js (or Chromium, for Tint) the tests are skipped with the reason, never passed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "codegen/compile.h"
#include "codegen/compile_wgsl.h"
#include "codegen/wgsl_translate.h"
#include "core/graph_io.h"
#include "eco_support.h"
#include "nodes/glsl_library.h"
#include "nodes/registry.h"

namespace wg::eco {
namespace {

std::string webgpuClient() { return test::sourcePath("clients/webgpu"); }

class WgslValidation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!haveTool("node")) {
      skip_ = "Node.js (node) is not on PATH: naga and Tint cannot run";
      return;
    }
    CmdResult r = sh(test::shellQuote(test::sourcePath("clients/three/test/npm_ci_cached.sh")) + " " +
                     test::shellQuote(webgpuClient()));
    npmError_ = r.exit == 0 ? "" : "installing clients/webgpu's npm packages failed: " + r.err;
  }
  void SetUp() override {
    if (!skip_.empty()) GTEST_SKIP() << skip_;
    ASSERT_TRUE(npmError_.empty()) << npmError_;
  }
  static bool haveChromium() { return std::filesystem::exists("/usr/bin/chromium"); }

  // Runs a checker script on files; one JSON result per file.
  static std::vector<nlohmann::json> check(const std::string& script, const std::vector<std::string>& files) {
    std::string cmd = "timeout 120 node " + test::shellQuote(webgpuClient() + "/" + script);
    for (const auto& f : files) cmd += " " + test::shellQuote(f);
    CmdResult r = sh(cmd);
    std::vector<nlohmann::json> out;
    for (const auto& line : test::splitLines(r.out)) out.push_back(nlohmann::json::parse(line, nullptr, false));
    EXPECT_EQ(out.size(), files.size()) << r.out << r.err;
    return out;
  }

  // The example graphs that have a WGSL form: all but those holding a glsl_function node,
  // themselves or in a subgraph, whose file is GLSL only (refused with WG045;
  // GlslFunctionNodesAreRefusedAtTheirNode below).
  static std::vector<std::string> wgslExamples() {
    std::vector<std::string> out;
    for (const auto& g : test::exampleGraphs())
      if (!test::holdsGlslFunction(g)) out.push_back(g);
    return out;
  }

  // Every example graph with a WGSL form compiled with --target wgsl into `dir`; the .wgsl paths.
  static std::vector<std::string> compiledExamples(const TempDir& dir) {
    std::string cmd = "compile --target wgsl --subdirs --quiet -o " + test::shellQuote(dir.path());
    for (const auto& g : wgslExamples()) cmd += " " + test::shellQuote(g);
    CmdResult c = wgRun(cmd);
    EXPECT_EQ(c.exit, 0) << c.err;
    std::vector<std::string> files;
    for (const auto& g : wgslExamples()) {
      std::string base = std::filesystem::path(g).stem().string();
      files.push_back(dir / (base + "/" + base + ".wgsl"));
    }
    return files;
  }

  static void expectAllValid(const std::vector<nlohmann::json>& results, const std::string& checker) {
    for (const auto& r : results) {
      ASSERT_TRUE(r.is_object());
      EXPECT_FALSE(r.contains("skipped")) << checker << " did not run: " << r.dump();
      EXPECT_TRUE(r.value("ok", false)) << checker << ": " << r.dump(1);
    }
  }

  static inline std::string skip_, npmError_;
};

TEST_F(WgslValidation, NagaAcceptsEveryExampleGraph) {
  TempDir dir("wg_wgsl_");
  auto files = compiledExamples(dir);
  ASSERT_GE(files.size(), 11u);
  expectAllValid(check("naga_check.mjs", files), "naga");
}

// A function node's own GLSL is not translated: the graph is refused at the node, exit 1.
TEST_F(WgslValidation, GlslFunctionNodesAreRefusedAtTheirNode) {
  TempDir dir("wg_wgsl_");
  CmdResult c = wgRun("compile --target wgsl -o " + test::shellQuote(dir.path()) + " " +
                      test::shellQuote(test::sourcePath("graphs/caustic_pool.json")));
  EXPECT_EQ(c.exit, 1) << c.err;
  EXPECT_NE(c.err.find("error: [WG045]"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("glsl_function"), std::string::npos) << c.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "caustic_pool.wgsl"));
}

TEST_F(WgslValidation, TintAcceptsEveryExampleGraph) {
  if (!haveChromium()) GTEST_SKIP() << "Debian's chromium is not installed (/usr/bin/chromium): Tint cannot run";
  TempDir dir("wg_wgsl_");
  expectAllValid(check("tint_check.mjs", compiledExamples(dir)), "Tint");
}

// Every item of the library in its fragment form and, where it samples with an implicit LOD,
// its level-0 form: one module that both compilers check whole (unused functions included).
TEST_F(WgslValidation, NagaAndTintAcceptTheWholeLibrary) {
  wgsl::Translator t;
  const GlslLibrary& lib = GlslLibrary::builtin();
  for (const GlslItem& item : lib.items())
    for (const GlslItem* needed : lib.itemsNamed({item.name})) t.addItem(*needed, wgsl::StageMode::Fragment);
  TempDir dir("wg_wgsl_");
  const std::string file = dir / "library.wgsl";
  test::writeFile(file, t.functionsText());
  expectAllValid(check("naga_check.mjs", {file}), "naga");
  if (haveChromium()) expectAllValid(check("tint_check.mjs", {file}), "Tint");
}

// A rejected line is reported at the node whose op wrote it: a perturbed module (one of the
// fresnel node's lines given a vec3 where an f32 is declared) goes through naga and back.
TEST_F(WgslValidation, ARejectedLineMapsBackToItsNode) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/lake.json"), diags);
  ASSERT_TRUE(graph);
  CompileOptions o;
  o.targets = {Target::Glsl330};
  o.wgsl = true;
  auto r = compileGraph(*graph, defaultRegistry(), o, diags);
  ASSERT_TRUE(r);
  std::string wgsl;
  for (const auto& f : r->files)
    if (f.name == "lake.wgsl") wgsl = f.contents;
  const std::string good = "var n8_fresnel_t1: f32 = ";
  size_t at = wgsl.find(good);
  ASSERT_NE(at, std::string::npos);
  wgsl.replace(at, good.size(), "var n8_fresnel_t1: f32 = vec3<f32>(1.0) + ");
  TempDir dir("wg_wgsl_");
  test::writeFile(dir / "lake.wgsl", wgsl);
  auto results = check("naga_check.mjs", {dir / "lake.wgsl"});
  ASSERT_EQ(results.size(), 1u);
  ASSERT_FALSE(results[0].value("ok", true));
  const auto& e = results[0]["errors"][0];
  Diagnostics mapped;
  reportWgslMessage(r->program, r->wgslLineOp, e.value("line", 0), e.value("message", ""), DiagCode::WgslRejected, mapped);
  ASSERT_EQ(mapped.all().size(), 1u);
  EXPECT_EQ(mapped.all()[0].node, "fresnel") << e.dump();
}

TEST_F(WgslValidation, ValidateRunsBothChecksAndSaysWhenItCannot) {
  const std::string graph = test::shellQuote(test::sourcePath("graphs/lake.json"));
  CmdResult ran = wgRun("validate --target wgsl " + graph);
  EXPECT_EQ(ran.exit, 0) << ran.err;
  EXPECT_EQ(ran.out.find("not validated by naga"), std::string::npos) << ran.out;
  if (haveChromium()) {
    EXPECT_EQ(ran.out.find("not validated by Tint"), std::string::npos) << ran.out;
  }
  EXPECT_NE(ran.out.find(": ok\n"), std::string::npos) << ran.out;
  // Without Node.js on PATH neither runs: said, and not called ok.
  CmdResult none = sh("PATH=/nonexistent " + test::shellQuote(test::watergraphBinary()) + " validate --target wgsl " + graph);
  EXPECT_EQ(none.exit, 0) << none.err;
  EXPECT_NE(none.out.find("wgsl: not validated by naga: Node.js (node) is not on PATH"), std::string::npos) << none.out;
  EXPECT_NE(none.out.find("wgsl: not validated by Tint: Node.js (node) is not on PATH"), std::string::npos) << none.out;
  EXPECT_EQ(none.out.find(": ok\n"), std::string::npos) << none.out;
}

}  // namespace
}  // namespace wg::eco
