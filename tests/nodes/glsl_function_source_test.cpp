// The token-level side of GLSL function files (nodes/glsl_function_source.h): the names a
// file declares at its top level, what it may not declare, and the renaming into a node's
// namespace that leaves members, swizzles, comments and line breaks alone.
#include <gtest/gtest.h>

#include "nodes/glsl_function_source.h"

namespace wg {
namespace {

TEST(GlslFunctionSource, NamesFunctionsAndConstantsAtTheTopLevel) {
  FunctionFileScan s = scanFunctionFile(
      "// header\nconst float A = 1.0, B[2] = float[2](1.0, 2.0);\nconst vec2 C = vec2(A);\n"
      "float helper(float x);\nfloat helper(float x) { float local = x; return local * A; }\n"
      "vec3 main_colour(vec3 c, out float l) { l = helper(c.x); return c; }\n");
  ASSERT_FALSE(s.fault) << s.fault->message;
  EXPECT_EQ(s.names.functions, (std::vector<std::string>{"helper", "main_colour"}));
  EXPECT_EQ(s.names.constants, (std::vector<std::string>{"A", "B", "C"}));
}

TEST(GlslFunctionSource, RenamesTopLevelNamesOnlyAndKeepsEveryLine) {
  std::string text = "const float K = 2.0; // K stays in comments\nfloat f(vec2 K2) {\n  return K * K2.x + f2(K);\n}\n";
  FunctionFileScan s = scanFunctionFile(text);
  ASSERT_FALSE(s.fault);
  std::string renamed = renameFunctionFile(text, s.names, functionNamespace(3));
  EXPECT_EQ(renamed, "const float wgfn3_K = 2.0; // K stays in comments\nfloat wgfn3_f(vec2 K2) {\n"
                     "  return wgfn3_K * K2.x + f2(wgfn3_K);\n}\n");
}

TEST(GlslFunctionSource, AMemberNamedLikeAFunctionIsNotRenamed) {
  std::string text = "float x(float a) { return a; }\nfloat f(vec2 p) { return x(p.x); }\n";
  FunctionFileScan s = scanFunctionFile(text);
  ASSERT_FALSE(s.fault);
  EXPECT_EQ(renameFunctionFile(text, s.names, "wgfn0_"),
            "float wgfn0_x(float a) { return a; }\nfloat wgfn0_f(vec2 p) { return wgfn0_x(p.x); }\n");
}

struct Refused {
  const char* text;
  int line, col;
  const char* says;
};

TEST(GlslFunctionSource, RefusesWhatOnlyTheGeneratedShaderDeclares) {
  const Refused cases[] = {
      {"uniform float t;\n", 1, 1, "'uniform'"},
      {"float f() { return 1.0; }\nin vec3 n;\n", 2, 1, "'in'"},
      {"layout(location = 0) out vec4 c;\n", 1, 1, "'layout'"},
      {"precision mediump float;\n", 1, 1, "precision"},
      {"struct S { float a; };\n", 1, 1, "struct"},
      {"float g = 2.0;\n", 1, 1, "constant"},
      {"void main() {}\n", 1, 6, "'main'"},
      {"  #version 330\n", 1, 3, "#version"},
      {"#define K 2.0\n", 1, 1, "preprocessor"},
      {"float f() { return 1.0; } \\\n", 1, 27, "backslash"},
      {"float wg_noise(float a) { return a; }\n", 1, 7, "reserved"},
      {"float f(float a) { float wgfn2_x = a; return wgfn2_x; }\n", 1, 26, "clash after renaming"},
      {"float f(float a) { return a; }\nfloat g(float a) {\n", 2, 18, "does not end"},
  };
  for (const auto& c : cases) {
    FunctionFileScan s = scanFunctionFile(c.text);
    ASSERT_TRUE(s.fault) << c.text;
    EXPECT_EQ(s.fault->where.line, c.line) << c.text;
    EXPECT_EQ(s.fault->where.col, c.col) << c.text;
    EXPECT_NE(s.fault->message.find(c.says), std::string::npos) << c.text << ": " << s.fault->message;
  }
}

TEST(GlslFunctionSource, ParametersMayBeInAndOut) {
  FunctionFileScan s = scanFunctionFile("void f(in vec3 c, out float l, const in float k) { l = c.x * k; }\n");
  EXPECT_FALSE(s.fault) << s.fault->message;
}

}  // namespace
}  // namespace wg
