#pragma once
// "did you mean 'fresnel'?" for unknown names.
#include <string>
#include <string_view>
#include <vector>

namespace wg {

// The closest candidate within an edit distance of max(2, |name|/3), or "".
std::string closestName(std::string_view name, const std::vector<std::string>& candidates);
// " (did you mean 'x'?)" or "".
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace wg
