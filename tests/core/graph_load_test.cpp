#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "core/graph_io.h"
#include "diagnostic_text.h"
#include "test_support.h"

namespace wg {
namespace {

using core_test::lc;

const char* kValid = R"({
  "$schema": "https://example.com/watergraph-1.json",
  "version": 1,
  "name": "ocean",
  "description": "A test graph",
  "parameters": {
    "waveHeight": {"type": "float", "default": 0.5, "min": 0, "max": 2},
    "deepColor": {"type": "vec3", "default": [0.1, 0.2, 0.3], "hint": "color", "static": true,
                  "description": "colour far down"}
  },
  "nodes": [
    {
      "id": "waves",
      "type": "gerstner",
      "options": {"count": 4, "model": "ocean"},
      "inputs": {"position": "vertexIn.position", "height": "$waveHeight", "dir": [1, 0]},
      "editor": {"x": 10, "y": -20.5}
    },
    {"id": "shade", "type": "lambert", "inputs": {"albedo": "$deepColor", "k": 0.5}}
  ],
  "outputs": {
    "fragment": {"alpha": 1, "color": "shade.color"},
    "vertex": {"position": "waves.position"}
  }
}
)";

struct Result {
  std::optional<Graph> graph;
  Diagnostics diags;
};

Result load(const std::string& text) {
  Result r;
  r.graph = parseGraph(text, "g.json", r.diags);
  return r;
}

// A minimal valid graph with `extra` spliced in as additional top-level members.
std::string withNodes(const std::string& nodes, const std::string& outputs =
                                                    R"({"fragment": {"color": [1, 0, 0]}})") {
  return R"({"version": 1, "name": "g", "nodes": )" + nodes + R"(, "outputs": )" + outputs + "}";
}

using core_test::dump;

// Expects exactly one error, with this code; returns it.
Diagnostic one(const std::string& text, DiagCode code) {
  Result r = load(text);
  EXPECT_FALSE(r.graph) << text;
  EXPECT_EQ(r.diags.all().size(), 1u) << dump(r.diags);
  if (r.diags.all().empty()) return {};
  EXPECT_EQ(r.diags.all()[0].code, code) << dump(r.diags);
  return r.diags.all()[0];
}

TEST(GraphLoad, ValidGraph) {
  Result r = load(kValid);
  ASSERT_TRUE(r.graph) << dump(r.diags);
  EXPECT_TRUE(r.diags.empty());
  const Graph& g = *r.graph;
  EXPECT_EQ(g.file, "g.json");
  EXPECT_EQ(g.schema, "https://example.com/watergraph-1.json");
  EXPECT_EQ(g.version, 1);
  EXPECT_EQ(g.name, "ocean");
  EXPECT_EQ(g.description, "A test graph");

  ASSERT_EQ(g.parameters.size(), 2u);
  EXPECT_EQ(g.parameters[0].name, "waveHeight");  // file order, not sorted
  EXPECT_EQ(g.parameters[0].type, Type::Float);
  EXPECT_EQ(g.parameters[0].defaultValue, std::vector<double>{0.5});
  EXPECT_EQ(g.parameters[0].min, 0.0);
  EXPECT_EQ(g.parameters[0].max, 2.0);
  EXPECT_FALSE(g.parameters[0].isStatic);
  EXPECT_EQ(lc(g.parameters[0].where), "7:5");
  EXPECT_EQ(g.parameters[1].name, "deepColor");
  EXPECT_EQ(g.parameters[1].type, Type::Vec3);
  EXPECT_EQ(g.parameters[1].defaultValue, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(g.parameters[1].hint, "color");
  EXPECT_EQ(g.parameters[1].description, "colour far down");
  EXPECT_TRUE(g.parameters[1].isStatic);
  EXPECT_FALSE(g.parameters[1].min);

  ASSERT_EQ(g.nodes.size(), 2u);
  const Node& w = g.nodes[0];
  EXPECT_EQ(w.id, "waves");
  EXPECT_EQ(w.type, "gerstner");
  EXPECT_EQ(lc(w.where), "12:5");
  EXPECT_EQ(lc(w.idWhere), "13:13");
  EXPECT_EQ(lc(w.typeWhere), "14:15");
  ASSERT_EQ(w.options.size(), 2u);
  EXPECT_EQ(w.options[0].name, "count");
  EXPECT_EQ(w.options[0].value, 4);
  EXPECT_EQ(lc(w.options[0].keyWhere), "15:19");
  EXPECT_EQ(lc(w.options[0].where), "15:28");
  EXPECT_EQ(w.options[1].value, "ocean");
  ASSERT_EQ(w.inputs.size(), 3u);
  EXPECT_EQ(w.inputs[0].port, "position");  // file order
  EXPECT_EQ(w.inputs[0].source.kind, InputSource::Kind::NodeOutput);
  EXPECT_EQ(w.inputs[0].source.name, "vertexIn");
  EXPECT_EQ(w.inputs[0].source.port, "position");
  EXPECT_EQ(lc(w.inputs[0].keyWhere), "16:18");
  EXPECT_EQ(lc(w.inputs[0].source.where), "16:30");
  EXPECT_EQ(w.inputs[1].port, "height");
  EXPECT_EQ(w.inputs[1].source.kind, InputSource::Kind::Parameter);
  EXPECT_EQ(w.inputs[1].source.name, "waveHeight");
  EXPECT_EQ(w.inputs[2].source.kind, InputSource::Kind::Literal);
  EXPECT_EQ(w.inputs[2].source.literal, (std::vector<double>{1, 0}));
  ASSERT_TRUE(w.editorPosition);
  EXPECT_EQ((*w.editorPosition)[0], 10);
  EXPECT_EQ((*w.editorPosition)[1], -20.5);
  EXPECT_FALSE(g.nodes[1].editorPosition);
  EXPECT_EQ(g.nodes[1].inputs[1].source.literal, std::vector<double>{0.5});

  ASSERT_EQ(g.outputs.size(), 3u);  // in slot order
  EXPECT_EQ(g.outputs[0].slot, OutputSlot::VertexPosition);
  EXPECT_EQ(g.outputs[1].slot, OutputSlot::FragmentColor);
  EXPECT_EQ(g.outputs[1].source.name, "shade");
  EXPECT_EQ(g.outputs[2].slot, OutputSlot::FragmentAlpha);
  EXPECT_EQ(g.outputs[2].source.literal, std::vector<double>{1});
  EXPECT_EQ(lc(g.outputs[2].keyWhere), "22:18");
  EXPECT_EQ(lc(g.outputs[2].source.where), "22:27");
}

TEST(GraphLoad, CrlfInput) {
  std::string text;
  for (const char* p = kValid; *p; ++p) {
    if (*p == '\n') text += '\r';
    text += *p;
  }
  Result r = load(text);
  ASSERT_TRUE(r.graph) << dump(r.diags);
  EXPECT_EQ(lc(r.graph->nodes[0].idWhere), "13:13");
  EXPECT_EQ(r.graph->description, "A test graph");
}

TEST(GraphLoad, JsonErrorsPassThrough) {
  auto e = one("{\n  \"version\": 1,\n  \"name\": \"g\",,\n}", DiagCode::JsonSyntax);
  EXPECT_EQ(lc(e.where), "3:15");
  one("\xEF\xBB\xBF{}", DiagCode::JsonEncoding);
  e = one(R"({"version": 1, "version": 1, "name": "g", "nodes": [], "outputs": {}})",
          DiagCode::DuplicateKey);
  EXPECT_EQ(e.message, "duplicate key 'version'");
}

TEST(GraphLoad, WrongJsonType) {
  auto e = one(R"({"version": 1, "name": "g", "nodes": {}, "outputs": {"fragment": {"alpha": 1}}})",
               DiagCode::WrongJsonType);
  EXPECT_EQ(e.message, "'nodes' must be an array, found object");
  EXPECT_EQ(lc(e.where), "1:38");
  e = one("[1]", DiagCode::WrongJsonType);
  EXPECT_EQ(e.message, "the graph must be a JSON object, found array");
  e = one(withNodes(R"([{"id": "a", "type": 3}])"), DiagCode::WrongJsonType);
  EXPECT_EQ(e.node, "a");
  one(withNodes(R"([{"id": "a", "type": "t", "options": []}])"), DiagCode::WrongJsonType);
  one(withNodes(R"(["a"])"), DiagCode::WrongJsonType);
  one(withNodes("[]", R"({"vertex": 1})"), DiagCode::WrongJsonType);
}

TEST(GraphLoad, MissingField) {
  const std::string text = "{\"version\": 1, \"name\": \"g\", \"outputs\": {}, \"nodes\": [\n"
                           "  {\"id\": \"a\"}]}";
  Result r = load(text);
  EXPECT_FALSE(r.graph);
  // The missing type; no outputs connected is resolve's to report, not the loader's.
  ASSERT_EQ(r.diags.all().size(), 1u) << dump(r.diags);
  EXPECT_EQ(r.diags.all()[0].code, DiagCode::MissingField);
  EXPECT_EQ(r.diags.all()[0].message, "node is missing \"type\"");
  EXPECT_EQ(lc(r.diags.all()[0].where), "2:3");

  auto e = one(R"({"version": 1, "name": "g", "outputs": {"fragment": {"alpha": 1}}})",
               DiagCode::MissingField);
  EXPECT_EQ(lc(e.where), "1:1");
  one(R"({"version": 1, "nodes": [], "outputs": {"fragment": {"alpha": 1}}})", DiagCode::MissingField);
  one(withNodes(R"([{"type": "t"}])"), DiagCode::MissingField);
  one(withNodes(R"([{"id": "a", "type": "t", "editor": {"x": 1}}])"), DiagCode::MissingField);
}

TEST(GraphLoad, UnknownField) {
  auto e = one(withNodes(R"([{"id": "a", "type": "t", "colour": 1}])"), DiagCode::UnknownField);
  EXPECT_EQ(e.message, "unknown field 'colour' in node (expected id, type, options, inputs, editor)");
  EXPECT_EQ(e.node, "a");
  EXPECT_EQ(lc(e.where), "1:64");
  one(R"({"version": 1, "name": "g", "nodes": [], "outputs": {"fragment": {"alpha": 1}}, "x": 0})",
      DiagCode::UnknownField);
}

TEST(GraphLoad, Version) {
  auto e = one(R"({"name": "g", "nodes": [], "outputs": {"fragment": {"alpha": 1}}})",
               DiagCode::UnsupportedVersion);
  EXPECT_EQ(e.message, "missing \"version\": this is graph format 1");
  EXPECT_EQ(lc(e.where), "1:1");
  e = one(R"({"version": 2, "name": "g", "nodes": [], "outputs": {"fragment": {"alpha": 1}}})",
          DiagCode::UnsupportedVersion);
  EXPECT_EQ(e.message, "graph format version 2 is newer than this watergraph supports (1)");
  EXPECT_EQ(lc(e.where), "1:13");
  one(R"({"version": "1", "name": "g", "nodes": [], "outputs": {"fragment": {"alpha": 1}}})",
      DiagCode::UnsupportedVersion);
  one(R"({"version": 1.5, "name": "g", "nodes": [], "outputs": {"fragment": {"alpha": 1}}})",
      DiagCode::UnsupportedVersion);
  one(R"({"version": 0, "name": "g", "nodes": [], "outputs": {"fragment": {"alpha": 1}}})",
      DiagCode::UnsupportedVersion);
}

TEST(GraphLoad, InvalidIdentifier) {
  auto e = one(withNodes(R"([{"id": "x; discard; //", "type": "t"}])"), DiagCode::InvalidIdentifier);
  EXPECT_EQ(e.message,
            "node id 'x; discard; //' is not an identifier (letters, digits and '_', not starting "
            "with a digit, at most 64)");
  EXPECT_EQ(lc(e.where), "1:46");
  one(withNodes("[]").replace(withNodes("[]").find("\"g\""), 3, "\"9g\""),
      DiagCode::InvalidIdentifier);
  one(R"({"version": 1, "name": "g", "parameters": {"a-b": {"type": "float", "default": 0}},
         "nodes": [], "outputs": {"fragment": {"alpha": 1}}})",
      DiagCode::InvalidIdentifier);
  one(withNodes("[{\"id\": \"" + std::string(65, 'a') + "\", \"type\": \"t\"}]"),
      DiagCode::InvalidIdentifier);
}

TEST(GraphLoad, InputSources) {
  for (const char* bad : {R"("a.b.c")", R"("a")", R"("$")", R"("$1x")", R"(".b")", R"("a.")",
                          R"("a b.c")", "[1]", "[1, 2, 3, 4, 5]", R"([1, "2"])", "true", "null",
                          R"({"x": 1})", "[]"}) {
    auto e = one(withNodes(std::string(R"([{"id": "a", "type": "t", "inputs": {"p": )") + bad + "}}]"),
                 DiagCode::InvalidReference);
    EXPECT_NE(e.message.find("\"node.port\""), std::string::npos) << e.message;
    EXPECT_EQ(e.node, "a");
    EXPECT_EQ(e.port, "input 'p'");
  }
  auto e = one(withNodes("[]", R"({"fragment": {"color": "oops"}})"), DiagCode::InvalidReference);
  EXPECT_EQ(e.port, "output 'fragment.color'");
}

TEST(GraphLoad, NumbersMustFitFloat32) {
  auto e = one(withNodes(R"([{"id": "a", "type": "t", "inputs": {"p": 1e39}}])"),
               DiagCode::NonFiniteLiteral);
  EXPECT_EQ(e.message, "number 1e+39 is outside float32 range");
  one(withNodes(R"([{"id": "a", "type": "t", "inputs": {"p": 1e999}}])"), DiagCode::NonFiniteLiteral);
  one(withNodes(R"([{"id": "a", "type": "t", "editor": {"x": -4e38, "y": 0}}])"),
      DiagCode::NonFiniteLiteral);
  one(withNodes(R"([{"id": "a", "type": "t", "options": {"k": [1, 5e38]}}])"),
      DiagCode::NonFiniteLiteral);
  EXPECT_TRUE(load(withNodes(R"([{"id": "a", "type": "t", "inputs": {"p": 3.4e38}}])")).graph);
}

std::string withParam(const std::string& param) {
  return R"({"version": 1, "name": "g", "parameters": {"p": )" + param +
         R"(}, "nodes": [], "outputs": {"fragment": {"alpha": "$p"}}})";
}

TEST(GraphLoad, InvalidParameter) {
  EXPECT_TRUE(load(withParam(R"({"type": "vec4", "default": [0, 0, 0, 1], "min": 0, "max": 1})")).graph);
  for (const char* bad : {
           R"({"type": "sampler2D", "default": 0})",
           R"({"type": "mat3", "default": 0})",
           R"({"type": "quux", "default": 0})",
           R"({"type": "vec3", "default": [1, 2]})",
           R"({"type": "vec3", "default": 1})",
           R"({"type": "float", "default": [1]})",
           R"({"type": "float", "default": 0, "min": 1, "max": 0})",
           R"({"type": "float", "default": 5, "min": 0, "max": 1})",
           R"({"type": "vec2", "default": [0.5, -1], "min": 0})",
           R"({"type": "float", "default": 0, "hint": "color"})",
           R"({"type": "vec3", "default": [0, 0, 0], "hint": "colour"})",
       }) {
    one(withParam(bad), DiagCode::InvalidParameter);
  }
  auto e = one(withParam(R"({"type": "vec3", "default": [1, 2]})"), DiagCode::InvalidParameter);
  EXPECT_NE(e.message.find("an array of 3 numbers"), std::string::npos) << e.message;
  one(withParam(R"({"default": 0})"), DiagCode::MissingField);
  one(withParam(R"({"type": "float"})"), DiagCode::MissingField);
  one(withParam(R"({"type": "float", "default": 0, "static": 1})"), DiagCode::WrongJsonType);
  one(withParam(R"({"type": "float", "default": 0, "range": 1})"), DiagCode::UnknownField);
}

TEST(GraphLoad, Outputs) {
  auto e = one(withNodes("[]", R"({"vertex": {"foo": 1}, "fragment": {"alpha": 1}})"),
               DiagCode::UnknownOutputSlot);
  EXPECT_EQ(e.message,
            "unknown output slot 'vertex.foo' (vertex: position, normal; fragment: color, alpha)");
  one(withNodes("[]", R"({"geometry": {"foo": 1}, "fragment": {"alpha": 1}})"),
      DiagCode::UnknownOutputSlot);
}

// A graph whose outputs are all disconnected loads (the editor saves one while the user
// rewires, and it must open again) and keeps where its "outputs" object is, for resolve's
// WG031 (tests/core/resolve_test.cpp).
TEST(GraphLoad, AGraphConnectingNoOutputsLoads) {
  Result r = load(withNodes("[]", "{\"vertex\": {}}"));
  ASSERT_TRUE(r.graph) << dump(r.diags);
  EXPECT_TRUE(r.diags.empty()) << dump(r.diags);
  EXPECT_TRUE(r.graph->outputs.empty());
  EXPECT_EQ(lc(r.graph->outputsWhere), "1:53");
}

TEST(GraphLoad, Limits) {
  one(withNodes("[{\"id\": \"a\", \"type\": \"" + std::string(5000, 't') + "\"}]"),
      DiagCode::LimitExceeded);
  std::string many = "[";
  for (int i = 0; i < 200001; ++i) many += i ? ",{}" : "{}";
  many += "]";
  one(withNodes(many), DiagCode::LimitExceeded);
}

TEST(GraphLoad, CollectsSeveralErrors) {
  Result r = load(withNodes(R"([{"id": "1a", "type": "t", "inputs": {"p": "x.y.z"}, "extra": 0},
                                 {"id": "b"}])"));
  EXPECT_FALSE(r.graph);
  EXPECT_EQ(r.diags.errorCount(), 4u) << dump(r.diags);
}

TEST(GraphLoad, FileErrors) {
  Diagnostics d;
  EXPECT_FALSE(loadGraphFile("/nonexistent/dir/x.json", d));
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, DiagCode::FileRead);
  EXPECT_EQ(d.all()[0].message, "cannot read '/nonexistent/dir/x.json': No such file or directory");
  EXPECT_EQ(d.all()[0].where.file, "/nonexistent/dir/x.json");

  std::string dir = test::makeTempDir("wg_load");
  Diagnostics d2;
  EXPECT_FALSE(loadGraphFile(dir, d2));
  ASSERT_EQ(d2.all().size(), 1u);
  EXPECT_EQ(d2.all()[0].code, DiagCode::FileRead);

  std::string path = dir + "/g.json";
  { std::ofstream(path, std::ios::binary) << kValid; }
  Diagnostics d3;
  auto g = loadGraphFile(path, d3);
  ASSERT_TRUE(g) << dump(d3);
  EXPECT_EQ(g->file, path);
  EXPECT_EQ(g->nodes[0].where.file, path);

  std::string big = dir + "/big.json";
  {
    std::ofstream out(big, std::ios::binary);
    out << std::string(16 * 1024 * 1024 + 1, ' ');
  }
  Diagnostics d4;
  EXPECT_FALSE(loadGraphFile(big, d4));
  ASSERT_EQ(d4.all().size(), 1u);
  EXPECT_EQ(d4.all()[0].code, DiagCode::LimitExceeded);
  std::filesystem::remove_all(dir);
}

// Loading is two steps: parseGraph reads one file and leaves its imports unfollowed (no
// file is opened: a missing one is no error there); loadGraphText and loadGraphFile parse
// it and then follow them, so the missing file is WG070 at the import's path.
TEST(GraphLoad, ParsingOneFileDoesNotFollowItsImports) {
  std::string dir = test::makeTempDir("wg_parse_only");
  const std::string path = dir + "/g.json";
  const std::string text = R"({"version": 1, "name": "g", "imports": {"foam": "lib/missing.json"},
  "nodes": [{"id": "f", "type": "fresnel"}], "outputs": {"fragment": {"color": "f.reflectance"}}})";
  { std::ofstream(path, std::ios::binary) << text; }
  Diagnostics parsed;
  auto g = parseGraph(text, path, parsed);
  ASSERT_TRUE(g) << dump(parsed);
  EXPECT_TRUE(parsed.all().empty()) << dump(parsed);
  ASSERT_EQ(g->imports.size(), 1u);
  EXPECT_EQ(g->imports[0].graph, nullptr);
  EXPECT_TRUE(g->imports[0].file.empty());

  for (int fromFile = 0; fromFile < 2; ++fromFile) {
    Diagnostics loaded;
    auto tree = fromFile ? loadGraphFile(path, loaded) : loadGraphText(std::make_shared<const std::string>(text), path, loaded);
    EXPECT_FALSE(tree);
    ASSERT_EQ(loaded.all().size(), 1u) << dump(loaded);
    EXPECT_EQ(loaded.all()[0].code, DiagCode::ImportMissing) << dump(loaded);
    EXPECT_EQ(loaded.all()[0].where.line, 1) << dump(loaded);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg

// A text the caller holds as a shared string is kept by the diagnostics as it is, not
// copied (a file is in memory once); a text given as a view is copied, and either way the
// kept text is the one parsed.
TEST(GraphLoad, ASharedTextIsKeptWithoutACopy) {
  const std::string graph =
      R"({"version": 1, "name": "g", "nodes": [{"id": "f", "type": "fresnel"}], "outputs": {"fragment": {"color": "f.reflectance"}}})";
  auto shared = std::make_shared<const std::string>(graph);
  wg::Diagnostics diags;
  ASSERT_TRUE(wg::parseGraph(shared, "shared.json", diags));
  EXPECT_EQ(diags.source("shared.json"), shared.get());
  wg::Diagnostics copied;
  ASSERT_TRUE(wg::parseGraph(std::string_view(graph), "view.json", copied));
  ASSERT_NE(copied.source("view.json"), nullptr);
  EXPECT_NE(copied.source("view.json"), &graph);
  EXPECT_EQ(*copied.source("view.json"), graph);
}
