#include "core/graph_draft.h"

#include <cstring>
#include <utility>

namespace wg {

const DraftValue* DraftValue::member(std::string_view wanted) const {
  for (const auto& m : members)
    if (m.name == wanted) return &m;
  return nullptr;
}

DraftValue& DraftMembers::emplace_back() {
  if (used_ == items_.size()) items_.emplace_back();
  DraftValue& m = items_[used_++];
  m.members.clear();
  return m;
}

DraftValue& GraphDraftReader::slot(JsonPosition at) {
  DraftValue* s = nullptr;
  if (open_.empty()) {
    s = &root_;
  } else if (open_.back().level == Level::Nodes) {
    s = &node_;
    s->members.clear();
    s->value = nullptr;
  } else {
    s = &open_.back().value->members.back();  // made by its key
  }
  s->at = at;
  s->structured = false;
  return *s;
}

void GraphDraftReader::finished() {
  if (!open_.empty() && open_.back().level == Level::Nodes) {
    ++nodeCount_;
    node(node_);
  }
}

nlohmann::json* GraphDraftReader::hold(nlohmann::json&& v) {
  nlohmann::json& top = *held_.back();
  if (top.is_array()) {
    top.push_back(std::move(v));
    return &top.back();
  }
  if (heldDuplicate_) {
    scratch_.push_back(std::move(v));
    return &scratch_.back();
  }
  return &top.get_ref<nlohmann::json::object_t&>().emplace(std::move(heldKey_), std::move(v)).first->second;
}

void GraphDraftReader::scalar(JsonScalar& v, JsonPosition at) {
  seenScalar(v, at);
  if (!held_.empty()) {
    hold(v.toJson());
    return;
  }
  DraftValue& s = slot(at);
  s.type = v.type;
  if (v.type == nlohmann::json::value_t::string && s.value.is_string())
    s.value.get_ref<std::string&>() = *v.string;  // into the reused member's string: no allocation
  else
    s.value = v.toJson();
  finished();
}

void GraphDraftReader::startContainer(bool isArray, JsonPosition at) {
  using value_t = nlohmann::json::value_t;
  // An empty held container, made only for one: an empty json object is a heap block, and
  // the structured ones (every node and its inputs) hold no json.
  auto empty = [isArray] { return isArray ? nlohmann::json::array() : nlohmann::json::object(); };
  if (!held_.empty()) {
    held_.push_back(hold(empty()));
    return;
  }
  DraftValue& s = slot(at);
  s.type = isArray ? value_t::array : value_t::object;
  auto named = [&](std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (s.name == n) return true;
    return false;
  };
  bool structured = false;
  Level level = Level::Record;
  if (open_.empty()) {
    structured = !isArray, level = Level::Root;
  } else {
    switch (open_.back().level) {
      case Level::Root:
        if (!isArray && named({"parameters", "presets", "outputs"})) structured = true, level = Level::Section;
        if (!isArray && (s.name == "imports" || s.name == "view")) structured = true, level = Level::Record;
        if (!isArray && (s.name == "interface" || s.name == "editor")) structured = true, level = Level::Interface;
        if (isArray && s.name == "nodes") structured = true, level = Level::Nodes;
        break;
      case Level::Section: structured = !isArray, level = Level::Record; break;
      case Level::Interface: structured = !isArray, level = Level::Section; break;
      case Level::Nodes: structured = !isArray, level = Level::Node; break;
      case Level::Node: structured = !isArray && named({"options", "inputs", "editor"}), level = Level::Record; break;
      case Level::Record: break;
    }
  }
  if (!structured) {
    s.value = empty();
    held_.push_back(&s.value);
    return;
  }
  s.structured = true;
  s.members.clear();
  s.value = nullptr;
  open_.push_back(Open{&s, level});
}

void GraphDraftReader::endContainer(bool) {
  if (!held_.empty()) {
    held_.pop_back();
    if (held_.empty()) finished();
    return;
  }
  open_.pop_back();
  finished();
}

void GraphDraftReader::key(std::string& name, JsonPosition at, bool duplicate) {
  seenKey(name, at);
  if (!held_.empty()) {
    heldKey_ = std::move(name);
    heldDuplicate_ = duplicate;
    return;
  }
  DraftValue& m = open_.back().value->members.emplace_back();
  m.name = std::move(name);
  m.key = at;
}

}  // namespace wg
