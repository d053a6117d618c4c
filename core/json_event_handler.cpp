#include "core/json_event_handler.h"

namespace wg {

bool JsonScalar::isNumber() const {
  using T = nlohmann::json::value_t;
  return type == T::number_integer || type == T::number_unsigned || type == T::number_float;
}

double JsonScalar::asDouble() const {
  using T = nlohmann::json::value_t;
  if (type == T::number_integer) return static_cast<double>(integer);
  if (type == T::number_unsigned) return static_cast<double>(unsignedInteger);
  return number;
}

nlohmann::json JsonScalar::toJson() {
  using T = nlohmann::json::value_t;
  switch (type) {
    case T::boolean: return boolean;
    case T::number_integer: return integer;
    case T::number_unsigned: return unsignedInteger;
    case T::number_float: return number;
    case T::string: return std::move(*string);
    default: return nullptr;
  }
}

}  // namespace wg
