#include "core/suggest.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace wg {
namespace {

std::size_t limitFor(std::string_view name) { return std::max<std::size_t>(2, name.size() / 3); }

std::string hint(const std::string& best) { return best.empty() ? std::string() : " (did you mean '" + best + "'?)"; }

}  // namespace

// Edit distance when it is at most `limit`, else limit + 1. Only cells within `limit` of
// the diagonal can hold a distance <= limit, so each row is computed in that band, and a
// row whose every cell is past the limit ends the search.
std::size_t NameSuggester::boundedDistance(std::string_view a, std::string_view b, std::size_t limit) {
  const std::size_t over = limit + 1;
  ++cells_;  // every candidate costs something, even one refused by its length
  if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > limit) return over;
  prev_.assign(b.size() + 2, over);
  cur_.assign(b.size() + 2, over);
  for (std::size_t j = 0; j <= std::min(b.size(), limit); ++j) prev_[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t lo = i > limit ? i - limit : 1, hi = std::min(b.size(), i + limit);
    cur_[lo - 1] = lo == 1 && i <= limit ? i : over;
    std::size_t rowMin = cur_[lo - 1];
    for (std::size_t j = lo; j <= hi; ++j) {
      std::size_t d = std::min({prev_[j] + 1, cur_[j - 1] + 1, prev_[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      cur_[j] = std::min(d, over);
      rowMin = std::min(rowMin, cur_[j]);
    }
    cur_[hi + 1] = over;  // the next row's band reaches one further
    cells_ += hi >= lo ? hi - lo + 1 : 0;
    if (rowMin > limit) return over;
    std::swap(prev_, cur_);
  }
  return std::min(prev_[b.size()], over);
}

NameSuggester::NameSuggester(std::vector<std::string> names) {
  order_.resize(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) order_[i] = i;
  // By length, and within a length in the given order: ties go to the earlier name.
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t a, std::size_t b) { return names[a].size() < names[b].size(); });
  names_.reserve(names.size());
  for (std::size_t i : order_) names_.push_back(std::move(names[i]));
  std::size_t longest = names_.empty() ? 0 : names_.back().size();
  firstOfLength_.assign(longest + 2, names_.size());
  std::size_t i = 0;
  for (std::size_t n = 0; n <= longest + 1; ++n) {
    while (i < names_.size() && names_[i].size() < n) ++i;
    firstOfLength_[n] = i;
  }
}

std::string NameSuggester::closest(std::string_view name) {
  if (suggestions_ >= kMaxSuggestions || cells_ >= kMaxCells || names_.empty()) return "";
  const std::size_t limit = limitFor(name);
  // The distance is at least the difference in length: only names of length |name| ± limit.
  std::size_t minLen = name.size() > limit ? name.size() - limit : 0;
  std::size_t maxLen = name.size() + limit;
  std::size_t begin = minLen < firstOfLength_.size() ? firstOfLength_[minLen] : names_.size();
  std::size_t end = maxLen + 1 < firstOfLength_.size() ? firstOfLength_[maxLen + 1] : names_.size();
  std::size_t bestDistance = limit + 1, bestOrder = 0;
  const std::string* best = nullptr;
  for (std::size_t i = begin; i < end && cells_ < kMaxCells; ++i) {
    // The band shrinks to the best distance so far: a worse name cannot win.
    std::size_t bound = best ? bestDistance : limit;
    std::size_t d = boundedDistance(name, names_[i], bound);
    if (d <= bound && (d < bestDistance || (d == bestDistance && order_[i] < bestOrder))) {
      bestDistance = d;
      bestOrder = order_[i];
      best = &names_[i];
    }
  }
  if (!best) return "";
  ++suggestions_;
  return *best;
}

std::string NameSuggester::didYouMean(std::string_view name) { return hint(closest(name)); }

std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
  return NameSuggester(candidates).closest(name);
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  return hint(closestName(name, candidates));
}

}  // namespace wg
