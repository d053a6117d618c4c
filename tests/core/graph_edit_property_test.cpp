// The edit model accepts only what the loader accepts, so what the editor saves always
// loads again (docs/robustness.md). A position of 1e39 overflowed the canvas's float cast
// (a crash in the editor), and a constant of 1e300 was saved and then refused with WG010:
// the user's work was lost.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "core/graph_edit.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "fuzz/edit_sequence.h"
#include "nodes/registry.h"

namespace wg {
namespace {

GraphEditor editorOn(const char* text) {
  Diagnostics diags;
  auto g = parseGraph(text, "e.json", diags);
  EXPECT_TRUE(g);
  return GraphEditor(*g, &defaultRegistry());
}

const char* kGraph =
    R"({"version": 1, "name": "e", "parameters": {"p": {"type": "float", "default": 0}},
        "nodes": [{"id": "t", "type": "time"}, {"id": "s", "type": "sin", "inputs": {"x": "t.out"}},
                  {"id": "n", "type": "fbm", "inputs": {"p": [0, 0]}}],
        "outputs": {"fragment": {"alpha": "s.out"}}})";

TEST(GraphEditLimits, NumbersOutsideFloat32AreRefused) {
  GraphEditor e = editorOn(kGraph);
  EXPECT_NE(e.moveNode("s", {0, 1e39}), "");
  EXPECT_NE(e.addNode("sin", "", {0, 1e39}), "");
  EXPECT_NE(e.addNode("sin", "", {-1e300, 0}), "");
  EXPECT_NE(e.setInputConstant({"s", "x"}, {1e300}), "");
  EXPECT_NE(e.setParameterDefault("p", {-1e39}), "");
  EXPECT_NE(e.setOption("n", "octaves", 1e300), "");
  EXPECT_FALSE(e.canUndo());
  // The largest float32 is accepted and survives a save and a load.
  EXPECT_EQ(e.moveNode("s", {3.4028234663852886e38, -3.4028234663852886e38}), "");
  EXPECT_EQ(e.setInputConstant({"s", "x"}, {-3.4e38}), "");
  Diagnostics diags;
  EXPECT_TRUE(parseGraph(saveGraph(e.graph()), "e.json", diags)) << (diags.empty() ? "" : formatText(diags.all()[0]));
}

TEST(GraphEditLimits, OptionValuesKeepTheFilesLimits) {
  GraphEditor e = editorOn(kGraph);
  nlohmann::json deep = 1;
  for (int i = 0; i < 60; ++i) deep = nlohmann::json::array({deep});  // 5 + 60 = 65 levels in the file
  EXPECT_NE(e.setOption("t", "anything", deep), "");  // refused before the name is even looked up
  EXPECT_NE(e.setOption("n", "octaves", std::string(5000, 'x')), "");
  EXPECT_NE(e.setOption("n", std::string(5000, 'o'), 1), "");
  EXPECT_FALSE(e.canUndo());
}

TEST(GraphEditLimits, PortNamesMustBeIdentifiers) {
  Diagnostics diags;
  auto g = parseGraph(kGraph, "e.json", diags);
  ASSERT_TRUE(g);
  GraphEditor e(*g);  // no registry: only what the file format requires is checked
  EXPECT_NE(e.setInputConstant({"s", "a b"}, {1}), "");
  EXPECT_NE(e.connect("t", "x\ny", {"s", "x"}), "");
}

// Deleting the node that feeds the only output leaves a graph connecting no outputs: it is
// saved, it loads back equal (the user's work is kept), and only compiling it is refused,
// with WG031 at its "outputs" object.
TEST(GraphEditProperty, AGraphWithEveryOutputDisconnectedSavesAndLoadsBack) {
  GraphEditor e = editorOn(kGraph);
  ASSERT_EQ(e.deleteNode("s"), "");
  ASSERT_TRUE(e.graph().outputs.empty());
  std::string saved = saveGraph(e.graph());
  Diagnostics diags;
  auto loaded = parseGraph(saved, "saved.json", diags);
  ASSERT_TRUE(loaded) << saved;
  EXPECT_FALSE(diags.hasErrors());
  EXPECT_EQ(saveGraph(*loaded), saved);
  auto program = buildProgram(*loaded, defaultRegistry(), diags);
  EXPECT_FALSE(program);
  ASSERT_EQ(diags.errorCount(), 1u);
  EXPECT_EQ(diags.all()[0].code, DiagCode::NoOutputs);
  EXPECT_EQ(diags.all()[0].where.line, loaded->outputsWhere.line);
  EXPECT_EQ(diags.all()[0].where.col, loaded->outputsWhere.col);
}

// Any sequence of edit operations leaves a graph whose saved form loads back equal.
TEST(GraphEditProperty, AnySequenceOfEditsSavesAndLoadsBackEqual) {
  std::mt19937 rng(20);  // fixed: the same sequences every run
  int failures = 0;
  for (int i = 0; i < 1500 && failures < 3; ++i) {
    std::string bytes(256, '\0');
    for (char& c : bytes) c = static_cast<char>(rng());
    std::string failed = fuzz::editSequenceProperty(bytes);
    if (!failed.empty()) {
      ++failures;
      ADD_FAILURE() << "sequence " << i << ": " << failed;
    }
  }
}

}  // namespace
}  // namespace wg
