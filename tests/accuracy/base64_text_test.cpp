// Base64 text (accuracy/base64_text.h), the WebGPU executor's way of handing bytes to its
// helper and frames back: RFC 4648's vectors, every length's padding, and text that is not
// base64 refused rather than read as something.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "accuracy/base64_text.h"

namespace wg::accuracy {
namespace {

TEST(Base64Text, MatchesTheRfcVectorsAndRoundTrips) {
  const std::vector<std::pair<std::string, std::string>> vectors = {
      {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, text] : vectors) {
    EXPECT_EQ(base64Text(plain.data(), plain.size()), text);
    auto bytes = bytesOfBase64Text(text);
    ASSERT_TRUE(bytes) << text;
    EXPECT_EQ(std::string(bytes->begin(), bytes->end()), plain);
  }
  std::vector<std::uint8_t> all(256);
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint8_t>(i);
  EXPECT_EQ(bytesOfBase64Text(base64Text(all.data(), all.size())), all);
}

TEST(Base64Text, RefusesWhatIsNotBase64) {
  for (const char* text : {"Zm9", "Zm9v!", "Z=9v", "Zg==Zm9v", "Zm9v\n", "Zg=a"})
    EXPECT_FALSE(bytesOfBase64Text(text)) << text;
}

}  // namespace
}  // namespace wg::accuracy
