#include "core/node_options.h"

#include <algorithm>
#include <cmath>

#include "core/node_spec.h"
#include "core/number_format.h"
#include "core/suggest.h"
#include "core/texture_check.h"

namespace wg {

OptionReader::OptionReader(const NodeSpec& spec, const nlohmann::json& complete) : spec_(spec), options_(complete) {}

void OptionReader::fail(const std::string& why) const {
  throw std::logic_error("node spec '" + spec_.type + "': " + why);
}

const nlohmann::json& OptionReader::value(std::string_view name, int kind) const {
  int i = spec_.optionIndex(name);
  if (i < 0) fail("its options read an option it does not declare: '" + std::string(name) + "'");
  if (static_cast<int>(spec_.options[static_cast<size_t>(i)].kind) != kind)
    fail("option '" + std::string(name) + "' is read as another kind than it is declared");
  auto it = options_.find(name);
  if (it == options_.end()) fail("option '" + std::string(name) + "' is missing from the complete options");
  read_.emplace(name);
  return *it;
}

double OptionReader::number(std::string_view name) const {
  return value(name, static_cast<int>(OptionSpec::Kind::Number)).get<double>();
}
int OptionReader::integer(std::string_view name) const {
  return static_cast<int>(std::lround(value(name, static_cast<int>(OptionSpec::Kind::Integer)).get<double>()));
}
std::int64_t OptionReader::wholeNumber(std::string_view name) const {
  return std::llround(value(name, static_cast<int>(OptionSpec::Kind::Integer)).get<double>());
}
bool OptionReader::flag(std::string_view name) const {
  return value(name, static_cast<int>(OptionSpec::Kind::Bool)).get<bool>();
}
const nlohmann::json& OptionReader::json(std::string_view name) const {
  return value(name, static_cast<int>(OptionSpec::Kind::Json));
}
const std::string& OptionReader::text(std::string_view name) const {
  return value(name, static_cast<int>(OptionSpec::Kind::Text)).get_ref<const std::string&>();
}
const std::string& OptionReader::choiceName(std::string_view name) const {
  return value(name, static_cast<int>(OptionSpec::Kind::Enum)).get_ref<const std::string&>();
}

bool OptionReader::is(std::string_view name, std::string_view v) const {
  const std::string& chosen = choiceName(name);
  const auto& choices = spec_.options[static_cast<size_t>(spec_.optionIndex(name))].choices;
  if (std::find(choices.begin(), choices.end(), v) == choices.end())
    fail("option '" + std::string(name) + "' is compared with '" + std::string(v) + "', which is not one of its choices");
  return chosen == v;
}

void OptionReader::checkMapping(std::string_view name, size_t size,
                                const std::function<bool(std::string_view)>& maps) const {
  choiceName(name);  // declared, an Enum
  const auto& choices = spec_.options[static_cast<size_t>(spec_.optionIndex(name))].choices;
  bool complete = size == choices.size();
  for (const auto& c : choices) complete = complete && maps(c);
  if (!complete) fail("option '" + std::string(name) + "' is parsed with a mapping that does not name each of its choices once");
}

nlohmann::json completeOptions(const NodeSpec& spec, const nlohmann::json& given) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& o : spec.options) out[o.name] = o.defaultValue;
  if (given.is_object())  // null (a `{}` in C++ brace initialisation) gives nothing
    for (auto it = given.begin(); it != given.end(); ++it) out[it.key()] = it.value();
  return out;
}

std::shared_ptr<const ParsedOptions> parseOptions(const NodeSpec& spec, const nlohmann::json& complete) {
  static const auto none = std::make_shared<const ParsedOptions>();
  if (!spec.parseOptions) return none;
  return spec.parseOptions(OptionReader(spec, complete));
}

std::string checkOption(const OptionSpec& o, const nlohmann::json& v, const std::string& graphDir, TextureFile* texture) {
  switch (o.kind) {
    case OptionSpec::Kind::Enum: {
      if (!v.is_string()) return "must be one of its choices (a string)";
      auto s = v.get<std::string>();
      if (std::find(o.choices.begin(), o.choices.end(), s) == o.choices.end()) {
        std::string list;
        for (const auto& c : o.choices) list += (list.empty() ? "" : ", ") + c;
        return "'" + s + "' is not one of: " + list + didYouMean(s, o.choices);
      }
      return "";
    }
    case OptionSpec::Kind::Number:
    case OptionSpec::Kind::Integer: {
      if (!v.is_number()) return "must be a number";
      double x = v.get<double>();
      if (!std::isfinite(x)) return "must be finite";
      if (o.kind == OptionSpec::Kind::Integer && std::floor(x) != x) return "must be a whole number";
      if (o.min && x < *o.min) return formatNumber(x) + " is below the minimum " + formatNumber(*o.min);
      if (o.max && x > *o.max) return formatNumber(x) + " is above the maximum " + formatNumber(*o.max);
      return "";
    }
    case OptionSpec::Kind::Bool:
      return v.is_boolean() ? "" : "must be true or false";
    case OptionSpec::Kind::Json:
      return o.validate ? o.validate(v) : "";
    case OptionSpec::Kind::Text:
      if (!v.is_string()) return "must be a string";
      return o.validate ? o.validate(v) : "";
    case OptionSpec::Kind::Texture: {
      if (!v.is_string()) return "must be a string: \"builtin:<name>\" or a .png path relative to the graph";
      std::string why = checkTextureSource(v.get<std::string>(), graphDir, texture);
      return why.empty() ? "" : "is not usable: " + why;
    }
  }
  return "";
}

NodePorts portsOfNode(const NodeSpec& spec, const nlohmann::json& written) {
  if (!spec.portsFor) return {spec.inputs, spec.outputs};
  if (written.is_object())
    for (auto it = written.begin(); it != written.end(); ++it) {
      int oi = spec.optionIndex(it.key());
      if (oi < 0) continue;  // an unknown option changes no port
      const OptionSpec& o = spec.options[static_cast<size_t>(oi)];
      if (o.kind != OptionSpec::Kind::Texture && !checkOption(o, it.value(), "").empty()) return {};
    }
  return spec.portsFor(*parseOptions(spec, completeOptions(spec, written)));
}

}  // namespace wg
