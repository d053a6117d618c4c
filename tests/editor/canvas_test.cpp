// The node canvas as an authoring surface (docs/editor.md, "Nodes"): zoom about the cursor,
// framing, box selection, the minimap, and panels whose sizes are dragged and remembered.
// The view's arithmetic is tested directly; the rest through the editor's scripted pointer
// and keys under Xvfb, measuring where widgets were drawn ("print_widgets").
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/graph_io.h"
#include "editor/canvas_view.h"
#include "editor/panel_layout.h"
#include "editor_run.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;
using Rect = std::array<double, 4>;

TEST(CanvasView, ZoomKeepsThePointUnderTheCursorAndStaysInRange) {
  CanvasView v;
  std::array<float, 2> cursor{300, 120};
  auto before = v.toCanvas(cursor[0], cursor[1]);
  v.zoomAbout(cursor, 1.5f);
  EXPECT_FLOAT_EQ(v.zoom(), 1.5f);
  auto after = v.toCanvas(cursor[0], cursor[1]);
  EXPECT_NEAR(after[0], before[0], 1e-3);
  EXPECT_NEAR(after[1], before[1], 1e-3);
  for (int i = 0; i < 20; ++i) v.zoomAbout(cursor, 2);
  EXPECT_EQ(v.zoom(), CanvasView::kMaxZoom);
  for (int i = 0; i < 40; ++i) v.zoomAbout(cursor, 0.5f);
  EXPECT_EQ(v.zoom(), CanvasView::kMinZoom);
  auto still = v.toCanvas(cursor[0], cursor[1]);
  EXPECT_NEAR(still[0], before[0], 1e-2) << "clamped zooms keep the point too";
}

TEST(CanvasView, FramingCentresTheBoxAndFitsIt) {
  CanvasView v;
  v.frame({-500, 0, 1500, 400}, {1000, 500});
  auto a = v.toPanel(-500, 0), b = v.toPanel(1500, 400);
  EXPECT_GE(a[0], 0);
  EXPECT_LE(b[0], 1000);
  EXPECT_NEAR((a[0] + b[0]) / 2, 500, 0.5);
  EXPECT_NEAR((a[1] + b[1]) / 2, 250, 0.5);
  v.frame({0, 0, 10, 10}, {1000, 500});
  EXPECT_EQ(v.zoom(), CanvasView::kMaxZoom) << "a small box is not blown up past 200 %";
}

TEST(PanelLayout, RemembersThreeFractionsAndRefusesNonsense) {
  std::string dir = test::makeTempDir("wg_panels");
  PanelLayout p;
  p.leftWidth = 0.5f, p.previewHeight = 0.3f, p.inspectorHeight = 0.7f;
  EditorSettings settings;
  settings.panels = p;
  for (int i = 0; i < 10; ++i) settings.opened(dir + "/g" + std::to_string(i) + ".json");
  settings.opened(dir + "/g5.json");
  ASSERT_EQ(saveEditorSettings(dir + "/sub/editor.json", settings), "");
  auto back = loadPanelLayout(dir + "/sub/editor.json");
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, p);
  EditorSettings again = loadEditorSettings(dir + "/sub/editor.json");
  ASSERT_EQ(again.recent.size(), EditorSettings::kRecentFiles);
  EXPECT_EQ(again.recent[0], dir + "/g5.json") << "opened again: to the front, once";
  EXPECT_EQ(again.recent[1], dir + "/g9.json");
  test::writeFile(dir + "/bad.json", R"({"panels": {"left_width": 7}})");
  EXPECT_FLOAT_EQ(loadPanelLayout(dir + "/bad.json")->leftWidth, 0.85f) << "clamped to where panels stay usable";
  test::writeFile(dir + "/junk.json", "not json");
  EXPECT_FALSE(loadPanelLayout(dir + "/junk.json"));
  EXPECT_FALSE(loadPanelLayout(dir + "/missing.json"));
  fs::remove_all(dir);
}

// A copy of lake.json, scripts run on it at 1600x900, and the widget boxes they printed.
struct CanvasRun {
  std::string dir = test::makeTempDir("wg_canvas");
  std::string graph = dir + "/lake.json";
  CanvasRun() { test::writeFile(graph, test::readFile(test::sourcePath("graphs/lake.json"))); }
  ~CanvasRun() { fs::remove_all(dir); }
  test::EditorRun run(const std::string& steps, const std::string& flags = "") const {
    test::writeFile(dir + "/edits.json", steps);
    return test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + flags + " " + test::shellQuote(graph),
                                  "1600x900");
  }
};

// Each "print_widgets" step's lines, in order: one map per step that printed.
std::vector<std::map<std::string, Rect>> widgetReports(const std::string& out) {
  std::vector<std::map<std::string, Rect>> reports;
  std::map<std::string, Rect> current;
  std::string last;
  for (const std::string& line : test::splitLines(out)) {
    if (line.rfind("widget ", 0) != 0) continue;
    size_t colon = line.find(": ");
    std::string name = line.substr(7, colon - 7);
    if (!current.empty() && name <= last) reports.push_back(std::move(current)), current = {};
    std::istringstream in(line.substr(colon + 2));
    Rect r{};
    in >> r[0] >> r[1] >> r[2] >> r[3];
    current[name] = r, last = name;
  }
  if (!current.empty()) reports.push_back(std::move(current));
  return reports;
}

TEST(Canvas, ZoomIsAboutTheCursorWithTheWheelAndTheKeys) {
  CanvasRun c;
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "node radius", "at": [0.3, 0.5]},
    {"op": "print_widgets", "prefix": "node radius"},
    {"op": "wheel", "widget": "node radius", "at": [0.3, 0.5], "delta": 2},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node radius"},
    {"op": "key", "key": "-"},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node radius"},
    {"op": "wheel", "widget": "canvas", "delta": -40},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node radius"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  auto reports = widgetReports(r.out);
  ASSERT_EQ(reports.size(), 4u) << r.out;
  Rect a = reports[0].at("node radius"), b = reports[1].at("node radius"), k = reports[2].at("node radius");
  double cursorX = a[0] + 0.3 * (a[2] - a[0]), cursorY = (a[1] + a[3]) / 2;
  double wheel = 1.15 * 1.15;
  EXPECT_NEAR(b[2] - b[0], (a[2] - a[0]) * wheel, 0.5) << "two notches zoom by 1.15^2";
  EXPECT_NEAR(b[0] - cursorX, (a[0] - cursorX) * wheel, 0.5) << "about the cursor";
  EXPECT_NEAR(b[1] - cursorY, (a[1] - cursorY) * wheel, 0.5);
  EXPECT_NEAR(k[2] - k[0], (b[2] - b[0]) * 0.8, 0.5) << "- zooms out by 0.8, about the cursor too";
  EXPECT_NEAR(k[0] - cursorX, (b[0] - cursorX) * 0.8, 0.5);
  Rect far = reports[3].at("node radius");
  EXPECT_NEAR(far[2] - far[0], 180 * 0.25, 0.5) << "no further out than 25 %";
}

TEST(Canvas, HomeFramesEverythingAndFFramesTheSelection) {
  CanvasRun c;
  test::EditorRun r = c.run(R"([
    {"op": "move_node", "id": "fresnel", "x": 1500, "y": 600},
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "canvas"},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": ""},
    {"op": "select", "node": "tint"},
    {"op": "hover", "widget": "canvas", "at": [0.1, 0.1]},
    {"op": "key", "key": "f"},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": ""}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  auto reports = widgetReports(r.out);
  ASSERT_EQ(reports.size(), 2u) << r.out;
  Rect canvas = reports[0].at("canvas");
  int nodes = 0;
  for (const auto& [name, box] : reports[0]) {
    if (name.rfind("node ", 0) != 0) continue;
    ++nodes;
    EXPECT_GE(box[0], canvas[0]) << name;
    EXPECT_LE(box[2], canvas[2]) << name;
    EXPECT_GE(box[1], canvas[1]) << name;
    EXPECT_LE(box[3], canvas[3]) << name;
  }
  EXPECT_EQ(nodes, 8);
  Rect tint = reports[1].at("node tint");
  EXPECT_NEAR((tint[0] + tint[2]) / 2, (canvas[0] + canvas[2]) / 2, 1.0) << "the selection, centred";
  EXPECT_NEAR((tint[1] + tint[3]) / 2, (canvas[1] + canvas[3]) / 2, 1.0);
  EXPECT_NEAR(tint[2] - tint[0], 180 * 2, 0.5) << "at 200 %, the most";
}

TEST(Canvas, ABoxSelectsNodesThatDeleteAndUndoTogether) {
  CanvasRun c;
  // Framed first; then a box from above-left of uv to below-right of radius, and Delete.
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "canvas"},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node"},
    {"op": "drag", "widget": "canvas", "from": [0.005, 0.2], "to": [0.33, 0.62]},
    {"op": "key", "key": "delete"},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.dir + R"(/deleted.json"},
    {"op": "key", "key": "z", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.dir + R"(/undone.json"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto deleted = loadGraphFile(c.dir + "/deleted.json", d);
  auto undone = loadGraphFile(c.dir + "/undone.json", d);
  ASSERT_TRUE(deleted && undone);
  for (const char* gone : {"uv", "from_centre", "radius"}) EXPECT_FALSE(deleted->findNode(gone)) << gone << "\n" << r.out;
  for (const char* kept : {"shore", "depth", "tint", "color"}) EXPECT_TRUE(deleted->findNode(kept)) << kept;
  EXPECT_EQ(undone->nodes.size(), 8u) << "one Ctrl+Z brings back every node the box deleted";
}

// A thumbnail let go (its node deselected) deletes its program, which was current when
// ImGui drew: the backend restored it afterwards, a GL error the next preview frame
// reported as WG043 (seen after a box selection, Delete and Ctrl+Z).
TEST(Canvas, ALetGoThumbnailLeavesNoGlErrorBehind) {
  CanvasRun c;
  test::EditorRun r = c.run(R"([
    {"op": "select", "node": "radius"}, {"op": "frames", "count": 2}, {"op": "select", "node": ""},
    {"op": "delete_node", "id": "radius"}, {"op": "frames", "count": 1},
    {"op": "undo"}, {"op": "frames", "count": 3}
  ])");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("WG043"), std::string::npos) << r.err;
}

TEST(Canvas, TheMinimapMovesTheView) {
  CanvasRun c;
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node uv"},
    {"op": "click", "widget": "minimap", "at": [0.9, 0.5]},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node uv"},
    {"op": "click", "widget": "minimap", "at": [0.1, 0.5]},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node uv"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  auto reports = widgetReports(r.out);
  ASSERT_EQ(reports.size(), 3u) << r.out;
  double x0 = reports[0].at("node uv")[0], right = reports[1].at("node uv")[0], left = reports[2].at("node uv")[0];
  EXPECT_LT(right, x0 - 100) << "the view went right: the nodes moved left";
  EXPECT_GT(left, right + 100);
}

TEST(Canvas, TheDefaultCanvasIsLargeAndDraggedPanelSizesAreRemembered) {
  CanvasRun c;
  std::string settings = c.dir + "/settings/editor.json";
  std::string printCanvas = R"([{"op": "frames", "count": 1}, {"op": "print_widgets", "prefix": "canvas"}])";
  test::EditorRun fresh = c.run(printCanvas);
  ASSERT_EQ(fresh.status, 0) << fresh.err;
  Rect first = widgetReports(fresh.out).at(0).at("canvas");
  EXPECT_GE(first[2] - first[0], 1000) << "at 1600x900";
  EXPECT_GE(first[3] - first[1], 430);
  EXPECT_FALSE(fs::exists(settings));

  test::EditorRun dragged = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "drag", "widget": "splitter preview", "from": [0.5, 0.5], "to": [0.5, -20]},
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "canvas"}
  ])", "--settings " + test::shellQuote(settings));
  ASSERT_EQ(dragged.status, 0) << dragged.err;
  Rect moved = widgetReports(dragged.out).at(0).at("canvas");
  EXPECT_LT(moved[1], first[1] - 100) << "the splitter moved the canvas's top up";
  ASSERT_TRUE(fs::exists(settings));

  test::EditorRun again = c.run(printCanvas, "--settings " + test::shellQuote(settings));
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NEAR(widgetReports(again.out).at(0).at("canvas")[1], moved[1], 1.0) << "remembered";
  test::EditorRun batch = c.run(printCanvas);
  EXPECT_NEAR(widgetReports(batch.out).at(0).at("canvas")[1], first[1], 0.5) << "a batch run reads no settings of its own";
}

}  // namespace
}  // namespace wg::editor
