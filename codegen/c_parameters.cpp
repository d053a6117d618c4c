#include "codegen/c_parameters.h"

#include <cmath>

#include "core/number_format.h"

namespace wg {

std::string numberLiteral(double x, HeaderLanguage language) {
  const bool c = language == HeaderLanguage::C;
  if (std::isnan(x)) return c ? "((double)NAN)" : "NaN";
  if (std::isinf(x)) return x > 0 ? (c ? "HUGE_VAL" : "Infinity") : (c ? "-HUGE_VAL" : "-Infinity");
  std::string s = formatNumber(x);
  if (c && s.find_first_of(".e") == std::string::npos) s += ".0";
  if (!c && s == "-0.0") s = "-0";
  return s;
}

std::string clampedParameter(const ProgramParameter& p, const std::string& source, HeaderLanguage language) {
  std::string v = source;
  if (p.min) {
    std::string lo = numberLiteral(*p.min, language);
    v = "(" + v + " >= " + lo + " ? " + v + " : " + lo + ")";
  } else if (p.max) {
    v = "(" + v + " == " + v + " ? " + v + " : " + numberLiteral(*p.max, language) + ")";  // NaN to the upper end
  }
  if (p.max) v = "wgd_min(" + v + ", " + numberLiteral(*p.max, language) + ")";
  return v;
}

std::string parameterRange(const ProgramParameter& p) {
  return "[" + (p.min ? formatNumber(*p.min) : std::string("-inf")) + ", " +
         (p.max ? formatNumber(*p.max) : std::string("inf")) + "]";
}

}  // namespace wg
