// check for a graph whose node has no double reference holds the targets to each other
// (accuracy/target_agreement.h): on frames made here, a component moved by 1.5 times the
// tolerance passes (within twice it), one moved by 3 times fails, and NaN is left to the
// NaN count. Then the CLI on a graph whose glsl_function node has no reference: every
// target rendered, the targets compared and found to agree, and the node named.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "accuracy/target_agreement.h"
#include "core/program.h"
#include "core/node_spec.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

CheckReport reportOf(Target target, float value) {
  CheckReport r;
  r.target = target;
  r.width = 4;
  r.height = 2;
  for (const char* label : {"elevation 2 deg", "time 1e+06 s"}) {
    CheckViewResult v;
    v.label = label;
    v.frame.assign(4 * 2 * 4, value);
    r.views.push_back(v);
  }
  return r;
}

TEST(TargetAgreement, TwiceTheToleranceApartIsTheBound) {
  const double tolerance = 1e-5;
  CheckReport first = reportOf(Target::Glsl330, 0.5f);
  CheckReport near = reportOf(Target::Es300, 0.5f);
  near.views[1].frame[5] = static_cast<float>(0.5 + 1.5 * tolerance);
  TargetAgreement a = compareTargets(first, near, tolerance);
  EXPECT_FALSE(a.failed());
  EXPECT_EQ(a.compared, 2 * 8 * 3);  // two views, eight pixels, three colour components
  EXPECT_NEAR(a.worstRatio, 0.75, 0.01);
  EXPECT_EQ(a.worstView, "time 1e+06 s");

  CheckReport far = reportOf(Target::Vk450, 0.5f);
  far.views[0].frame[0] = static_cast<float>(0.5 + 3 * tolerance);
  far.views[0].frame[3] = 7.0f;  // alpha: the frame's, never compared
  TargetAgreement b = compareTargets(first, far, tolerance);
  EXPECT_TRUE(b.failed());
  EXPECT_EQ(b.overBound, 1);
  EXPECT_NEAR(b.maxDifference, 3 * tolerance, 1e-7);
  EXPECT_NE(formatTargetAgreement(b).find("vk450 against glsl330: 48 values"), std::string::npos)
      << formatTargetAgreement(b);

  // Past 1 the bound is relative: 1000 and 1000.015 are within 2e-5 of each other relatively.
  CheckReport bright = reportOf(Target::Glsl330, 1000.0f), brighter = reportOf(Target::Es300, 1000.0f);
  brighter.views[0].frame[1] = 1000.015f;
  EXPECT_FALSE(compareTargets(bright, brighter, tolerance).failed());

  CheckReport nan = reportOf(Target::Es300, 0.5f);
  nan.views[0].frame[2] = std::numeric_limits<float>::quiet_NaN();
  TargetAgreement c = compareTargets(first, nan, tolerance);
  EXPECT_FALSE(c.failed());
  EXPECT_EQ(c.compared, 2 * 8 * 3 - 1);
}

TEST(TargetAgreement, NeedsTheFramesOfOneSweep) {
  CheckReport first = reportOf(Target::Glsl330, 0.5f), other = reportOf(Target::Es300, 0.5f);
  other.views[1].frame.clear();
  EXPECT_THROW(compareTargets(first, other, 1e-5), std::invalid_argument);
  other = reportOf(Target::Es300, 0.5f);
  other.views.pop_back();
  EXPECT_THROW(compareTargets(first, other, 1e-5), std::invalid_argument);
}

TEST(TargetAgreement, NamesTheNodeWithoutAReference) {
  NodeSpec withEval, without;
  withEval.type = "add";
  withEval.eval = [](EvalContext&) {};
  without.type = "glsl_function";
  Program p;
  Op a, b;
  a.spec = &withEval;
  a.nodeId = "sum";
  b.spec = &without;
  b.nodeId = "layer/caustic";
  p.ops = {a};
  EXPECT_EQ(nodeWithoutReference(p), "");
  p.ops.push_back(b);
  EXPECT_EQ(nodeWithoutReference(p), "node 'layer/caustic' (glsl_function)");
}

// The caustic pool's function graph with its reference formula taken out, so that check has
// nothing but the targets to compare.
TEST(CheckCli, NodeWithoutReferenceIsHeldToTheOtherTargets) {
  test::FileTree tree("wg_check_unreferenced");
  tree.write("lib/caustic.glsl", test::readFile(test::sourcePath("graphs/lib/caustic.glsl")));
  auto lib = nlohmann::json::parse(test::readFile(test::sourcePath("graphs/lib/caustic_light.json")));
  bool removed = false;
  for (auto& node : lib["nodes"])
    if (node["type"] == "glsl_function") removed = node["options"].erase("reference") == 1;
  ASSERT_TRUE(removed);
  tree.write("lib/caustic_light.json", lib.dump(2));
  std::string graph = tree.write("caustic_own.json", R"({
  "version": 1, "name": "caustic_own",
  "imports": {"caustic_light": "lib/caustic_light.json"},
  "nodes": [{"id": "light", "type": "caustic_light", "inputs": {"scale": 7}}],
  "outputs": {"fragment": {"color": "light.light"}}
})");
  auto r = test::runWatergraph("check " + test::shellQuote(graph) + " --size 32x18");
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("reference: node 'light/caustic' (glsl_function) has no double reference; checked for NaN and "
                       "Inf, and the targets against each other"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("against each other (node 'light/caustic' (glsl_function) has no double reference):"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  es300 against glsl330: 20736 values"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  vk450 against glsl330: 20736 values"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ok: the targets agree within twice the graph's tolerance"), std::string::npos) << r.out;

  auto one = test::runWatergraph("check " + test::shellQuote(graph) + " --size 32x18 --target es300");
  EXPECT_EQ(one.exit, 0) << one.out << one.err;
  EXPECT_NE(one.out.find("only es300 was checked: --target all holds glsl330, es300 and vk450 to each other"),
            std::string::npos)
      << one.out;
}

}  // namespace
}  // namespace wg::accuracy
