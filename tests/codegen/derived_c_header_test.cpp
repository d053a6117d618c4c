// The C header of derived uniforms (codegen/derived_c_header.h): compiled as C and as C++
// with every warning an error, it computes what the double CPU backend computes, for every
// node type of the derived vocabulary, at edge values (zeros, ties, NaN, huge arguments)
// and with a parameter clamped into its range as the runtime clamps it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "codegen/cpu_backend.h"
#include "derived_samples.h"
#include "test_support.h"

namespace wg {
namespace {

using test::DerivedCase;
using test::DerivedSample;

std::string cNumber(double x) {
  if (std::isnan(x)) return "NAN";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// A C program that fills the structs for every case and prints every derived component.
std::string driver(const DerivedSample& s, const std::vector<DerivedCase>& cases) {
  const std::string pre = derivedCPrefix("sample");
  std::string c = "#include <math.h>\n#include <stdio.h>\n#include <string.h>\n#include \"sample.h\"\nint main(void) {\n";
  for (const DerivedCase& k : cases) {
    c += "  {\n    " + pre + "parameters p;\n    " + pre + "draw d;\n    " + pre + "uniforms o;\n";
    c += "    memset(&d, 0, sizeof d);\n";
    for (size_t i = 0; i < s.parameters.size(); ++i) {
      const Value& v = k.parameters[i];
      const std::string& name = s.parameters[i].name;
      for (int j = 0; j < v.size(); ++j)
        c += "    p." + name + (v.size() == 1 ? "" : "[" + std::to_string(j) + "]") + " = " + cNumber(v[j]) + ";\n";
    }
    c += "    d.time = " + cNumber(k.env.time[0]) + ";\n";
    for (int j = 0; j < 3; ++j) {
      c += "    d.camera_position[" + std::to_string(j) + "] = " + cNumber(k.env.cameraPosition[j]) + ";\n";
      c += "    d.sun_direction[" + std::to_string(j) + "] = " + cNumber(k.env.sunDirection[j]) + ";\n";
    }
    for (int j = 0; j < 16; ++j) c += "    d.view[" + std::to_string(j) + "] = " + cNumber(k.env.view[j]) + ";\n";
    for (int j = 0; j < 2; ++j)
      c += "    d.camera_near_far[" + std::to_string(j) + "] = " + cNumber(k.env.cameraNearFar[j]) + ";\n";
    c += "    " + pre + "compute_derived(&p, &d, &o);\n";
    for (const DerivedUniform& u : s.derived)
      for (int j = 0; j < componentCount(u.value.type); ++j)
        c += "    printf(\"%.9g\\n\", (double)o." + u.uniform + "[" + std::to_string(j) + "]);\n";
    c += "  }\n";
  }
  return c + "  return 0;\n}\n";
}

// Compiles `main.c` beside the header with `compiler` and runs it.
std::vector<std::string> compileAndRun(const std::string& dir, const std::string& compiler) {
  std::string out;
  std::string exe = dir + "/run_" + std::to_string(std::hash<std::string>{}(compiler));
  int rc = test::runCommand(compiler + " -Wall -Wextra -Werror -O2 -o " + test::shellQuote(exe) + " " +
                                test::shellQuote(dir + "/main.c") + " -lm",
                            &out);
  EXPECT_EQ(rc, 0) << compiler << ":\n" << out;
  if (rc != 0) return {};
  std::string printed;
  rc = test::runCommand(test::shellQuote(exe), &printed);
  EXPECT_EQ(rc, 0) << printed;
  return test::splitLines(printed);
}

bool sameFloat(double got, double want) {
  if (std::isnan(want)) return std::isnan(got);
  // One float ulp: the header rounds the same double the backend computes, so only a
  // libm difference at a rounding boundary could move it.
  float w = static_cast<float>(want), g = static_cast<float>(got);
  return g == w || g == std::nextafter(w, INFINITY) || g == std::nextafter(w, -INFINITY);
}

class DerivedCHeader : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    sample_ = new DerivedSample(test::derivedVocabularySample());
    dir_ = test::makeTempDir("wg_derived_c");
    test::writeFile(dir_ + "/sample.h", derivedCHeader("sample", sample_->parameters, sample_->derived));
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(dir_);
    delete sample_;
  }
  static DerivedSample* sample_;
  static std::string dir_;
};
DerivedSample* DerivedCHeader::sample_ = nullptr;
std::string DerivedCHeader::dir_;

TEST_F(DerivedCHeader, EveryVocabularyTypeIsInTheSample) {
  for (std::string_view type : derivedNodeTypes()) {
    bool found = false;
    for (const auto& u : sample_->derived)
      for (const Op& op : u.value.program.ops) found = found || op.spec->type == type;
    EXPECT_TRUE(found) << type;
  }
}

TEST_F(DerivedCHeader, ComputesWhatTheCpuBackendComputes) {
  std::vector<DerivedCase> cases = test::derivedSampleCases(sample_->parameters);
  test::writeFile(dir_ + "/main.c", driver(*sample_, cases));
  for (const std::string compiler : {"cc -std=c99 -pedantic", "c++ -x c++ -std=c++17"}) {
    std::vector<std::string> lines = compileAndRun(dir_, compiler);
    if (lines.empty()) continue;
    size_t at = 0, compared = 0;
    for (const DerivedCase& k : cases) {
      std::vector<Value> params;
      for (size_t i = 0; i < k.parameters.size(); ++i) params.push_back(test::clampedParameter(sample_->parameters[i], k.parameters[i]));
      for (const DerivedUniform& u : sample_->derived) {
        Value want = evaluateDerived(u.value, k.env, params);
        for (int j = 0; j < want.size(); ++j, ++at) {
          ASSERT_LT(at, lines.size()) << compiler;
          double got = std::strtod(lines[at].c_str(), nullptr);
          EXPECT_TRUE(sameFloat(got, want[j]))
              << compiler << ", case " << k.what << ", " << u.uniform << "[" << j << "]: C " << lines[at] << ", backend " << want[j];
          ++compared;
        }
      }
    }
    EXPECT_EQ(at, lines.size()) << compiler;
    EXPECT_GT(compared, 500u);
  }
}

TEST_F(DerivedCHeader, IsDeterministicAndNamesTheGraph) {
  std::string again = derivedCHeader("sample", sample_->parameters, sample_->derived);
  EXPECT_EQ(again, test::readFile(dir_ + "/sample.h"));
  EXPECT_NE(again.find("wg_sample_compute_derived"), std::string::npos);
  EXPECT_EQ(derivedCPrefix("my-lake.v2"), "wg_zzmy_2dlake_2ev2_");  // codegen/c_names.h
}

// Found in review: parameters named like <math.h>'s object-like macros (NAN, INFINITY,
// M_PI, math_errhandling) made members the preprocessor replaced, and names C reserves
// (__x, _X) were kept; and a constant an op does not read (lagoon's combine) warned under
// -Wall. Both compile with every warning an error, as C after <math.h> and as C++.
TEST_F(DerivedCHeader, MacroLikeParameterNamesAndUnreadConstantsCompileCleanly) {
  std::vector<ProgramParameter> parameters = sample_->parameters;  // the derived values index these
  const std::vector<std::pair<std::string, std::string>> names = {
      {"NAN", "zzNAN"}, {"INFINITY", "zzINFINITY"}, {"M_PI", "zzM_5fPI"}, {"HUGE_VAL", "zzHUGE_5fVAL"},
      {"math_errhandling", "zzmath_5ferrhandling"}, {"DOMAIN", "zzDOMAIN"}, {"__x", "zz_5f_5fx"}, {"_Y", "zz_5fY"},
      {"class", "zzclass"}, {"speed", "speed"}};
  for (const auto& [name, member] : names) {
    ProgramParameter p;
    p.name = name;
    p.defaultValue = Value::scalar(1);
    parameters.push_back(p);
  }
  std::string dir = test::makeTempDir("wg_derived_c_macros");
  test::writeFile(dir + "/macros.h", derivedCHeader("macros", parameters, sample_->derived));
  std::string c = "#include <math.h>\n#include \"macros.h\"\nint main(void) {\n  wg_macros_parameters p;\n"
                  "  wg_macros_parameters_default(&p);\n";
  for (const auto& [name, member] : names) c += "  p." + member + " = 2.0;\n";
  test::writeFile(dir + "/main.c", c + "  return p.speed == 2.0 ? 0 : 1;\n}\n");
  for (const std::string compiler : {"cc -std=c99 -pedantic", "c++ -x c++ -std=c++17"}) {
    std::string out;
    int rc = test::runCommand(compiler + " -Wall -Wextra -Werror -o " + test::shellQuote(dir + "/run") + " " +
                                  test::shellQuote(dir + "/main.c") + " -lm",
                              &out);
    EXPECT_EQ(rc, 0) << compiler << ":\n" << out;
  }
  // The lagoon's header through the CLI: its scroll combines read two of four constants.
  std::string out;
  int rc = test::runCommand(test::watergraphBinary() + " compile " + test::shellQuote(test::sourcePath("graphs/lagoon.json")) +
                                " -o " + test::shellQuote(dir + "/lagoon") + " --target c-header",
                            &out);
  ASSERT_EQ(rc, 0) << out;
  test::writeFile(dir + "/lagoon/main.c", "#include \"lagoon.derived.h\"\nint main(void) { return 0; }\n");
  rc = test::runCommand("cc -std=c99 -pedantic -Wall -Wextra -Werror -o " + test::shellQuote(dir + "/lagoon/run") + " " +
                            test::shellQuote(dir + "/lagoon/main.c") + " -lm",
                        &out);
  EXPECT_EQ(rc, 0) << out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
