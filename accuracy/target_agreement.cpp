#include "accuracy/target_agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace wg::accuracy {

std::string nodeWithoutReference(const Program& program) {
  for (const Op& op : program.ops)
    if (!op.spec->eval) return "node '" + op.nodeId + "' (" + op.spec->type + ")";
  return "";
}

TargetAgreement compareTargets(const CheckReport& first, const CheckReport& other, double tolerance) {
  if (first.views.size() != other.views.size() || first.width != other.width || first.height != other.height)
    throw std::invalid_argument("comparing targets needs two reports of one sweep at one size");
  TargetAgreement a;
  a.first = first.target;
  a.other = other.target;
  for (size_t k = 0; k < first.views.size(); ++k) {
    const std::vector<float>& f = first.views[k].frame;
    const std::vector<float>& o = other.views[k].frame;
    if (f.size() != o.size() || f.size() != static_cast<size_t>(first.width) * first.height * 4)
      throw std::invalid_argument("comparing targets needs every view's frame (CheckOptions::keepFrames)");
    for (size_t i = 0; i < f.size(); ++i) {
      if (i % 4 == 3) continue;  // alpha is the frame's, always 1
      double x = f[i], y = o[i];
      if (!std::isfinite(x) || !std::isfinite(y)) continue;  // counted as NaN/Inf by each target
      double difference = std::abs(x - y);
      double bound = 2.0 * tolerance * std::max(1.0, std::abs(x));
      double ratio = difference / bound;
      ++a.compared;
      if (difference > bound) ++a.overBound;
      a.maxDifference = std::max(a.maxDifference, difference);
      if (ratio > a.worstRatio) {
        a.worstRatio = ratio;
        a.worstView = first.views[k].label;
      }
    }
  }
  return a;
}

std::string formatTargetAgreement(const TargetAgreement& a) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "  %s against %s: %ld values, max difference %.2e, worst difference/bound %.3g%s%s, over the bound %ld\n",
                std::string(targetName(a.other)).c_str(), std::string(targetName(a.first)).c_str(), a.compared,
                a.maxDifference, a.worstRatio, a.worstView.empty() ? "" : " (", a.worstView.empty() ? "" : (a.worstView + ")").c_str(),
                a.overBound);
  return buf;
}

}  // namespace wg::accuracy
