#pragma once
// The hard-case suite file (tests/hardcases/suite.json), loaded for the accuracy tests that
// walk its cases: the region checks and the mutation runs.
#include <gtest/gtest.h>

#include "accuracy/probe_cases.h"
#include "test_support.h"

namespace wg::accuracy::test_suite {

inline ProbeCaseFile loadSuite() {
  Diagnostics diags;
  auto suite = loadProbeCases(test::sourcePath("tests/hardcases/suite.json"), diags);
  std::string why;
  for (const auto& d : diags.all()) why += formatText(d) + "\n";
  EXPECT_TRUE(suite) << why;
  return suite ? *suite : ProbeCaseFile{};
}

}  // namespace wg::accuracy::test_suite
