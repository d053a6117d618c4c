// The editor's script runner without a window: a stand-in host records what the steps
// asked for, so the order of steps, the waiting and the messages are checked directly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/graph_io.h"
#include "editor/script_runner.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::editor {
namespace {

class FakeHost : public ScriptHost {
 public:
  explicit FakeHost(std::string path) : path_(std::move(path)) {
    Diagnostics d;
    auto g = loadGraphFile(test::sourcePath("graphs/lake.json"), d);
    EXPECT_TRUE(g);
    editor_ = GraphEditor(g ? *g : Graph{}, &defaultRegistry());
  }
  bool loaded = true;
  int edits = 0;
  int disk = 0;
  std::vector<std::string> calls;  // "save path", "select node 2", ...
  std::string refuse;              // what every host step answers ("" accepts)

  bool graphLoaded() const override { return loaded; }
  GraphEditor& graphEditor() override { return editor_; }
  void edited() override { ++edits; }
  const std::string& graphPath() const override { return path_; }
  int diskEvents() const override { return disk; }
  std::string save(const std::string& path) override { return call("save " + path); }
  std::string screenshot(const std::string& path) override { return call("screenshot " + path); }
  std::string savePreview(const std::string& path) override { return call("save_preview " + path); }
  std::string saveThumbnail(const std::string& path) override { return call("save_thumbnail " + path); }
  std::string select(const std::string& node, int port) override {
    return call("select " + node + " " + std::to_string(port));
  }
  std::string camera(const std::string& preset) override { return call("camera " + preset); }
  void setTime(float seconds) override { calls.push_back("time " + std::to_string(seconds)); }
  std::string openSubgraph(const std::string& node) override { return call("open_subgraph " + node); }
  std::string back(bool discard) override { return call(discard ? "back discard" : "back"); }

 private:
  std::string call(std::string what) {
    calls.push_back(std::move(what));
    return refuse;
  }
  std::string path_;
  GraphEditor editor_{Graph{}};
};

std::vector<ScriptStep> steps(const nlohmann::json& list) {
  std::vector<ScriptStep> out;
  int index = 0;
  for (const auto& s : list) out.push_back({s["op"].get<std::string>(), s, ++index});
  return out;
}

TEST(ScriptRunner, EditsGoThroughTheGraphEditorAndStartTheClockOnlyWhenTheGraphChanged) {
  FakeHost host("g.json");
  ScriptRunner run(steps(nlohmann::json::parse(R"([
    {"op": "set_parameter", "name": "max_depth", "value": 7},
    {"op": "set_parameter", "name": "max_depth", "value": 7},
    {"op": "undo"}])")),
                   "s.json");
  ASSERT_TRUE(run.step(host));
  EXPECT_EQ(host.graphEditor().graph().findParameter("max_depth")->defaultValue, std::vector<double>{7});
  EXPECT_EQ(host.edits, 1);
  ASSERT_TRUE(run.step(host));  // the same value again: no change, no clock
  EXPECT_EQ(host.edits, 1);
  ASSERT_TRUE(run.step(host));
  EXPECT_EQ(host.edits, 2);
  EXPECT_NE(host.graphEditor().graph().findParameter("max_depth")->defaultValue, std::vector<double>{7});
  EXPECT_TRUE(run.done());
}

TEST(ScriptRunner, ARefusedEditNamesTheScriptStepAndOp) {
  FakeHost host("g.json");
  ScriptRunner run(steps(nlohmann::json::parse(R"([{"op": "frames", "count": 0},
    {"op": "delete_node", "id": "no_such_node"}])")),
                   "s.json");
  ASSERT_TRUE(run.step(host));
  EXPECT_FALSE(run.step(host));
  EXPECT_EQ(run.error().rfind("s.json: step 2 (delete_node): ", 0), 0u) << run.error();
  EXPECT_NE(run.error().find("no_such_node"), std::string::npos) << run.error();

  FakeHost notLoaded("g.json");
  notLoaded.loaded = false;
  ScriptRunner early(steps(nlohmann::json::parse(R"([{"op": "undo"}])")), "s.json");
  EXPECT_FALSE(early.step(notLoaded));
  EXPECT_EQ(early.error(), "s.json: step 1 (undo): the graph has not loaded");
}

TEST(ScriptRunner, FramesWaitBeforeTheNextStep) {
  FakeHost host("g.json");
  ScriptRunner run(steps(nlohmann::json::parse(R"([{"op": "frames", "count": 2}, {"op": "camera", "preset": "above"}])")),
                   "s.json");
  ASSERT_TRUE(run.step(host));  // sets the wait
  ASSERT_TRUE(run.step(host));
  ASSERT_TRUE(run.step(host));
  EXPECT_FALSE(run.done());
  EXPECT_TRUE(host.calls.empty());
  ASSERT_TRUE(run.step(host));
  EXPECT_EQ(host.calls, std::vector<std::string>{"camera above"});
  EXPECT_TRUE(run.done());
}

TEST(ScriptRunner, HostStepsGetTheirArgumentsAndTheirRefusalsFailTheScript) {
  FakeHost host("g.json");
  ScriptRunner run(steps(nlohmann::json::parse(R"([{"op": "save"}, {"op": "save", "path": "b.json"},
    {"op": "select", "node": "shore", "port": 1}, {"op": "time", "value": 2.5},
    {"op": "save_preview", "path": "p.png"}, {"op": "save_thumbnail", "path": "t.png"},
    {"op": "screenshot", "path": "w.png"}])")),
                   "s.json");
  while (!run.done()) ASSERT_TRUE(run.step(host)) << run.error();
  EXPECT_EQ(host.calls, (std::vector<std::string>{"save g.json", "save b.json", "select shore 1", "time 2.500000",
                                                 "save_preview p.png", "save_thumbnail t.png", "screenshot w.png"}));

  ScriptRunner noPath(steps(nlohmann::json::parse(R"([{"op": "screenshot"}])")), "s.json");
  EXPECT_FALSE(noPath.step(host));
  EXPECT_EQ(noPath.error(), "s.json: step 1 (screenshot): needs a string \"path\"");

  host.refuse = "no camera preset 'sideways'";
  ScriptRunner refused(steps(nlohmann::json::parse(R"([{"op": "camera", "preset": "sideways"}])")), "s.json");
  EXPECT_FALSE(refused.step(host));
  EXPECT_EQ(refused.error(), "s.json: step 1 (camera): no camera preset 'sideways'");
}

TEST(ScriptRunner, SubgraphStepsGoToTheHostAndAnotherFileCanBeWritten) {
  std::string dir = test::makeTempDir("script_runner_subgraph");
  FakeHost host(dir + "/g.json");
  ScriptRunner run(steps(nlohmann::json::parse(R"([{"op": "open_subgraph", "node": "near"}, {"op": "back"},
    {"op": "back", "discard": true}, {"op": "external_write", "path": ")" + dir + R"(/lib.json", "text": "[]"}])")),
                   "s.json");
  while (!run.done()) ASSERT_TRUE(run.step(host)) << run.error();
  EXPECT_EQ(host.calls, (std::vector<std::string>{"open_subgraph near", "back", "back discard"}));
  std::ifstream in(dir + "/lib.json");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "[]");

  ScriptRunner badDiscard(steps(nlohmann::json::parse(R"([{"op": "back", "discard": "yes"}])")), "s.json");
  EXPECT_FALSE(badDiscard.step(host));
  EXPECT_EQ(badDiscard.error(), "s.json: step 1 (back): \"discard\" must be true or false");
  std::filesystem::remove_all(dir);
}

TEST(ScriptRunner, ExternalWriteThenWaitReloadWaitsForTheChangeOnDisk) {
  std::string dir = test::makeTempDir("script_runner");
  FakeHost host(dir + "/g.json");
  ScriptRunner run(steps(nlohmann::json::parse(R"([{"op": "external_write", "text": "{}"}, {"op": "wait_reload"},
    {"op": "camera", "preset": "above"}])")),
                   "s.json");
  ASSERT_TRUE(run.step(host));
  std::ifstream in(dir + "/g.json");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "{}");
  ASSERT_TRUE(run.step(host));  // starts waiting
  ASSERT_TRUE(run.step(host));
  EXPECT_TRUE(host.calls.empty()) << "the next step waits for the reload";
  host.disk = 1;  // the watcher noticed the write
  ASSERT_TRUE(run.step(host));
  EXPECT_EQ(host.calls, std::vector<std::string>{"camera above"});

  FakeHost quiet(dir + "/g.json");
  ScriptRunner never(steps(nlohmann::json::parse(R"([{"op": "wait_reload"}])")), "s.json");
  ASSERT_TRUE(never.step(quiet));
  int frames = 0;
  while (never.step(quiet)) ASSERT_LT(++frames, ScriptRunner::kReloadFrames + 1);
  EXPECT_EQ(frames, ScriptRunner::kReloadFrames - 1);
  EXPECT_EQ(never.error(), "s.json: wait_reload: the change on disk was not noticed");
}

}  // namespace
}  // namespace wg::editor
