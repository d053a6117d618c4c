// docs/watergraph.schema.json: generated from the registry, checked in, named by every
// example graph, and a real JSON Schema validator (python3-jsonschema, Draft7Validator)
// accepts the example graphs and rejects graphs the compiler rejects.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "eco_support.h"

namespace wg {
namespace {

using eco::sh;
using test::shellQuote;

std::string schemaPath() { return test::sourcePath("docs/watergraph.schema.json"); }

std::string validatorCommand(const std::vector<std::string>& files, bool expectInvalid) {
  std::string cmd = eco::debianPython() + " " + shellQuote(test::sourcePath("tests/ecosystem/validate_json_schema.py")) +
                    " " + shellQuote(schemaPath());
  if (expectInvalid) cmd += " --expect-invalid";
  for (const auto& f : files) cmd += " " + shellQuote(f);
  return cmd;
}

std::vector<std::string> schemaBadGraphs() {
  std::vector<std::string> paths;
  for (const auto& name : test::listFiles(test::sourcePath("tests/ecosystem/schema_bad"), ".json"))
    paths.push_back(test::sourcePath("tests/ecosystem/schema_bad/" + name));
  return paths;
}

TEST(Schema, CheckedInFileMatchesTheGenerator) {
  auto r = eco::wgRun("schema");
  ASSERT_EQ(r.exit, 0) << r.err;
  ASSERT_FALSE(r.out.empty());
  EXPECT_TRUE(r.out == test::readFile(schemaPath()))
      << "docs/watergraph.schema.json is out of date; regenerate it with: cmake --build build --target docs";
}

TEST(Schema, OutputOptionWritesTheSameBytes) {
  eco::TempDir tmp;
  auto r = eco::wgRun("schema -o " + shellQuote(tmp / "s.json"));
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(test::readFile(tmp / "s.json"), eco::wgRun("schema").out);
}

TEST(Schema, ListsEveryNodeTypeWithItsPortsAndOptions) {
  auto schema = nlohmann::json::parse(test::readFile(schemaPath()));
  auto nodes = nlohmann::json::parse(eco::wgRun("nodes --json").out);
  const auto& defs = schema["definitions"];
  std::vector<std::string> types = defs["node_type"]["enum"];
  // The registry's types, and glsl_function, whose ports come from its .glsl file: its
  // options name the file and the function, its inputs are any identifier.
  ASSERT_EQ(types.size(), nodes.size() + 1);
  EXPECT_NE(std::find(types.begin(), types.end(), "glsl_function"), types.end());
  const auto& function = defs["node_glsl_function"]["properties"];
  EXPECT_EQ(function["options"]["required"], nlohmann::json({"file", "function"}));
  EXPECT_EQ(function["inputs"]["additionalProperties"]["$ref"], "#/definitions/source");
  for (const auto& n : nodes) {
    std::string type = n["type"];
    ASSERT_TRUE(defs.contains("node_" + type)) << type;
    const auto& props = defs["node_" + type]["properties"];
    for (const auto& p : n["inputs"]) EXPECT_TRUE(props["inputs"]["properties"].contains(p["name"])) << type;
    for (const auto& o : n["options"]) EXPECT_TRUE(props["options"]["properties"].contains(o["name"])) << type;
    if (type == "expression")  // its inputs are those its options declare: any identifier, any source
      EXPECT_EQ(props["inputs"]["additionalProperties"]["$ref"], "#/definitions/source");
    else
      EXPECT_EQ(props["inputs"]["additionalProperties"], false) << type;
    EXPECT_EQ(props["options"]["additionalProperties"], false);
  }
  // Enum options list their choices; numeric ones their range.
  const auto& fresnel = defs["node_fresnel"]["properties"]["options"]["properties"];
  EXPECT_EQ(fresnel["model"]["enum"], nlohmann::json({"schlick", "exact", "power"}));
  EXPECT_EQ(fresnel["ior"]["minimum"], 1);
  EXPECT_EQ(fresnel["ior"]["maximum"], 3);
}

TEST(Schema, ExampleGraphsNameTheSchema) {
  for (const auto& path : test::exampleGraphs()) {
    auto j = nlohmann::json::parse(test::readFile(path));
    EXPECT_EQ(j.value("$schema", ""), "../docs/watergraph.schema.json") << path;
  }
  auto r = eco::wgRun("fmt --check " + [] {
    std::string all;
    for (const auto& p : test::exampleGraphs()) all += shellQuote(p) + " ";
    return all;
  }());
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
}

TEST(Schema, ValidatorAcceptsEveryExampleGraph) {
  auto graphs = test::exampleGraphs();
  ASSERT_FALSE(graphs.empty());
  auto r = sh(validatorCommand(graphs, false));
  ASSERT_NE(r.exit, 3) << r.out << "(the test needs Debian's python3-jsonschema: scripts/setup.sh installs it)";
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  for (const auto& g : graphs) EXPECT_NE(r.out.find(g + ": valid"), std::string::npos) << r.out;
}

TEST(Schema, ValidatorAcceptsEveryLibraryFunctionGraph) {
  std::vector<std::string> graphs;
  for (const auto& name : test::listFiles(test::sourcePath("graphs/lib"), ".json"))
    graphs.push_back(test::sourcePath("graphs/lib/" + name));
  ASSERT_GE(graphs.size(), 4u);
  auto r = sh(validatorCommand(graphs, false));
  ASSERT_NE(r.exit, 3) << r.out;
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
}

// The editor's frames ("editor": {"frames": ...}, docs/graph-format.md) are part of the
// format the schema describes: a graph with one validates (tests/ecosystem/schema_bad has
// one whose frame holds no node).
TEST(Schema, ValidatorAcceptsTheEditorsFrames) {
  std::string dir = test::makeTempDir("wg_schema_frames");
  std::string graph = dir + "/framed.json";
  test::writeFile(graph, R"({"version": 1, "name": "framed",
    "nodes": [{"id": "u", "type": "uv"}, {"id": "s", "type": "saturate", "inputs": {"x": "u.out"}}],
    "outputs": {"fragment": {"color": [1, 0, 0]}},
    "editor": {"frames": {"coords": {"title": "Coordinates", "comment": "two\nlines", "nodes": ["u", "s"]}}}})");
  auto r = sh(validatorCommand({graph}, false));
  ASSERT_NE(r.exit, 3) << r.out;
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  std::filesystem::remove_all(dir);
}

TEST(Schema, ValidatorRejectsBadGraphs) {
  auto bad = schemaBadGraphs();
  ASSERT_GE(bad.size(), 2u);
  for (const auto& path : bad) {
    auto r = sh(validatorCommand({path}, true));
    ASSERT_NE(r.exit, 3) << r.out;
    EXPECT_EQ(r.exit, 0) << "the schema accepts " << path << ":\n" << r.out << r.err;
    EXPECT_NE(r.out.find(": invalid: "), std::string::npos) << r.out;
  }
}

TEST(Schema, TheCompilerAlsoRejectsTheSchemaBadGraphs) {
  // The schema is stricter than nothing but never stricter than the compiler: each graph
  // it rejects, watergraph rejects too.
  for (const auto& path : schemaBadGraphs()) {
    auto r = eco::wgRun("validate " + shellQuote(path));
    EXPECT_EQ(r.exit, 1) << path << "\n" << r.out << r.err;
  }
}

TEST(Schema, NamesTheUnknownTypeAndOptionValue) {
  auto r = sh(validatorCommand({test::sourcePath("tests/ecosystem/schema_bad/unknown_node_type.json"),
                                test::sourcePath("tests/ecosystem/schema_bad/unknown_option_value.json")},
                               true));
  EXPECT_NE(r.out.find("fresnell"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("schlik"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace wg
