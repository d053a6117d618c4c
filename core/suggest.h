#pragma once
// "did you mean 'fresnel'?" for unknown names.
//
// Hostile files can hold hundreds of thousands of bad references, so suggesting costs
// near-linear time in the file: a NameSuggester indexes its names once (by length), looks
// only at names whose length could be within the edit-distance limit, computes each
// distance inside a band that stops at the best distance found so far, and stops
// suggesting altogether once it has spent its budget of distance cells or suggestions.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace wg {

class NameSuggester {
 public:
  // At most this many suggestions, and this many edit-distance cells in all, per suggester:
  // past either, didYouMean() returns "" (the error is still reported, just without a hint).
  static constexpr std::size_t kMaxSuggestions = 100;
  static constexpr std::size_t kMaxCells = std::size_t{1} << 26;

  NameSuggester() = default;
  explicit NameSuggester(std::vector<std::string> names);

  // The closest name within an edit distance of max(2, |name|/3), or "".
  std::string closest(std::string_view name);
  // " (did you mean 'x'?)" or "".
  std::string didYouMean(std::string_view name);

 private:
  std::size_t boundedDistance(std::string_view a, std::string_view b, std::size_t limit);

  std::vector<std::string> names_;          // by length; within a length, in the given order
  std::vector<std::size_t> order_;          // each name's place in the given list (ties go to the first)
  std::vector<std::size_t> firstOfLength_;  // [n]: the index of the first name of length >= n
  std::vector<std::size_t> prev_, cur_;     // distance rows, kept between calls
  std::size_t suggestions_ = 0;
  std::size_t cells_ = 0;
};

// One-off forms over a small fixed list (a node type's ports, a registry's types).
std::string closestName(std::string_view name, const std::vector<std::string>& candidates);
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace wg
