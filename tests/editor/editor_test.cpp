// watergraph-editor run as a user would, without a person: under xvfb-run, with scripted
// edits (--script) and screenshots, checking the saved file and the images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

using test::editorBinary;
using test::EditorRun;

EditorRun runEditor(const std::string& dir, const std::string& args, const std::string& window = "640x360") {
  return test::runEditorProgram(dir, args, window);
}

// A temporary folder holding a copy of graphs/lake.json.
struct Workspace {
  std::string dir = test::makeTempDir("wg_editor");
  std::string graph = dir + "/lake.json";
  Workspace() { test::writeFile(graph, test::readFile(test::sourcePath("graphs/lake.json"))); }
  ~Workspace() { fs::remove_all(dir); }
  std::string path(const std::string& name) const { return dir + "/" + name; }
  std::string script(const std::string& json) const {
    test::writeFile(path("edits.json"), json);
    return "--script " + test::shellQuote(path("edits.json"));
  }
};

double lumaVarianceOf(const rt::Image& img) { return rt::lumaVariance(img, 0, 0, img.width, img.height); }

TEST(Editor, WithoutADisplayItSaysSoAndExits2) {
  if (!fs::exists(editorBinary())) GTEST_SKIP() << "no editor binary";
  std::string out, err;
  int status = test::runCommandSplit("env -u DISPLAY -u WAYLAND_DISPLAY " + test::shellQuote(editorBinary()) + " " +
                                         test::shellQuote(test::sourcePath("graphs/lake.json")),
                                     &out, &err);
  EXPECT_EQ(status, 2);
  auto lines = test::splitLines(err);
  ASSERT_EQ(lines.size(), 1u) << err;
  EXPECT_NE(lines[0].find("cannot open a window"), std::string::npos) << err;
}

// --tonemap and --exposure choose the preview's output transform over the graph's view
// (lake states neutral at 0 EV); a bad one is a usage error naming the flag, exit 2.
TEST(Editor, TheViewFlagsChooseThePreviewsOutputTransform) {
  Workspace ws;
  auto preview = [&](const std::string& flags, const char* name) {
    EditorRun r = runEditor(ws.dir, ws.script(R"([{"op": "save_preview", "path": ")" + ws.path(name) + R"("}])") +
                                        " --time 3.5 " + flags + " " + test::shellQuote(ws.graph));
    EXPECT_EQ(r.status, 0) << flags << ": " << r.err;
    return rt::readPng(ws.path(name));
  };
  rt::Image graphView = preview("", "graph.png");
  rt::Image dark = preview("--tonemap none --exposure -3", "dark.png");
  EXPECT_LT(rt::psnrRgb8(graphView, dark), 25.0) << "the flags reach the preview";
  double sumGraph = 0, sumDark = 0;
  for (size_t i = 0; i < graphView.rgba8.size(); i += 4) sumGraph += graphView.rgba8[i + 1], sumDark += dark.rgba8[i + 1];
  EXPECT_LT(sumDark, 0.7 * sumGraph) << "-3 EV is darker";
  for (const char* bad : {"--tonemap filmic", "--exposure nan", "--exposure 30"}) {
    EditorRun r = runEditor(ws.dir, std::string(bad) + " " + test::shellQuote(ws.graph));
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE((r.out + r.err).find(std::string(bad).substr(0, std::string(bad).find(' ')) + ":"), std::string::npos)
        << bad << ": " << r.out << r.err;
    EXPECT_EQ(test::splitLines(r.out + r.err).size(), 1u) << "one line: " << r.out << r.err;
  }
}

TEST(Editor, ScriptedEditsAreSavedCanonicallyAndReopenUnchanged) {
  Workspace ws;
  EditorRun r = runEditor(ws.dir, ws.script(R"([
    {"op": "set_parameter", "name": "shallow", "value": [0.2, 0.6, 0.1]},
    {"op": "set_input", "node": "fresnel", "port": "f0", "value": 0.04},
    {"op": "set_option", "node": "fresnel", "name": "model", "value": "exact"},
    {"op": "add_node", "type": "saturate", "id": "clamped", "x": 480, "y": 300},
    {"op": "connect", "from": "shore.out", "to": "clamped.x"},
    {"op": "connect", "from": "clamped.out", "to": "depth.a"},
    {"op": "move_node", "id": "uv", "x": -200, "y": 40},
    {"op": "add_node", "type": "add", "id": "spare"},
    {"op": "delete_node", "id": "spare"},
    {"op": "save"}
  ])") + " " + test::shellQuote(ws.graph));
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto g = loadGraphFile(ws.graph, d);
  ASSERT_TRUE(g);
  std::string saved = test::readFile(ws.graph);
  EXPECT_EQ(saveGraph(*g), saved) << "the saved file is in the canonical form";
  EXPECT_EQ(g->findParameter("shallow")->defaultValue, (std::vector<double>{0.2, 0.6, 0.1}));
  ASSERT_TRUE(g->findNode("clamped"));
  EXPECT_EQ(g->findNode("clamped")->editorPosition, (std::array<double, 2>{480, 300}));
  EXPECT_EQ(g->findNode("uv")->editorPosition, (std::array<double, 2>{-200, 40}));
  EXPECT_FALSE(g->findNode("spare"));
  EXPECT_EQ(g->findNode("fresnel")->options.at(0).value, "exact");
  for (const auto& n : g->nodes) EXPECT_TRUE(n.editorPosition) << "every node keeps a canvas position: " << n.id;
  const Node* depth = g->findNode("depth");
  bool linked = false;
  for (const auto& in : depth->inputs) linked |= in.port == "a" && in.source.name == "clamped";
  EXPECT_TRUE(linked);
  EXPECT_EQ(test::listFiles(ws.dir, ".json"), (std::vector<std::string>{"edits.json", "lake.json"}))
      << "no temporary left";
  for (const auto& f : test::listFiles(ws.dir)) EXPECT_EQ(f.find(".tmp"), std::string::npos) << f;

  // Reopened and saved again: byte for byte the same file.
  EditorRun again = runEditor(ws.dir, ws.script(R"([{"op": "save"}])") + " " + test::shellQuote(ws.graph));
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(test::readFile(ws.graph), saved);
}

TEST(Editor, PreviewShowsParameterChangesAndNodeThumbnails) {
  Workspace ws;
  auto p = [&](const char* name) { return ws.path(name); };
  EditorRun r = runEditor(ws.dir, ws.script(R"([
    {"op": "save_preview", "path": ")" + p("before.png") + R"("},
    {"op": "set_parameter", "name": "shallow", "value": [1, 0.2, 0]},
    {"op": "set_parameter", "name": "deep", "value": [0.6, 0, 0.1]},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + p("after.png") + R"("},
    {"op": "select", "node": "tint"},
    {"op": "frames", "count": 1},
    {"op": "save_thumbnail", "path": ")" + p("tint.png") + R"("},
    {"op": "select", "node": "uv"},
    {"op": "frames", "count": 1},
    {"op": "save_thumbnail", "path": ")" + p("uv.png") + R"("}
  ])") + " --stats --screenshot " + test::shellQuote(p("window.png")) + " " + test::shellQuote(ws.graph));
  ASSERT_EQ(r.status, 0) << r.err;
  rt::Image before = rt::readPng(ws.path("before.png")), after = rt::readPng(ws.path("after.png"));
  EXPECT_EQ(before.width, 320);
  EXPECT_EQ(before.height, 180);
  EXPECT_GT(lumaVarianceOf(before), 20.0) << "the preview is not blank";
  EXPECT_LT(rt::psnrRgb8(before, after), 30.0) << "the new colours reach the preview";
  rt::Image window = rt::readPng(ws.path("window.png"));
  EXPECT_EQ(window.width, 640);
  EXPECT_EQ(window.height, 360);
  EXPECT_GT(lumaVarianceOf(window), 20.0);
  rt::Image tint = rt::readPng(ws.path("tint.png")), uv = rt::readPng(ws.path("uv.png"));
  EXPECT_GT(lumaVarianceOf(tint), 5.0);
  EXPECT_GT(lumaVarianceOf(uv), 5.0);
  EXPECT_LT(rt::psnrRgb8(tint, uv), 30.0);
  // Parameter edits are uniforms: no recompile, and the latency is reported.
  EXPECT_NE(r.out.find("edit-to-pixels:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("uniform, no recompile"), std::string::npos) << r.out;
}

TEST(Editor, HotReloadKeepsTheLastGoodPreviewWhileTheFileIsBroken) {
  Workspace ws;
  std::string good = test::readFile(ws.graph);
  std::string bad = good;
  size_t at = bad.find("\"x\": \"radius.out\"");
  ASSERT_NE(at, std::string::npos);
  bad.replace(at, 17, "\"x\": \"ghost.out\"");
  // Where the loader will point: the value "ghost.out", 1-based line and column.
  size_t valueAt = bad.find("\"ghost.out\"");
  int line = 1 + static_cast<int>(std::count(bad.begin(), bad.begin() + static_cast<ptrdiff_t>(valueAt), '\n'));
  int col = static_cast<int>(valueAt - bad.rfind('\n', valueAt));
  std::string fixed = good;
  size_t deep = fixed.find("[0, 0.1, 0.3]");
  ASSERT_NE(deep, std::string::npos);
  fixed.replace(deep, 13, "[0.7, 0.1, 0]");
  test::writeFile(ws.path("bad.json"), bad);
  test::writeFile(ws.path("fixed.json"), fixed);

  EditorRun r = runEditor(ws.dir, ws.script(R"([
    {"op": "save_preview", "path": ")" + ws.path("good.png") + R"("},
    {"op": "external_write", "from": ")" + ws.path("bad.json") + R"("},
    {"op": "wait_reload"},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + ws.path("while_bad.png") + R"("},
    {"op": "external_write", "from": ")" + ws.path("fixed.json") + R"("},
    {"op": "wait_reload"},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + ws.path("fixed.png") + R"("}
  ])") + " " + test::shellQuote(ws.graph));
  EXPECT_EQ(r.status, 0) << "the graph compiles again at the end\n" << r.err;
  std::string expected = ws.graph + ":" + std::to_string(line) + ":" + std::to_string(col) + ": error: [WG024]";
  EXPECT_NE(r.err.find(expected), std::string::npos) << "want " << expected << " in\n" << r.err;
  EXPECT_NE(r.err.find("node 'shore'"), std::string::npos) << r.err;
  rt::Image goodImg = rt::readPng(ws.path("good.png")), badImg = rt::readPng(ws.path("while_bad.png"));
  EXPECT_TRUE(std::isinf(rt::psnrRgb8(goodImg, badImg))) << "the last good preview stays on screen";
  EXPECT_LT(rt::psnrRgb8(goodImg, rt::readPng(ws.path("fixed.png"))), 35.0) << "the fixed file reloads";
  EXPECT_EQ(test::readFile(ws.graph), fixed) << "the editor never writes the file by itself";
}

TEST(Editor, APresetFromTheInspectorBecomesTheSavedDefaults) {
  Workspace ws;
  std::string graph = ws.path("topdown.json");
  test::writeFile(graph, test::readFile(test::sourcePath("graphs/topdown.json")));
  EditorRun r = runEditor(ws.dir, ws.script(R"([{"op": "apply_preset", "name": "choppy"}, {"op": "save"}])") + " " +
                                      test::shellQuote(graph));
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto g = loadGraphFile(graph, d);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->findParameter("wave_height")->defaultValue, std::vector<double>{1});
  EXPECT_EQ(g->findParameter("foam_threshold")->defaultValue, std::vector<double>{0.66});
  EXPECT_EQ(g->presets.size(), 5u) << "the presets stay in the file";
}

TEST(Editor, ARefusedScriptEditFailsWithItsReason) {
  Workspace ws;
  std::string original = test::readFile(ws.graph);
  EditorRun r = runEditor(ws.dir, ws.script(R"([{"op": "connect", "from": "color.out", "to": "from_centre.a"}, {"op": "save"}])") +
                    " " + test::shellQuote(ws.graph));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("step 1 (connect)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cycle"), std::string::npos) << r.err;
  EXPECT_EQ(test::readFile(ws.graph), original) << "the script stops at the failed step";
}

// Pixels of the fault colour (ImGui text in (1, 0.45, 0.4), anti-aliased) in the
// inspector's column above the errors panel (the right 38 % of the window, top 65 %).
size_t faultColouredPixels(const rt::Image& img) {
  size_t n = 0;
  for (int y = 0; y < img.height * 65 / 100; ++y)
    for (int x = img.width * 62 / 100; x < img.width; ++x) {
      size_t i = (static_cast<size_t>(y) * static_cast<size_t>(img.width) + static_cast<size_t>(x)) * 4;
      int r = img.rgba8[i], g = img.rgba8[i + 1], b = img.rgba8[i + 2];
      n += r > 200 && g > 90 && g < 140 && b > 80 && b < 125;
    }
  return n;
}

TEST(Editor, AnExpressionIsDeclaredWiredAndEditedWithItsFaultShownInline) {
  Workspace ws;
  auto p = [&](const char* name) { return ws.path(name); };
  EditorRun r = runEditor(ws.dir, ws.script(R"JSON([
    {"op": "add_node", "type": "expression", "id": "formula", "x": 700, "y": 120},
    {"op": "set_option", "node": "formula", "name": "inputs", "value": {"c": "vec3", "k": "float"}},
    {"op": "connect", "from": "shore.out", "to": "formula.k"},
    {"op": "set_input", "node": "formula", "port": "c", "value": [0.1, 0.5, 0.6]},
    {"op": "connect", "from": "formula.out", "to_output": "fragment.color"},
    {"op": "select", "node": "formula"},
    {"op": "set_option", "node": "formula", "name": "formula", "value": "mixx(c, vec3(1.0), k)"},
    {"op": "frames", "count": 2},
    {"op": "screenshot", "path": ")JSON" + p("fault.png") + R"JSON("},
    {"op": "set_option", "node": "formula", "name": "formula", "value": "mix(c, vec3(1.0), clamp(k, 0.0, 1.0))"},
    {"op": "frames", "count": 2},
    {"op": "screenshot", "path": ")JSON" + p("fixed.png") + R"JSON("},
    {"op": "save"}
  ])JSON") + " " + test::shellQuote(ws.graph), "1200x1000");  // tall enough to show the selected node's options
  ASSERT_EQ(r.status, 0) << r.err;
  // The faulty formula's message and caret are drawn in the inspector; the fixed one's are not.
  size_t withFault = faultColouredPixels(rt::readPng(p("fault.png")));
  size_t fixed = faultColouredPixels(rt::readPng(p("fixed.png")));
  EXPECT_GT(withFault, 30u);
  EXPECT_LT(fixed, withFault / 4) << "fault " << withFault << ", fixed " << fixed;
  Diagnostics d;
  auto g = loadGraphFile(ws.graph, d);
  ASSERT_TRUE(g);
  const Node* formula = g->findNode("formula");
  ASSERT_TRUE(formula);
  EXPECT_EQ(writtenOptions(*formula)["formula"], "mix(c, vec3(1.0), clamp(k, 0.0, 1.0))");
  auto compiled = compileGraph(*g, defaultRegistry(), CompileOptions{}, d);
  EXPECT_TRUE(compiled) << (d.all().empty() ? "" : formatText(d.all().front()));
}

TEST(Editor, AnInputTheExpressionDoesNotDeclareIsRefused) {
  Workspace ws;
  EditorRun r = runEditor(ws.dir, ws.script(R"([
    {"op": "add_node", "type": "expression", "id": "formula"},
    {"op": "connect", "from": "shore.out", "to": "formula.k"}
  ])") + " " + test::shellQuote(ws.graph));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("has no input 'k'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace wg
