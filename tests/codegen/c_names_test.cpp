// The C names of the generated headers (codegen/c_names.h), issue 40's sixth class: names
// unique by construction. cIdentifier is injective and never gives a keyword, a predefined
// or standard macro, a reserved name or "__"; the header suffixes are tail-free; and the
// query headers of graphs `a-b` and `a_b`, whose parameters are named
// linux, unix, int, int_, __x, p__x, errno and NAN, compile together in one translation unit
// after <errno.h> and <math.h> with GCC and Clang, as C99 and C++, every warning an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>

#include "codegen/c_names.h"
#include "codegen/query_header.h"
#include "query_samples.h"

namespace wg {
namespace {

TEST(CNames, PlainNamesStayAndOthersAreEscaped) {
  const std::map<std::string, std::string> expected = {
      {"deep_color", "deep_color"}, {"speed2", "speed2"},   {"int", "zzint"},        {"int_", "zzint_5f"},
      {"__x", "zz_5f_5fx"},        {"p__x", "zzp_5f_5fx"}, {"linux", "zzlinux"},    {"unix", "zzunix"},
      {"errno", "zzerrno"},        {"NAN", "zzNAN"},       {"a-b", "zza_2db"},      {"a_b", "a_b"},
      {"zzint", "zzzzint"},        {"wg_x", "zzwg_5fx"},   {"1a", "zz1a"},          {"", "zz"},
      {"\xff\xfe", "zz_ff_fe"},    {"my lake", "zzmy_20lake"}, {"_Y", "zz_5fY"}, {"stdin", "zzstdin"},
      {"complex", "zzcomplex"},    {"st_mtime", "zzst_5fmtime"}, {"i386", "zzi386"}, {"class", "zzclass"}};
  for (const auto& [name, id] : expected) EXPECT_EQ(cIdentifier(name), id) << name;
}

// Every name over a small hostile alphabet, up to three bytes, plus the keywords and macros:
// all distinct after the map, and each a safe identifier.
TEST(CNames, TheMapIsInjectiveAndGivesSafeIdentifiers) {
  const std::string alphabet = std::string("a_-Zzwg0\xff", 10);  // and a NUL byte
  std::vector<std::string> names = {"", "int", "errno", "linux", "unix", "NAN", "M_PI", "__x", "p__x", "int_"};
  for (char a : alphabet) {
    names.push_back(std::string(1, a));
    for (char b : alphabet) {
      names.push_back(std::string{a, b});
      for (char c : alphabet) names.push_back(std::string{a, b, c});
    }
  }
  std::map<std::string, std::string> seen;
  const std::regex safe("[A-Za-z][A-Za-z0-9_]*");
  for (const std::string& n : names) {
    std::string id = cIdentifier(n);
    auto [it, fresh] = seen.emplace(id, n);
    EXPECT_TRUE(fresh || it->second == n) << "'" << n << "' and '" << it->second << "' both give " << id;
    EXPECT_TRUE(std::regex_match(id, safe)) << id;
    EXPECT_EQ(id.find("__"), std::string::npos) << id;
    EXPECT_NE(id.back(), '_') << id;
    EXPECT_TRUE(isPlainCName(id) || id.rfind("zz", 0) == 0) << id;
    // A plain result is the name itself; an escaped one is never plain.
    EXPECT_EQ(isPlainCName(n), id == n) << n;
  }
}

// "wg_" + G1 + "_" + s1 == "wg_" + G2 + "_" + s2 with G1 != G2 would need one suffix to end
// in "_" + another.
TEST(CNames, HeaderSuffixesAreTailFree) {
  const auto& s = cHeaderSuffixes();
  for (std::string_view a : s)
    for (std::string_view b : s)
      if (a != b) EXPECT_FALSE(a.size() > b.size() && a.ends_with("_" + std::string(b))) << a << " ends in _" << b;
  EXPECT_EQ(cGraphPrefix("a-b"), "wg_zza_2db_");
  EXPECT_NE(cIncludeGuard("a-b", "QUERY"), cIncludeGuard("a_b", "QUERY"));
  EXPECT_NE(cIncludeGuard("A", "QUERY"), cIncludeGuard("a", "QUERY"));  // no upper-casing
}

std::string hostileGraph() {
  return test::graphJson(R"J({"id": "waves", "type": "gerstner_waves"},
      {"id": "bump", "type": "expression",
       "options": {"inputs": {"a": "float", "b": "float", "c": "float", "d": "float", "e": "float", "f": "float",
                              "g": "float", "h": "vec2"},
                   "formula": "vec3(0.0, 0.01 * (a + b + c + d + e + f + g + h.x), 0.0)"},
       "inputs": {"a": "$linux", "b": "$unix", "c": "$int", "d": "$int_", "e": "$__x", "f": "$p__x", "g": "$errno",
                  "h": "$NAN"}},
      {"id": "surface", "type": "vertex_output",
       "inputs": {"position": "waves.position", "displacement": "bump.out", "normal": "waves.normal"}})J",
                         R"J("vertex": {"position": "surface.position", "normal": "surface.normal"},
      "fragment": {"color": [0, 0.2, 0.4]})J",
                         R"J("linux": {"type": "float", "default": 1}, "unix": {"type": "float", "default": 2},
      "int": {"type": "float", "default": 3}, "int_": {"type": "float", "default": 4},
      "__x": {"type": "float", "default": 5}, "p__x": {"type": "float", "default": 6},
      "errno": {"type": "float", "default": 7}, "NAN": {"type": "vec2", "default": [8, 9]})J");
}

// Every global name a header declares is "wg_" + G + "_" + one of the listed suffixes.
void expectListedGlobals(const std::string& header, const std::string& graph) {
  const std::string prefix = cGraphPrefix(graph);
  const std::regex global("\\b" + prefix + "([A-Za-z0-9_]+)");
  const auto& suffixes = cHeaderSuffixes();
  size_t found = 0;
  for (auto it = std::sregex_iterator(header.begin(), header.end(), global); it != std::sregex_iterator(); ++it, ++found)
    EXPECT_NE(std::find(suffixes.begin(), suffixes.end(), (*it)[1].str()), suffixes.end()) << (*it)[0].str();
  EXPECT_GT(found, 5u);
}

TEST(CNames, TwoGraphsHeadersCompileInOneProgram) {
  std::string dir = test::makeTempDir("wg_c_names");
  test::writeFile(dir + "/g.json", hostileGraph());
  std::string errors;
  auto program = test::compileFile(dir + "/g.json", &errors);
  ASSERT_TRUE(program) << errors;
  std::string includes = "#include <errno.h>\n#include <math.h>\n#include <stdio.h>\n";
  std::string body;
  for (const std::string graph : {"a-b", "a_b"}) {
    Diagnostics diags;
    auto query = queryCHeader(graph, *program, diags);
    ASSERT_TRUE(query);
    expectListedGlobals(*query, graph);
    test::writeFile(dir + "/" + graph + ".query.h", *query);
    includes += "#include \"" + graph + ".query.h\"\n";
    const std::string g = cGraphPrefix(graph);
    body += "  {\n    " + g + "params q;\n    double P[3], N[3], V[3];\n";
    body += "    " + g + "params_default(&q);\n";
    body += "    q.zzlinux = q.zzlinux + q.zzunix + q.zzint + q.zzint_5f + q.zz_5f_5fx + q.zzp_5f_5fx + q.zzerrno + q.zzNAN[1];\n";
    body += "    " + g + "displace(&q, 1.0, 2.0, 3.0, P, N, V);\n";
    body += "    printf(\"%.17g %.17g\\n\", P[1], " + g + "height(&q, P[0], P[2], 3.0));\n  }\n";
  }
  test::writeFile(dir + "/main.c", includes + "int main(void) {\n  errno = 0;\n" + body + "  return errno;\n}\n");
  for (const std::string& compiler : test::cCompilers()) {
    auto rows = test::compileAndRunC(dir, compiler);
    ASSERT_EQ(rows.size(), 2u) << compiler;
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), 2u);
      EXPECT_NEAR(row[0], row[1], 1e-12) << compiler;  // linux = 45 lifts the sea by 0.01 * 82
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
