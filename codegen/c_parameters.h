#pragma once
// What the generated query headers (the C header and its JavaScript twin) write alike
// about numbers and parameters: literals, the clamp a parameter goes through before use
// (the one the runtime applies to the uniforms it uploads), and the range a comment states.
#include <string>

#include "core/program.h"

namespace wg {

enum class HeaderLanguage { C, JavaScript };

// A double literal that reads back to `x`: C always with '.' or an exponent, infinities
// and NaN by <math.h>'s macros; JavaScript's own spellings.
std::string numberLiteral(double x, HeaderLanguage language);

// `source` clamped into the parameter's range as the runtime clamps an uploaded uniform:
// below the minimum (NaN included) to the minimum, above the maximum to the maximum; with
// only a maximum, NaN to the maximum. Calls wgd_min, which both define.
std::string clampedParameter(const ProgramParameter& p, const std::string& source, HeaderLanguage language);

// "[lo, hi]" with "-inf"/"inf" for a missing end, for comments.
std::string parameterRange(const ProgramParameter& p);

}  // namespace wg
