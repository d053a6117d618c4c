#pragma once
// The reader of valid JSON (core/json_fast_read.h) held to nlohmann's parser on any input:
// what it accepts, nlohmann accepts, with the same values and number types (compared as
// nlohmann prints them, where 1 and 1.0 differ). The other direction, that it accepts every
// file nlohmann accepts but for duplicate keys and nesting past the limit, falls to
// parseJsonEvents, which reports an error for every file the reader refuses (checkErrors
// in loaderProperty then needs one with a line:col).
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/json_fast_read.h"

namespace wg::fuzz {

class JsonDomBuilder : public JsonEventHandler {
 public:
  nlohmann::json root;
  void scalar(JsonScalar& v, JsonPosition) override { place(v.toJson()); }
  void startContainer(bool isArray, JsonPosition) override {
    stack_.push_back(place(isArray ? nlohmann::json::array() : nlohmann::json::object()));
  }
  void endContainer(bool) override { stack_.pop_back(); }
  void key(std::string& name, JsonPosition, bool) override { key_ = name; }

 private:
  nlohmann::json* place(nlohmann::json&& v) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    nlohmann::json& parent = *stack_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      return &parent.back();
    }
    return &(parent[key_] = std::move(v));
  }
  std::vector<nlohmann::json*> stack_;
  std::string key_;
};

inline std::string jsonReaderProperty(std::string_view text) {
  JsonDomBuilder fast;
  if (!readWellFormedJsonEvents(text, fast)) return "";
  nlohmann::json reference = nlohmann::json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (reference.is_discarded()) return "the JSON reader accepted a file nlohmann's parser refuses";
  if (fast.root.dump() != reference.dump())
    return "the JSON reader's values differ from nlohmann's:\n  " + fast.root.dump().substr(0, 400) + "\n  " +
           reference.dump().substr(0, 400);
  return "";
}

}  // namespace wg::fuzz
