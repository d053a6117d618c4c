// The watergraph command as a user runs it: exit codes (0 ok, 1 graph errors, 2 usage or
// I/O), what is written and what is not, the diagnostic formats, and each subcommand.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

using test::CmdResult;
// Runs `watergraph <args>` (args already shell-quoted where needed).
CmdResult wgRun(const std::string& args) { return test::runWatergraph(args); }

std::string badGraph(const std::string& name) { return test::sourcePath("tests/bad/" + name); }

class TempDir {
 public:
  TempDir() : path_(test::makeTempDir("wg_cli_")) {}
  ~TempDir() {
    std::error_code ec;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& rel) const { return path_ + "/" + rel; }

 private:
  std::string path_;
};

// `line` is `<path>:<line>:<col>: error: [WGnnn] ...`.
bool isDiagnosticLine(const std::string& line, const std::string& path) {
  static const std::regex rest(R"(^\d+:\d+: error: \[WG\d{3}\] .+)");
  return line.rfind(path + ":", 0) == 0 && std::regex_search(line.substr(path.size() + 1), rest);
}

std::vector<std::string> errorLines(const std::string& err) {
  std::vector<std::string> lines;
  for (const auto& l : test::splitLines(err))
    if (l.find(": error: ") != std::string::npos) lines.push_back(l);
  return lines;
}

TEST(CliCompile, GoodGraphWritesEveryTargetAndTheManifest) {
  TempDir tmp;
  std::string out = tmp / "out";
  CmdResult r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(out));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  std::vector<std::string> expected = {
      "lake.es300.frag",    "lake.es300.frag.body", "lake.es300.vert",     "lake.es300.vert.body",
      "lake.glsl330.frag",  "lake.glsl330.vert",    "lake.manifest.json",  "lake.vk450.frag",
      "lake.vk450.frag.spv", "lake.vk450.vert",     "lake.vk450.vert.spv"};
  // Exactly these: no temporary files (".lake...tmpNNN") left behind by the atomic write.
  EXPECT_EQ(test::listFilesRecursive(out), expected);
  auto manifest = nlohmann::json::parse(test::readFile(out + "/lake.manifest.json"));
  EXPECT_EQ(manifest.at("graph"), "lake");
  // SPIR-V starts with its magic number, little-endian.
  std::string spv = test::readFile(out + "/lake.vk450.frag.spv");
  ASSERT_GE(spv.size(), 20u);
  EXPECT_EQ(spv.substr(0, 4), std::string("\x03\x02\x23\x07", 4));
  EXPECT_EQ(spv.size() % 4, 0u);
}

TEST(CliCompile, TargetOptionLimitsTheOutput) {
  TempDir tmp;
  std::string out = tmp / "out";
  CmdResult r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(out) +
                " --target es300");
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_EQ(test::listFilesRecursive(out),
            (std::vector<std::string>{"lake.es300.frag", "lake.es300.frag.body", "lake.es300.vert", "lake.es300.vert.body",
                                      "lake.manifest.json"}));
}

// A host loads each node texture by the name the manifest records ("file"), named after the
// files written (here a copy named other than the graph's "name"), and `--textures` writes
// exactly those files.
TEST(CliCompile, TheManifestNamesEachNodeTexturesFile) {
  TempDir tmp;
  fs::copy_file(test::sourcePath("graphs/river.json"), tmp / "my-river.json");
  fs::copy(test::sourcePath("graphs/lib"), tmp / "lib", fs::copy_options::recursive);  // its subgraphs
  std::string out = tmp / "out";
  CmdResult r = wgRun("compile " + shellQuote(tmp / "my-river.json") + " -o " + shellQuote(out) +
                      " --target es300 --textures");
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  auto manifest = nlohmann::json::parse(test::readFile(out + "/my-river.manifest.json"));
  std::vector<std::string> expected = {"my-river.es300.frag", "my-river.es300.frag.body", "my-river.es300.vert",
                                       "my-river.es300.vert.body", "my-river.manifest.json"};
  // (listFilesRecursive lists the output folder only: the copied graph and lib/ lie beside it)
  int nodeTextures = 0;
  for (const auto& t : manifest.at("textures")) {
    if (!t.contains("source")) {
      EXPECT_FALSE(t.contains("file")) << t.dump();  // a scene texture is rendered, not a file
      continue;
    }
    ++nodeTextures;
    EXPECT_EQ(t.at("file"), "my-river." + t.at("name").get<std::string>() + ".png") << t.dump();
    expected.push_back(t.at("file"));
  }
  ASSERT_GT(nodeTextures, 0) << "river samples no node texture: the test reaches nothing";
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(test::listFilesRecursive(out), expected);
}

TEST(CliCompile, UnknownTargetIsAUsageError) {
  TempDir tmp;
  CmdResult r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(tmp / "out") +
                " --target glsl999");
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_FALSE(fs::exists(tmp / "out"));
}

// The experimental derived uniforms are gone: their switch and the c-header target they
// implied are usage errors like any unknown option or target.
TEST(CliCompile, TheRemovedDerivedUniformsAndCHeaderAreUsageErrors) {
  TempDir tmp;
  const std::string base = "compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(tmp / "out");
  CmdResult flag = wgRun(base + " --derived-uniforms");
  EXPECT_EQ(flag.exit, 2) << flag.out << flag.err;
  EXPECT_NE(flag.err.find("--derived-uniforms"), std::string::npos) << flag.err;
  CmdResult target = wgRun(base + " --target glsl330,c-header");
  EXPECT_EQ(target.exit, 2) << target.out << target.err;
  EXPECT_NE(target.err.find("unknown target 'c-header'"), std::string::npos) << target.err;
  EXPECT_FALSE(fs::exists(tmp / "out"));
}

// a/water.json and b/water.json write water.* (with --subdirs, water/): the second would
// replace the first. A usage error, nothing written.
TEST(CliCompile, TwoGraphsOfOneFileNameAreRefusedBeforeWriting) {
  TempDir tmp;
  fs::create_directories(tmp / "a");
  fs::create_directories(tmp / "b");
  fs::copy_file(test::sourcePath("graphs/lake.json"), tmp / "a/water.json");
  fs::copy_file(test::sourcePath("graphs/shelf.json"), tmp / "b/water.json");
  for (const char* subdirs : {"", " --subdirs"}) {
    CmdResult r = wgRun("compile " + shellQuote(tmp / "a/water.json") + " " + shellQuote(tmp / "b/water.json") + " -o " +
                        shellQuote(tmp / "out") + subdirs);
    EXPECT_EQ(r.exit, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("would both write"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp / "out"));
  }
  // validate writes nothing: both are checked.
  CmdResult r = wgRun("validate " + shellQuote(tmp / "a/water.json") + " " + shellQuote(tmp / "b/water.json"));
  EXPECT_EQ(r.exit, 0) << r.err;
  // One file, spelled two ways, is no clash.
  r = wgRun("compile " + shellQuote(tmp / "a/water.json") + " " + shellQuote(tmp / "a/../a/water.json") + " -o " +
            shellQuote(tmp / "out") + " --target glsl330");
  EXPECT_EQ(r.exit, 0) << r.err;
}

TEST(CliCompile, AnEmptyTargetIsAUsageError) {
  TempDir tmp;
  CmdResult r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(tmp / "out") +
                      " --target ''");
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--target: the value is empty"), std::string::npos) << r.err;  // as every option's
  EXPECT_FALSE(fs::exists(tmp / "out"));
  for (const char* list : {"glsl330,", ",glsl330", "glsl330,,es300"}) {
    r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(tmp / "out") + " --target " + list);
    EXPECT_EQ(r.exit, 2) << list << ": " << r.err;
    EXPECT_NE(r.err.find("has an empty entry"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp / "out"));
  }
}

TEST(CliCompile, MissingRequiredOptionIsAUsageError) {
  CmdResult r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")));
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
}

TEST(CliCompile, BadGraphExitsOneAndWritesNothing) {
  for (const char* name : {"WG029_type_mismatch.json", "WG003_duplicate_key.json", "WG033_screen_uv_to_vertex_position.json"}) {
    SCOPED_TRACE(name);
    TempDir tmp;
    std::string path = badGraph(name);
    std::string out = tmp / "out";
    CmdResult r = wgRun("compile " + shellQuote(path) + " -o " + shellQuote(out));
    EXPECT_EQ(r.exit, 1) << r.out << r.err;
    auto lines = errorLines(r.err);
    ASSERT_FALSE(lines.empty()) << r.err;
    for (const auto& l : lines) EXPECT_TRUE(isDiagnosticLine(l, path)) << l;
    EXPECT_FALSE(fs::exists(out)) << "the output folder was created for a failed graph";
    // Nothing at all next to it either (no temporary files).
    EXPECT_TRUE(test::listFilesRecursive(tmp.path()).empty());
  }
}

TEST(CliCompile, BadGraphLeavesAnExistingOutputFolderEmpty) {
  TempDir tmp;
  std::string out = tmp / "out";
  fs::create_directory(out);
  CmdResult r = wgRun("compile " + shellQuote(badGraph("WG028_cycle_of_2.json")) + " -o " + shellQuote(out));
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_TRUE(fs::is_empty(out));
}

TEST(CliCompile, MissingGraphFileIsWG050AndExitTwo) {
  TempDir tmp;
  std::string missing = tmp / "no_such_graph.json";
  CmdResult r = wgRun("compile " + shellQuote(missing) + " -o " + shellQuote(tmp / "out"));
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  auto lines = errorLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind(missing + ": error: [WG050] ", 0), 0u) << lines[0];
  EXPECT_FALSE(fs::exists(tmp / "out"));
}

TEST(CliCompile, GraphPathThatIsAFolderIsWG050) {
  TempDir tmp;
  CmdResult r = wgRun("validate " + shellQuote(tmp.path()));
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("[WG050]"), std::string::npos) << r.err;
}

TEST(CliCompile, UnwritableOutputFolderIsWG051AndExitTwo) {
  // A folder under a regular file can never be created, not even by root.
  TempDir tmp;
  std::string file = tmp / "plain_file";
  test::writeFile(file, "not a folder\n");
  std::string out = file + "/out";
  CmdResult r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(out));
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("[WG051]"), std::string::npos) << r.err;
  EXPECT_EQ(test::readFile(file), "not a folder\n");
  EXPECT_EQ(test::listFilesRecursive(tmp.path()), std::vector<std::string>{"plain_file"});
}

TEST(CliValidate, GoodGraphsExitZeroAndWriteNothing) {
  std::string args;
  for (const auto& g : test::exampleGraphs()) args += " " + shellQuote(g);
  ASSERT_FALSE(args.empty());
  CmdResult r = wgRun("validate" + args);
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("ok"), std::string::npos) << r.out;
}

// Function graphs (graphs/lib/) need no output slots: validate checks each through every
// interface output, compile and render take the first, as the editor previews it (one rule;
// they failed with WG031 "connects no outputs"). A library's own errors are still found,
// here an interface output whose source has another type than it declares.
TEST(CliValidate, FunctionGraphsValidateAsLibrariesAndPreviewTheirFirstOutput) {
  std::string args;
  for (const auto& g : test::listFiles(test::sourcePath("graphs/lib"), ".json"))
    args += " " + shellQuote(test::sourcePath("graphs/lib/" + g));
  ASSERT_FALSE(args.empty());
  CmdResult r = wgRun("validate" + args);
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  TempDir tmp;
  r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lib/shore_foam.json")) + " -o " + shellQuote(tmp / "out") +
            " --target glsl330");
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(test::readFile(tmp / "out/shore_foam.glsl330.frag").find("o_color"), std::string::npos);
  // Two outputs; the second is declared float but its source is a vec3.
  test::writeFile(tmp / "two.json", R"({"version": 1, "name": "two",
    "interface": {"outputs": {"fine": {"type": "float", "source": "u.out"},
                              "broken": {"type": "float", "source": "bad.out"}}},
    "nodes": [{"id": "u", "type": "time"},
              {"id": "bad", "type": "fract", "inputs": {"x": "sampled.rgb"}},
              {"id": "sampled", "type": "texture_sample", "inputs": {"uv": "u.out"}}]})");
  r = wgRun("validate " + shellQuote(tmp / "two.json"));
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("[WG074] interface output 'broken'"), std::string::npos) << r.err;
}

TEST(CliValidate, BadGraphsExitOneWithOneLinePerFailure) {
  // Each of these has exactly one problem.
  std::vector<std::string> paths = {badGraph("WG020_unknown_node_type.json"), badGraph("WG024_dangling_reference.json"),
                                    badGraph("WG007_future_version.json")};
  std::string args;
  for (const auto& p : paths) args += " " + shellQuote(p);
  CmdResult r = wgRun("validate" + args);
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  auto lines = test::splitLines(r.err);
  ASSERT_EQ(lines.size(), paths.size()) << r.err;
  std::set<std::string> seen;
  for (const auto& l : lines) {
    bool matched = false;
    for (const auto& p : paths)
      if (isDiagnosticLine(l, p)) {
        matched = true;
        seen.insert(p);
      }
    EXPECT_TRUE(matched) << l;
  }
  EXPECT_EQ(seen.size(), paths.size()) << r.err;
  EXPECT_EQ(r.out.find("validated"), std::string::npos) << r.out;
}

TEST(CliValidate, GoodAndBadTogetherExitOne) {
  CmdResult r = wgRun("validate " + shellQuote(test::sourcePath("graphs/lake.json")) + " " +
                shellQuote(badGraph("WG029_type_mismatch.json")));
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_EQ(errorLines(r.err).size(), 1u) << r.err;
}

TEST(CliValidate, MissingAndBadTogetherExitOne) {
  // A graph error (1) outranks an I/O error (2): the graph problem is what to fix.
  TempDir tmp;
  CmdResult r = wgRun("validate " + shellQuote(tmp / "missing.json") + " " + shellQuote(badGraph("WG029_type_mismatch.json")));
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_EQ(errorLines(r.err).size(), 2u) << r.err;
}

void expectJsonDiagnostic(const CmdResult& r, const std::string& path) {
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << r.out;
  ASSERT_TRUE(j.contains("diagnostics")) << r.out;
  ASSERT_EQ(j["diagnostics"].size(), 1u) << r.out;
  const auto& d = j["diagnostics"][0];
  EXPECT_EQ(d.at("code"), "WG021");
  EXPECT_EQ(d.at("severity"), "error");
  EXPECT_EQ(d.at("file"), path);
  EXPECT_EQ(d.at("line"), 5);
  EXPECT_EQ(d.at("column"), 54);
  EXPECT_EQ(d.at("node"), "l");
  EXPECT_EQ(d.at("port"), "input 'colour'");
  EXPECT_TRUE(d.at("message").is_string());
}

TEST(CliDiagnostics, JsonFormatBeforeTheSubcommand) {
  std::string path = badGraph("WG021_unknown_input_port.json");
  CmdResult r = wgRun("--diagnostics-format json validate " + shellQuote(path));
  expectJsonDiagnostic(r, path);
  EXPECT_EQ(r.err, "");  // JSON goes to stdout, nothing to stderr
}

TEST(CliDiagnostics, JsonFormatAfterTheSubcommand) {
  std::string path = badGraph("WG021_unknown_input_port.json");
  CmdResult r = wgRun("validate " + shellQuote(path) + " --diagnostics-format json");
  expectJsonDiagnostic(r, path);
}

TEST(CliDiagnostics, TextFormatNamesNodeAndPort) {
  std::string path = badGraph("WG021_unknown_input_port.json");
  CmdResult r = wgRun("validate " + shellQuote(path));
  EXPECT_EQ(r.exit, 1);
  auto lines = test::splitLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind(path + ":5:54: error: [WG021] ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("(node 'l', input 'colour')"), std::string::npos) << lines[0];
}

TEST(CliDiagnostics, UnknownFormatIsAUsageError) {
  CmdResult r = wgRun("--diagnostics-format xml validate " + shellQuote(test::sourcePath("graphs/lake.json")));
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
}

TEST(CliNodes, ListsEveryRegistryType) {
  CmdResult r = wgRun("nodes");
  ASSERT_EQ(r.exit, 0) << r.err;
  std::set<std::string> listed;
  for (const auto& l : test::splitLines(r.out)) listed.insert(l.substr(0, l.find(' ')));
  std::set<std::string> registered;
  for (const NodeSpec* s : defaultRegistry().all()) registered.insert(s->type);
  EXPECT_EQ(listed, registered);
  EXPECT_EQ(test::splitLines(r.out).size(), defaultRegistry().all().size());
}

TEST(CliNodes, JsonParsesAndDescribesEveryType) {
  CmdResult r = wgRun("nodes --json");
  ASSERT_EQ(r.exit, 0) << r.err;
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(r.out));
  ASSERT_TRUE(j.is_array());
  std::set<std::string> types;
  for (const auto& n : j) {
    ASSERT_TRUE(n.contains("type")) << n.dump();
    types.insert(n["type"].get<std::string>());
    EXPECT_TRUE(n.contains("inputs")) << n["type"];
    EXPECT_TRUE(n.contains("outputs")) << n["type"];
    EXPECT_TRUE(n.contains("options")) << n["type"];
  }
  std::set<std::string> registered;
  for (const NodeSpec* s : defaultRegistry().all()) registered.insert(s->type);
  EXPECT_EQ(types, registered);
}

TEST(CliNodes, JsonAndMarkdownExcludeEachOther) {
  CmdResult r = wgRun("nodes --json --markdown");
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
}

TEST(CliFmt, ExampleGraphsAreCanonical) {
  for (const auto& g : test::exampleGraphs()) {
    CmdResult r = wgRun("fmt --check " + shellQuote(g));
    EXPECT_EQ(r.exit, 0) << g << " is not in canonical form (run: watergraph fmt " << g << ")\n" << r.out << r.err;
  }
}

// Deliberately not canonical: one line, keys out of order, CRLF, "-0", "1.50".
const char* kMessyGraph =
    "{\"outputs\": {\"fragment\": {\"alpha\": \"f.reflectance\", \"color\": [1.50, 0.5, -0]}}, \"name\": \"messy\",\r\n"
    "\"nodes\": [{\"inputs\": {\"f0\": 0.04}, \"type\": \"fresnel\", \"options\": {\"model\": \"schlick\"}, \"id\": \"f\","
    " \"editor\": {\"y\": 2, \"x\": 1}}], \"version\": 1}\r\n";

TEST(CliFmt, RewritesANonCanonicalCopyOnceThenIsANoOp) {
  TempDir tmp;
  std::string path = tmp / "messy.json";
  test::writeFile(path, kMessyGraph);

  CmdResult check = wgRun("fmt --check " + shellQuote(path));
  EXPECT_EQ(check.exit, 1) << check.out << check.err;
  EXPECT_EQ(test::readFile(path), kMessyGraph) << "--check changed the file";

  CmdResult first = wgRun("fmt " + shellQuote(path));
  ASSERT_EQ(first.exit, 0) << first.out << first.err;
  std::string formatted = test::readFile(path);
  EXPECT_NE(formatted, kMessyGraph);
  EXPECT_EQ(formatted.find('\r'), std::string::npos);
  ASSERT_FALSE(formatted.empty());
  EXPECT_EQ(formatted.back(), '\n');

  // The formatted file says the same as the original.
  Diagnostics d1, d2;
  auto original = parseGraph(kMessyGraph, "messy.json", d1);
  auto reread = parseGraph(formatted, "messy.json", d2);
  ASSERT_TRUE(original && reread) << formatted;
  EXPECT_EQ(saveGraph(*original), formatted);
  EXPECT_EQ(saveGraph(*reread), formatted);

  CmdResult second = wgRun("fmt " + shellQuote(path));
  EXPECT_EQ(second.exit, 0) << second.out << second.err;
  EXPECT_EQ(test::readFile(path), formatted) << "a second fmt changed the file";
  EXPECT_EQ(second.out.find("formatted"), std::string::npos) << second.out;

  CmdResult recheck = wgRun("fmt --check " + shellQuote(path));
  EXPECT_EQ(recheck.exit, 0) << recheck.out << recheck.err;
  // No temporary file left next to it.
  EXPECT_EQ(test::listFilesRecursive(tmp.path()), std::vector<std::string>{"messy.json"});
}

TEST(CliFmt, FormattingExampleGraphCopiesIsIdempotent) {
  for (const auto& g : test::exampleGraphs()) {
    SCOPED_TRACE(g);
    TempDir tmp;
    std::string path = tmp / fs::path(g).filename().string();
    test::writeFile(path, test::readFile(g));
    // The textures a graph reads lie beside it (lagoon_ripples.png), the subgraphs it
    // imports in lib/: copied with it.
    std::string folder = fs::path(g).parent_path().string();
    for (const auto& png : test::listFiles(folder, ".png")) fs::copy_file(folder + "/" + png, tmp / png);
    fs::copy(folder + "/lib", tmp / "lib", fs::copy_options::recursive);
    ASSERT_EQ(wgRun("fmt " + shellQuote(path)).exit, 0);
    std::string once = test::readFile(path);
    ASSERT_EQ(wgRun("fmt " + shellQuote(path)).exit, 0);
    EXPECT_EQ(test::readFile(path), once);
    // Formatting changes nothing the compiler sees.
    TempDir a, b;
    ASSERT_EQ(wgRun("compile " + shellQuote(g) + " -o " + shellQuote(a.path())).exit, 0);
    ASSERT_EQ(wgRun("compile " + shellQuote(path) + " -o " + shellQuote(b.path())).exit, 0);
    auto files = test::listFilesRecursive(a.path());
    ASSERT_EQ(files, test::listFilesRecursive(b.path()));
    for (const auto& f : files) EXPECT_EQ(test::readFile(a / f), test::readFile(b / f)) << f;
  }
}

TEST(CliFmt, BadGraphIsNotRewritten) {
  TempDir tmp;
  std::string path = tmp / "bad.json";
  std::string text = test::readFile(badGraph("WG001_trailing_garbage.json"));
  test::writeFile(path, text);
  CmdResult r = wgRun("fmt " + shellQuote(path));
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_EQ(test::readFile(path), text);
}

// The subcommands `watergraph --help` lists (so a new one is covered without editing here).
std::vector<std::string> subcommands() {
  CmdResult r = wgRun("--help");
  std::vector<std::string> names;
  bool inSection = false;
  static const std::regex entry(R"(^  ([a-z][a-z0-9_-]*)\s)");
  for (const auto& line : test::splitLines(r.out)) {
    if (line.rfind("Subcommands:", 0) == 0 || line.rfind("SUBCOMMANDS:", 0) == 0) {
      inSection = true;
      continue;
    }
    std::smatch m;
    if (inSection && std::regex_search(line, m, entry)) names.push_back(m[1]);
  }
  return names;
}

TEST(CliHelp, EverySubcommandHasExamples) {
  auto names = subcommands();
  for (const char* required : {"compile", "validate", "nodes", "fmt"})
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required << " missing from --help";
  names.insert(names.begin(), "");  // the top-level help too
  for (const auto& cmd : names) {
    SCOPED_TRACE(cmd);
    CmdResult r = wgRun(cmd + " --help");
    EXPECT_EQ(r.exit, 0) << r.err;
    EXPECT_NE(r.out.find("Examples"), std::string::npos) << r.out;
  }
}

TEST(CliHelp, NoSubcommandIsAUsageError) {
  CmdResult r = wgRun("");
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
}

TEST(CliCompile, SummaryWithSubdirs) {
  TempDir tmp;
  std::string out = tmp / "out";
  std::string args;
  auto graphs = test::exampleGraphs();
  for (const auto& g : graphs) args += " " + shellQuote(g);
  CmdResult r = wgRun("compile" + args + " -o " + shellQuote(out) + " --summary --subdirs");
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  auto lines = test::splitLines(r.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_TRUE(std::regex_search(lines[0], std::regex(R"(^graph\s+nodes\s+targets\s+status\s*$)"))) << r.out;
  for (const auto& g : graphs) {
    std::string name = fs::path(g).stem().string();
    EXPECT_TRUE(fs::exists(out + "/" + name + "/" + name + ".manifest.json")) << name;
    EXPECT_TRUE(fs::exists(out + "/" + name + "/" + name + ".glsl330.frag")) << name;
    bool rowFound = false;
    for (const auto& l : lines)
      rowFound |= std::regex_search(l, std::regex("^" + name + R"(\s+\d+/\d+\s+glsl330,es300,vk450\s+ok$)"));
    EXPECT_TRUE(rowFound) << name << "\n" << r.out;
  }
}

TEST(CliCompile, SummaryReportsFailures) {
  TempDir tmp;
  CmdResult r = wgRun("compile " + shellQuote(badGraph("WG029_type_mismatch.json")) + " -o " + shellQuote(tmp / "out") +
                " --summary");
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.out.find("FAILED"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace wg
