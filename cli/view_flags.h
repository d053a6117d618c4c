#pragma once
// --tonemap NAME and --exposure EV, the same on every command that shows a frame (render,
// check --error-map, the gallery script through render, the editor): they override the
// graph's "view" (core/view_transform.h). A bad name or a number that is not finite and in
// [-20, 20] is a usage error naming the flag (exit 2).
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/finite_number.h"
#include "core/view_transform.h"

namespace wg::cli {

struct ViewFlags {
  std::string toneMapper;         // "" = the graph's
  std::optional<double> exposure;  // unset = the graph's

  // The view a frame of a graph whose own view is `graphView` is shown through.
  ViewTransform over(const ViewTransform& graphView) const;
};

inline ViewTransform ViewFlags::over(const ViewTransform& graphView) const {
  ViewTransform v = graphView;
  if (!toneMapper.empty()) v.toneMapper = *parseToneMapper(toneMapper);  // checked by the flag
  if (exposure) v.exposureEv = *exposure;
  return v;
}

inline void addViewFlags(CLI::App* cmd, ViewFlags& flags) {
  std::vector<std::string> names(toneMapperNames().begin(), toneMapperNames().end());
  cmd->add_option("--tonemap", flags.toneMapper,
                  "tone mapper of the output transform: " + toneMapperList() +
                      " (default: the graph's \"view\", else none = clamp)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--exposure", flags.exposure,
                  "exposure in EV (stops) before the tone mapper: linear radiance x 2^EV (default: the graph's "
                  "\"view\", else 0)")
      ->check(finiteFloat() & CLI::Range(kMinExposureEv, kMaxExposureEv));
}

}  // namespace wg::cli
