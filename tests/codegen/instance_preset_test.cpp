// Presets that set options of nodes inside subgraph instances ("a/fresnel.model": the
// instance's id, '/', the node's id inside the subgraph, '.', the option): applied to that
// instance only, checked against the inner node's type whichever preset is applied, and
// refused with a message where the path names no node, or a node that is no instance.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "codegen/compile.h"
#include "core/graph_edit.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

const char* kSkyBlend = R"({
  "version": 1,
  "name": "sky_blend",
  "interface": {"outputs": {"color": {"type": "vec3", "source": "blend.out"}}},
  "parameters": {"water": {"type": "vec3", "default": [0, 0.3, 0.4], "min": 0, "max": 1}},
  "nodes": [
    {"id": "fresnel", "type": "fresnel", "options": {"model": "schlick"}},
    {"id": "blend", "type": "mix", "inputs": {"a": "$water", "b": [0.55, 0.7, 0.9], "t": "fresnel.reflectance"}}
  ]
}
)";

// Two instances, `a` and `b`, and a preset `fast` with the given members.
std::string parent(const std::string& fast) {
  return R"({
  "version": 1,
  "name": "parent",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "presets": {"fast": {)" + fast + R"(}},
  "nodes": [
    {"id": "a", "type": "sky_blend"},
    {"id": "b", "type": "sky_blend", "inputs": {"water": [0.2, 0.2, 0.2]}},
    {"id": "sum", "type": "add", "inputs": {"a": "a.color", "b": "b.color"}}
  ],
  "outputs": {"fragment": {"color": "sum.out"}}
}
)";
}

struct Tree {
  std::string dir = test::makeTempDir("wg_instance_preset");
  Tree() { write("lib/sky_blend.json", kSkyBlend); }
  ~Tree() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string write(const std::string& rel, const std::string& text) const {
    fs::create_directories(fs::path(dir + "/" + rel).parent_path());
    test::writeFile(dir + "/" + rel, text);
    return dir + "/" + rel;
  }
};

struct PresetBuilt {
  std::optional<CompileResult> result;
  Diagnostics diags;
  std::string firstError() const { return diags.all().empty() ? "" : formatText(diags.sorted().front()); }
  std::string fragment() const {
    for (const auto& f : result->files)
      if (f.name.ends_with(".glsl330.frag")) return f.contents;
    return "";
  }
};

PresetBuilt build(const std::string& path, const std::string& preset) {
  PresetBuilt b;
  auto graph = loadGraphFile(path, b.diags);
  CompileOptions options;
  options.targets = {Target::Glsl330};
  options.validate = false;
  options.preset = preset;
  if (graph) b.result = compileGraph(*graph, defaultRegistry(), options, b.diags);
  return b;
}

TEST(InstancePresetOptions, SetTheOptionOfTheNodeInsideThatInstanceOnly) {
  Tree tree;
  std::string path = tree.write("parent.json", parent(R"("a/fresnel.model": "exact")"));
  PresetBuilt plain = build(path, ""), fast = build(path, "fast");
  ASSERT_TRUE(plain.result) << plain.firstError();
  ASSERT_TRUE(fast.result) << fast.firstError();
  // Written: both instances take Schlick of the same inputs, one computation after CSE.
  // With the preset, `a` takes the exact Fresnel and `b` keeps Schlick: one call of each.
  EXPECT_EQ(test::glslCalls(plain.fragment(), "wg_fresnel_schlick"), 1u) << plain.fragment();
  EXPECT_EQ(test::glslCalls(plain.fragment(), "wg_fresnel_exact"), 0u);
  EXPECT_EQ(test::glslCalls(fast.fragment(), "wg_fresnel_schlick"), 1u) << fast.fragment();
  EXPECT_EQ(test::glslCalls(fast.fragment(), "wg_fresnel_exact"), 1u) << fast.fragment();
  // The subgraph's file is shared and stays as written: a second compile without the
  // preset is the first again.
  EXPECT_EQ(build(path, "").fragment(), plain.fragment());
}

TEST(InstancePresetOptions, APathThatNamesNoNodeOrNoInstanceIsRefused) {
  Tree tree;
  PresetBuilt b = build(tree.write("p1.json", parent(R"("c/fresnel.model": "exact")")), "");
  EXPECT_FALSE(b.result);
  EXPECT_NE(b.firstError().find("error: [WG024] preset 'fast' sets an option of node 'c', which the graph does not have"),
            std::string::npos)
      << b.firstError();
  b = build(tree.write("p2.json", parent(R"("a/fresnl.model": "exact")")), "fast");
  EXPECT_FALSE(b.result);
  EXPECT_NE(b.firstError().find("error: [WG024] preset 'fast' sets an option of node 'a/fresnl', but 'sky_blend' has no "
                                "node 'fresnl'"),
            std::string::npos)
      << b.firstError();
  b = build(tree.write("p3.json", parent(R"("sum/x.model": "exact")")), "");
  EXPECT_FALSE(b.result);
  EXPECT_NE(b.firstError().find("[WG024] preset 'fast' sets an option of node 'sum/x', but 'sum' is a 'add' node, not a "
                                "subgraph instance"),
            std::string::npos)
      << b.firstError();
  b = build(tree.write("p4.json", parent(R"("a/b/c/.model": 1)")), "");
  EXPECT_FALSE(b.result);
  EXPECT_NE(b.firstError().find("[WG008]"), std::string::npos) << b.firstError();
}

// Whichever preset is applied, the inner node's type checks the option and its value.
TEST(InstancePresetOptions, AnOptionTheInnerTypeLacksOrAValueItRefusesIsReported) {
  Tree tree;
  PresetBuilt b = build(tree.write("p1.json", parent(R"("a/fresnel.modl": "exact")")), "");
  EXPECT_FALSE(b.result);
  EXPECT_NE(b.firstError().find("[WG022] preset 'fast': node type 'fresnel' has no option 'modl' (did you mean 'model'?)"),
            std::string::npos)
      << b.firstError();
  std::string p2 = tree.write("p2.json", parent(R"("b/fresnel.model": "best")"));
  for (const char* preset : {"", "fast"}) {
    b = build(p2, preset);
    EXPECT_FALSE(b.result) << preset;
    EXPECT_NE(b.firstError().find("p2.json:5:43: error: [WG030]"), std::string::npos) << preset << ": " << b.firstError();
  }
}

// The editor's preset list applies them too, as one undoable edit: its preview compiles the
// instance with the option; undone, the instance is as written again.
TEST(InstancePresetOptions, TheEditorAppliesThemToThePreview) {
  Tree tree;
  std::string path = tree.write("parent.json", parent(R"("a/fresnel.model": "exact")"));
  Diagnostics d;
  auto g = loadGraphFile(path, d);
  ASSERT_TRUE(g);
  GraphEditor e(*g);
  EXPECT_EQ(e.applyPreset("fast"), "");
  CompileOptions options;
  options.targets = {Target::Glsl330};
  options.validate = false;
  auto fragment = [&] {
    Diagnostics cd;
    auto r = compileGraph(e.graph(), defaultRegistry(), options, cd);
    EXPECT_TRUE(r);
    for (const auto& f : r->files)
      if (f.name.ends_with(".glsl330.frag")) return f.contents;
    return std::string();
  };
  EXPECT_EQ(test::glslCalls(fragment(), "wg_fresnel_exact"), 1u);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(test::glslCalls(fragment(), "wg_fresnel_exact"), 0u);
}

}  // namespace
}  // namespace wg
