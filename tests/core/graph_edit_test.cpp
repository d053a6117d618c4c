// The editing model under the editor: each edit changes the graph or is refused with a
// reason and leaves it alone; undo/redo restore exact states; saving round-trips.
#include <gtest/gtest.h>

#include <filesystem>

#include "codegen/output_files.h"
#include "core/graph_edit.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

Graph lake() {
  Diagnostics d;
  auto g = loadGraphFile(test::sourcePath("graphs/lake.json"), d);
  EXPECT_TRUE(g);
  return g ? *g : Graph{};
}

const NodeInput* input(const Graph& g, const std::string& node, const std::string& port) {
  const Node* n = g.findNode(node);
  if (!n) return nullptr;
  for (const auto& in : n->inputs)
    if (in.port == port) return &in;
  return nullptr;
}

const GraphOutput* output(const Graph& g, OutputSlot slot) {
  for (const auto& o : g.outputs)
    if (o.slot == slot) return &o;
  return nullptr;
}

TEST(GraphEdit, SetParameterDefaultChecksNameSizeAndRange) {
  GraphEditor e(lake(), &defaultRegistry());
  std::string before = saveGraph(e.graph());
  EXPECT_NE(e.setParameterDefault("nope", {1}), "");
  EXPECT_NE(e.setParameterDefault("shallow", {0.1, 0.2}), "");     // vec3 needs 3
  EXPECT_NE(e.setParameterDefault("max_depth", {60}), "");          // max 50
  EXPECT_NE(e.setParameterDefault("max_depth", {0.0}), "");         // min 0.1
  EXPECT_NE(e.setParameterDefault("max_depth", {std::nan("")}), "");
  EXPECT_EQ(saveGraph(e.graph()), before);
  EXPECT_FALSE(e.canUndo());
  EXPECT_FALSE(e.dirty());

  EXPECT_EQ(e.setParameterDefault("shallow", {0.1, 0.2, 0.3}), "");
  EXPECT_EQ(e.graph().findParameter("shallow")->defaultValue, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_TRUE(e.dirty());
  EXPECT_EQ(e.undoLabel(), "set parameter 'shallow'");
}

TEST(GraphEdit, SliderDragsMergeIntoOneUndoStepUntilSealed) {
  GraphEditor e(lake(), &defaultRegistry());
  for (double v : {7.0, 8.0, 9.0}) ASSERT_EQ(e.setParameterDefault("max_depth", {v}), "");
  e.seal();
  ASSERT_EQ(e.setParameterDefault("max_depth", {10}), "");
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(e.graph().findParameter("max_depth")->defaultValue[0], 9.0);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(e.graph().findParameter("max_depth")->defaultValue[0], 6.0);
  EXPECT_FALSE(e.canUndo());
  EXPECT_FALSE(e.dirty());  // back at the loaded state
}

TEST(GraphEdit, ConnectChecksPortsAndRefusesCycles) {
  GraphEditor e(lake(), &defaultRegistry());
  EXPECT_NE(e.connect("uv", "nope", {"radius", "x"}), "");
  EXPECT_NE(e.connect("uv", "out", {"radius", "nope"}), "");
  EXPECT_NE(e.connect("ghost", "out", {"radius", "x"}), "");
  EXPECT_NE(e.connect("color", "out", {"from_centre", "a"}), "") << "color is downstream of from_centre";
  EXPECT_NE(e.connect("radius", "out", {"radius", "x"}), "");
  EXPECT_NE(e.connect("uv", "out", {"", "fragment.colour"}), "");
  EXPECT_FALSE(e.canUndo());

  ASSERT_EQ(e.connect("shore", "out", {"", "fragment.color"}), "");
  const GraphOutput* o = output(e.graph(), OutputSlot::FragmentColor);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->source.name, "shore");
  ASSERT_EQ(e.connect("radius", "out", {"depth", "a"}), "");
  EXPECT_EQ(input(e.graph(), "depth", "a")->source.name, "radius");
}

TEST(GraphEdit, InputsTakeConstantsAndParameters) {
  GraphEditor e(lake(), &defaultRegistry());
  EXPECT_NE(e.setInputConstant({"fresnel", "f0"}, {}), "");
  EXPECT_NE(e.setInputConstant({"fresnel", "f0"}, {1, 2, 3, 4, 5}), "");
  ASSERT_EQ(e.setInputConstant({"fresnel", "f0"}, {0.04}), "");
  EXPECT_EQ(input(e.graph(), "fresnel", "f0")->source.literal, std::vector<double>{0.04});
  EXPECT_NE(e.setInputParameter({"fresnel", "f0"}, "missing"), "");
  ASSERT_EQ(e.setInputParameter({"depth", "b"}, "max_depth"), "");
  EXPECT_EQ(input(e.graph(), "depth", "b")->source.name, "max_depth");
}

TEST(GraphEdit, OptionsAreCheckedAgainstTheNodeType) {
  GraphEditor e(lake(), &defaultRegistry());
  EXPECT_NE(e.setOption("fresnel", "model", "nonsense"), "");
  EXPECT_NE(e.setOption("fresnel", "modle", "exact"), "");
  EXPECT_NE(e.setOption("shore", "clamp", 1), "") << "a bool option";
  EXPECT_NE(e.setOption("ghost", "model", "exact"), "");
  EXPECT_FALSE(e.canUndo());
  ASSERT_EQ(e.setOption("fresnel", "model", "exact"), "");
  EXPECT_EQ(e.graph().findNode("fresnel")->options[0].value, "exact");
  ASSERT_EQ(e.setOption("shore", "clamp", false), "");
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(e.graph().findNode("shore")->options[0].value, true);
}

TEST(GraphEdit, DisconnectRestoresTheDefault) {
  GraphEditor e(lake(), &defaultRegistry());
  EXPECT_NE(e.disconnect({"fresnel", "normal"}), "") << "not set in the file";
  ASSERT_EQ(e.disconnect({"fresnel", "f0"}), "");
  EXPECT_EQ(input(e.graph(), "fresnel", "f0"), nullptr);
  ASSERT_EQ(e.disconnect({"", "fragment.alpha"}), "");
  EXPECT_EQ(output(e.graph(), OutputSlot::FragmentAlpha), nullptr);
}

TEST(GraphEdit, AddNodeNamesItAndDeleteRemovesItsLinks) {
  GraphEditor e(lake(), &defaultRegistry());
  EXPECT_NE(e.addNode("no_such_type", "", {0, 0}), "");
  EXPECT_NE(e.addNode("add", "uv", {0, 0}), "") << "id taken";
  EXPECT_NE(e.addNode("add", "bad id", {0, 0}), "");
  std::string id;
  ASSERT_EQ(e.addNode("add", "", {10, 20}, &id), "");
  EXPECT_EQ(id, "add_1");
  ASSERT_EQ(e.addNode("add", "", {10, 20}, &id), "");
  EXPECT_EQ(id, "add_2");
  EXPECT_EQ(e.graph().findNode("add_2")->editorPosition, (std::array<double, 2>{10, 20}));

  ASSERT_EQ(e.deleteNode("radius"), "");
  EXPECT_EQ(e.graph().findNode("radius"), nullptr);
  EXPECT_EQ(input(e.graph(), "shore", "x"), nullptr) << "the link from radius goes with it";
  ASSERT_EQ(e.deleteNode("color"), "");
  EXPECT_EQ(output(e.graph(), OutputSlot::FragmentColor), nullptr);
  EXPECT_NE(e.deleteNode("color"), "");
}

TEST(GraphEdit, UndoRedoRestoreExactStates) {
  GraphEditor e(lake(), &defaultRegistry());
  std::vector<std::string> states{saveGraph(e.graph())};
  ASSERT_EQ(e.moveNode("uv", {1, 2}), "");
  states.push_back(saveGraph(e.graph()));
  ASSERT_EQ(e.deleteNode("tint"), "");
  states.push_back(saveGraph(e.graph()));
  ASSERT_EQ(e.addNode("fresnel", "f2", {5, 5}), "");
  states.push_back(saveGraph(e.graph()));
  long rev = e.revision();
  for (int i = 2; i >= 0; --i) {
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(saveGraph(e.graph()), states[static_cast<size_t>(i)]);
  }
  EXPECT_FALSE(e.undo());
  for (int i = 1; i <= 3; ++i) {
    ASSERT_TRUE(e.redo());
    EXPECT_EQ(saveGraph(e.graph()), states[static_cast<size_t>(i)]);
  }
  EXPECT_EQ(e.revision(), rev);
  EXPECT_FALSE(e.redo());
  // A new edit after an undo drops the redo branch.
  ASSERT_TRUE(e.undo());
  ASSERT_EQ(e.moveNode("uv", {3, 3}), "");
  EXPECT_FALSE(e.canRedo());
}

TEST(GraphEdit, SeveralNodesMoveAndGoAsOneUndoStep) {
  GraphEditor e(lake(), &defaultRegistry());
  std::string before = saveGraph(e.graph());
  // A drag: the same nodes moved frame after frame merge into one step until sealed.
  ASSERT_EQ(e.moveNodes({{"uv", {1, 2}}, {"radius", {3, 4}}}), "");
  ASSERT_EQ(e.moveNodes({{"uv", {5, 6}}, {"radius", {7, 8}}}), "");
  EXPECT_EQ(e.graph().findNode("radius")->editorPosition, (std::array<double, 2>{7, 8}));
  EXPECT_NE(e.moveNodes({{"uv", {0, 0}}, {"ghost", {0, 0}}}), "") << "an unknown id refuses the whole move";
  EXPECT_EQ(e.graph().findNode("uv")->editorPosition, (std::array<double, 2>{5, 6}));
  EXPECT_NE(e.moveNodes({{"uv", {0, 0}}, {"radius", {0, 1e39}}}), "");
  e.seal();
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(saveGraph(e.graph()), before) << "one step";

  ASSERT_EQ(e.deleteNodes({"radius", "shore"}), "");
  EXPECT_FALSE(e.graph().findNode("radius"));
  EXPECT_FALSE(e.graph().findNode("shore"));
  for (const Node& n : e.graph().nodes)
    for (const NodeInput& in : n.inputs) EXPECT_TRUE(in.source.name != "radius" && in.source.name != "shore") << n.id;
  EXPECT_NE(e.deleteNodes({"uv", "ghost"}), "");
  EXPECT_TRUE(e.graph().findNode("uv")) << "refused whole";
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(saveGraph(e.graph()), before);
}

TEST(GraphEdit, PastedNodesGoInAsOneStepOrNotAtAll) {
  GraphEditor e(lake(), &defaultRegistry());
  std::string before = saveGraph(e.graph());
  auto node = [](const std::string& id, const std::string& type, const std::string& from = "") {
    Node n;
    n.id = id, n.type = type, n.editorPosition = std::array<double, 2>{10, 20};
    if (!from.empty()) n.inputs.push_back({"x", InputSource{InputSource::Kind::NodeOutput, from, "out", {}, {}}, {}});
    return n;
  };
  EXPECT_NE(e.insertNodes({node("a", "saturate"), node("uv", "saturate")}), "") << "a taken id";
  EXPECT_NE(e.insertNodes({node("a", "saturate"), node("a", "saturate")}), "") << "an id twice";
  EXPECT_NE(e.insertNodes({node("a", "no_such_type")}), "");
  EXPECT_NE(e.insertNodes({node("a", "saturate", "ghost")}), "") << "a link to nothing";
  std::string cycle = e.insertNodes({node("a", "saturate", "b"), node("b", "saturate", "c"), node("c", "saturate", "a")});
  EXPECT_NE(cycle.find("cycle"), std::string::npos) << cycle;
  EXPECT_NE(e.insertNodes({node("9a", "saturate")}), "");
  EXPECT_EQ(saveGraph(e.graph()), before) << "every refusal left the graph as it was";
  EXPECT_FALSE(e.canUndo());
  // A long chain (no recursion), linked inside and to the graph.
  std::vector<Node> chain{node("c0", "saturate", "radius")};
  for (int i = 1; i < 5000; ++i) chain.push_back(node("c" + std::to_string(i), "saturate", "c" + std::to_string(i - 1)));
  ASSERT_EQ(e.insertNodes(chain), "");
  EXPECT_EQ(e.graph().nodes.size(), lake().nodes.size() + 5000);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(saveGraph(e.graph()), before) << "one step";
}

TEST(GraphEdit, ParametersAreAddedRenamedMovedAndDeletedWithTheirReferences) {
  GraphEditor e(lake(), &defaultRegistry());
  ASSERT_EQ(e.createPreset("now"), "");  // before glow: the preset holds the lake's five
  Parameter p;
  p.name = "glow", p.type = Type::Vec3, p.defaultValue = {1, 0.5, 0}, p.min = 0, p.max = 1, p.hint = "color";
  ASSERT_EQ(e.addParameter(p), "");
  EXPECT_NE(e.addParameter(p), "") << "taken";
  Parameter bad = p;
  bad.name = "2x";
  EXPECT_NE(e.addParameter(bad), "");
  bad.name = "short", bad.defaultValue = {1, 2};
  EXPECT_NE(e.addParameter(bad), "") << "a vec3 takes three numbers";
  bad.defaultValue = {2, 0, 0};
  EXPECT_NE(e.addParameter(bad), "") << "outside min..max";
  bad.type = Type::Float, bad.defaultValue = {0.5}, bad.hint = "color";
  EXPECT_NE(e.addParameter(bad), "") << "a colour hint on a float";

  // Rename: node inputs and presets follow; a clash or a non-identifier is refused in place.
  EXPECT_NE(e.renameParameter("max_depth", "deep"), "");
  EXPECT_NE(e.renameParameter("max_depth", "max depth"), "");
  ASSERT_EQ(e.renameParameter("max_depth", "floor_depth"), "");
  EXPECT_FALSE(e.graph().findParameter("max_depth"));
  bool follows = false;
  for (const NodeInput& in : e.graph().findNode("tint")->inputs) follows |= in.port == "max_depth" && in.source.name == "floor_depth";
  EXPECT_TRUE(follows);
  bool inPreset = false;
  for (const PresetValue& v : e.graph().findPreset("now")->values) inPreset |= v.parameter == "floor_depth";
  EXPECT_TRUE(inPreset);
  Diagnostics d;
  EXPECT_TRUE(parseGraph(saveGraph(e.graph()), "renamed.json", d)) << "the renamed graph saves and loads";

  // Delete: refused while read, naming the readers.
  std::string why = e.deleteParameter("floor_depth");
  EXPECT_NE(why.find("node 'tint' input 'max_depth'"), std::string::npos) << why;
  EXPECT_NE(why.find("preset 'now'"), std::string::npos) << why;
  ASSERT_EQ(e.deleteParameter("glow"), "") << "nothing reads it";
  ASSERT_EQ(e.moveParameter("sky", 0), "");
  EXPECT_EQ(e.graph().parameters[0].name, "sky");
  EXPECT_NE(e.moveParameter("sky", 99), "");

  ASSERT_EQ(e.renamePreset("now", "later"), "");
  EXPECT_NE(e.renamePreset("later", "x y"), "");
  ASSERT_EQ(e.deletePreset("later"), "");
  EXPECT_TRUE(e.graph().presets.empty());
}

TEST(GraphEdit, DirtyFollowsTheSavedState) {
  GraphEditor e(lake(), &defaultRegistry());
  ASSERT_EQ(e.moveNode("uv", {1, 2}), "");
  e.markSaved();
  EXPECT_FALSE(e.dirty());
  ASSERT_TRUE(e.undo());
  EXPECT_TRUE(e.dirty());
  ASSERT_TRUE(e.redo());
  EXPECT_FALSE(e.dirty());
}

TEST(GraphEdit, SavedFileKeepsPositionsAndReopensIdentical) {
  GraphEditor e(lake(), &defaultRegistry());
  ASSERT_EQ(e.moveNode("uv", {-120.5, 40}), "");
  ASSERT_EQ(e.addNode("clamp", "", {300, 10}), "");
  ASSERT_EQ(e.setParameterDefault("deep", {0, 0.2, 0.4}), "");
  std::string dir = test::makeTempDir("wg_graph_edit");
  std::string path = dir + "/lake.json";
  Diagnostics d;
  std::string text = saveGraph(e.graph());
  ASSERT_TRUE(writeFileAtomically(path, text, d));
  auto reopened = loadGraphFile(path, d);
  ASSERT_TRUE(reopened);
  EXPECT_EQ(reopened->findNode("uv")->editorPosition, (std::array<double, 2>{-120.5, 40}));
  EXPECT_EQ(saveGraph(*reopened), text);
  EXPECT_EQ(test::listFiles(dir), std::vector<std::string>{"lake.json"}) << "no temporary file left behind";
  std::filesystem::remove_all(dir);
}

TEST(GraphEdit, APresetSetsItsParametersInOneStep) {
  Diagnostics d;
  auto topdown = loadGraphFile(test::sourcePath("graphs/topdown.json"), d);
  ASSERT_TRUE(topdown);
  GraphEditor e(*topdown, &defaultRegistry());
  std::string before = saveGraph(e.graph());
  EXPECT_NE(e.applyPreset("stormy"), "");
  ASSERT_EQ(e.applyPreset("choppy"), "");
  EXPECT_EQ(e.graph().findParameter("wave_height")->defaultValue, std::vector<double>{1});
  EXPECT_EQ(e.graph().findParameter("ripple_strength")->defaultValue, std::vector<double>{0.3});
  EXPECT_EQ(e.undoLabel(), "apply preset 'choppy'");
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(saveGraph(e.graph()), before);
  EXPECT_FALSE(e.canUndo());
}

TEST(GraphEdit, ReplaceIsUndoable) {
  GraphEditor e(lake(), &defaultRegistry());
  std::string before = saveGraph(e.graph());
  Graph other = e.graph();
  other.nodes.pop_back();
  e.replace(other, "reload from disk");
  EXPECT_EQ(e.graph().nodes.size(), other.nodes.size());
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(saveGraph(e.graph()), before);
}

}  // namespace
}  // namespace wg
