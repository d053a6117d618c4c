#pragma once
// A CLI11 check for number options that reach a shader as a float uniform (time, sun
// angles): the text must be a finite number within float range. CLI11's own conversion
// takes "nan", "inf" and 1e300, which would reach the shader as NaN or Inf and render a
// wrong frame with exit status 0; CLI11's Range lets NaN through (no comparison holds).
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

namespace wg::cli {

// True when `v` reaches a float uniform as a finite value.
inline bool fitsFiniteFloat(double v) { return std::isfinite(v) && std::fabs(v) <= FLT_MAX; }

inline CLI::Validator finiteFloat() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        double v = std::strtod(begin, &end);  // overflow gives +-HUGE_VAL, caught below
        if (end == begin || *end != '\0') return "";  // not a number: CLI11's conversion says so
        if (!fitsFiniteFloat(v))
          return "must be a finite number within float range (got '" + text + "')";
        return "";
      },
      "FINITE");
}

}  // namespace wg::cli
