#pragma once
// Typed node options. A node declares its options once (NodeSpec::options: name, kind,
// default, choices) and reads them once, with one parse function, into a plain struct of
// its own; emit, eval, facts, infer and tessellation all read that struct. The JSON it is
// parsed from is complete (completeOptions fills in the declared defaults), so a default
// is never written a second time in the code that uses it.
//
//   struct FresnelOptions { FresnelModel model; bool fromBelow; double ior; };
//   FresnelOptions parse(const OptionReader& o) {
//     return {o.choice<FresnelModel>("model", {{"schlick", Schlick}, ...}), o.is("direction", "water_to_air"),
//             o.number("ior")};
//   }
//   s.parseOptions = optionParser<FresnelOptions>(parse);
//   ... ctx.options<FresnelOptions>().ior
#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg {

struct NodeSpec;
struct OptionSpec;

// One op's parsed options: the node's own struct inside (OptionsOf<T>), or nothing for a
// node without options.
class ParsedOptions {
 public:
  virtual ~ParsedOptions() = default;
  // The node's struct; throws std::logic_error when the node parses into another type.
  template <class T>
  const T& as() const;
};

template <class T>
struct OptionsOf final : ParsedOptions {
  explicit OptionsOf(T v) : value(std::move(v)) {}
  T value;
};

template <class T>
const T& ParsedOptions::as() const {
  if (const auto* held = dynamic_cast<const OptionsOf<T>*>(this)) return held->value;
  throw std::logic_error(std::string("node options read as a type they were not parsed into: ") + typeid(T).name());
}

// What a parse function reads its options through. Every read names an option the spec
// declares, with the kind it declares; an Enum comparison names one of its choices. A
// mistake is a std::logic_error naming the node, and since checkSpec parses every node's
// defaults at registration, a misspelt name fails when the node is registered.
class OptionReader {
 public:
  OptionReader(const NodeSpec& spec, const nlohmann::json& complete);

  double number(std::string_view name) const;  // Number
  int integer(std::string_view name) const;     // Integer
  std::int64_t wholeNumber(std::string_view name) const;  // Integer beyond int's range (a 32-bit seed)
  bool flag(std::string_view name) const;       // Bool
  const nlohmann::json& json(std::string_view name) const;  // Json
  const std::string& text(std::string_view name) const;     // Text
  // An Enum option's value, for nodes that build a GLSL name from it.
  const std::string& choiceName(std::string_view name) const;
  // Whether an Enum option is `value`, which must be one of its choices.
  bool is(std::string_view name, std::string_view value) const;
  // An Enum option as a C++ value; `map` must name each of the spec's choices exactly once.
  template <class E>
  E choice(std::string_view name, std::initializer_list<std::pair<std::string_view, E>> map) const {
    checkMapping(name, map.size(), [&](std::string_view c) {
      for (const auto& [key, value] : map)
        if (key == c) return true;
      return false;
    });
    const std::string& chosen = choiceName(name);
    for (const auto& [key, value] : map)
      if (key == chosen) return value;
    throw std::logic_error("unreachable: choice checked against the spec");
  }

  // The option names read so far (checkSpec: every declared option must be read).
  const std::set<std::string, std::less<>>& namesRead() const { return read_; }

 private:
  const nlohmann::json& value(std::string_view name, int kind) const;
  void checkMapping(std::string_view name, size_t size, const std::function<bool(std::string_view)>& maps) const;
  [[noreturn]] void fail(const std::string& why) const;

  const NodeSpec& spec_;
  const nlohmann::json& options_;
  mutable std::set<std::string, std::less<>> read_;
};

using OptionParser = std::function<std::shared_ptr<const ParsedOptions>(const OptionReader&)>;

// NodeSpec::parseOptions for a node whose options parse into T.
template <class T>
OptionParser optionParser(T (*parse)(const OptionReader&)) {
  return [parse](const OptionReader& r) -> std::shared_ptr<const ParsedOptions> {
    return std::make_shared<const OptionsOf<T>>(parse(r));
  };
}

// `given` over the spec's defaults: the complete options every parse function reads.
nlohmann::json completeOptions(const NodeSpec& spec, const nlohmann::json& given);

// Parses complete, valid options with the spec's parseOptions (an empty ParsedOptions
// for a node without one).
std::shared_ptr<const ParsedOptions> parseOptions(const NodeSpec& spec, const nlohmann::json& complete);

// The ports of a graph node of type `spec` whose options are `written` (as in the file):
// the spec's own, or for a node whose ports follow from its options (NodeSpec::portsFor)
// those its options give; none when those options are not valid (resolve says why).
struct NodePorts;
NodePorts portsOfNode(const NodeSpec& spec, const nlohmann::json& written);

struct TextureFile;  // core/texture_check.h
// Checks one option value against its spec; returns "" or the reason it is refused. A
// texture option naming a PNG that passes fills *texture (its real path and size).
std::string checkOption(const OptionSpec& o, const nlohmann::json& v, const std::string& graphDir,
                        TextureFile* texture = nullptr);

}  // namespace wg
