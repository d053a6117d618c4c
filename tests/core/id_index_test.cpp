// IdIndex, resolve's node-id table: every stored name found with its index, absent names
// not found, a duplicate keeps the first index, and the table grows past what was reserved.
#include "core/id_index.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace wg {
namespace {

TEST(IdIndex, FindsEveryNameAndNoOther) {
  std::vector<std::string> names;
  for (int i = 0; i < 5000; ++i) names.push_back("n" + std::to_string(i));
  IdIndex index;
  index.reserve(10);  // far fewer than stored: it must grow and keep every entry
  for (size_t i = 0; i < names.size(); ++i) {
    auto [stored, inserted] = index.emplace(names[i], static_cast<int>(i));
    EXPECT_TRUE(inserted) << names[i];
    EXPECT_EQ(stored, static_cast<int>(i));
  }
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(index.find(names[i]), static_cast<int>(i)) << names[i];
  EXPECT_EQ(index.find("n5000"), -1);
  EXPECT_EQ(index.find("n"), -1);
  EXPECT_EQ(index.find(""), -1);
  EXPECT_EQ(index.find("n12x"), -1);
}

TEST(IdIndex, DuplicateKeepsTheFirstIndex) {
  std::string a = "water", b = "water", c = "foam";
  IdIndex index;
  EXPECT_EQ(index.find("water"), -1);  // empty table
  EXPECT_EQ(index.emplace(a, 3), std::make_pair(3, true));
  EXPECT_EQ(index.emplace(c, 4), std::make_pair(4, true));
  EXPECT_EQ(index.emplace(b, 9), std::make_pair(3, false));
  EXPECT_EQ(index.find("water"), 3);
  EXPECT_EQ(index.find("foam"), 4);
}

}  // namespace
}  // namespace wg
