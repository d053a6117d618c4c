#include "core/instance_options.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/number_format.h"
#include "core/suggest.h"

namespace wg {

namespace {

using nlohmann::json;

constexpr std::string_view kTextureStateKeys[] = {"file", "wrap", "filter", "color_space"};

std::string quotedList(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out;
}

std::string optionRangeText(const InterfaceOption& o) {
  return "[" + (o.min ? formatNumber(*o.min) : std::string("-inf")) + ", " +
         (o.max ? formatNumber(*o.max) : std::string("inf")) + "]";
}

// Why a texture option's value is not of its form, or "".
std::string interfaceTextureFormProblem(const json& value) {
  if (value.is_string()) return value.get_ref<const std::string&>().empty() ? "is an empty texture path" : "";
  if (!value.is_object())
    return "must be a texture path (a .png beside the graph, or builtin:<name>) or an object with \"file\" and "
           "optionally \"wrap\", \"filter\", \"color_space\"";
  for (auto it = value.begin(); it != value.end(); ++it)
    if (std::find(std::begin(kTextureStateKeys), std::end(kTextureStateKeys), it.key()) == std::end(kTextureStateKeys))
      return "has an unknown member '" + it.key() + "' (expected file, wrap, filter, color_space)";
  auto file = value.find("file");
  if (file == value.end() || !file->is_string() || file->get_ref<const std::string&>().empty())
    return "must name its texture as a non-empty string \"file\"";
  auto wrap = value.find("wrap");
  if (wrap != value.end() && !(wrap->is_string() && parseWrap(wrap->get_ref<const std::string&>())))
    return "has 'wrap' " + wrap->dump() + "; it is repeat, clamp or mirror";
  auto filter = value.find("filter");
  if (filter != value.end() && !(filter->is_string() && parseFilter(filter->get_ref<const std::string&>())))
    return "has 'filter' " + filter->dump() + "; it is nearest, linear or mipmapped";
  auto space = value.find("color_space");
  if (space != value.end() && !(space->is_string() && parseColorSpace(space->get_ref<const std::string&>())))
    return "has 'color_space' " + space->dump() + "; it is srgb or linear";
  return "";
}

std::string folderOf(const std::string& file) { return std::filesystem::path(file).parent_path().string(); }

// `source` (relative to `folder`) as a path relative to the top-level graph's folder, the
// way the program names every texture (builtin names as they are).
std::string relativeToTop(const std::string& source, const std::string& folder, const std::string& top) {
  if (source.rfind(kBuiltinTexturePrefix, 0) == 0) return source;
  namespace fs = std::filesystem;
  fs::path here = folder.empty() ? fs::path(".") : fs::path(folder);
  fs::path root = top.empty() ? fs::path(".") : fs::path(top);
  return (here / source).lexically_normal().lexically_relative(root.lexically_normal()).generic_string();
}

// Binds one option's value into `out`; false after reporting. `file` is the graph file the
// value is written in (texture paths are relative to its folder, and must stay inside it).
bool bindValue(const InstanceOptionRequest& r, const InterfaceOption& option, const json& value, const SourceRef& where,
               const std::string& file, InstanceBindings& out, Diagnostics& diags) {
  const std::string label = "option '" + option.name + "'";
  if (option.kind == InterfaceOption::Kind::Choice) {
    const auto& chosen = value.get_ref<const std::string&>();
    auto at = std::find(option.choices.begin(), option.choices.end(), chosen);
    out.statics[option.name] = static_cast<double>(at - option.choices.begin());
    return true;
  }
  if (option.kind == InterfaceOption::Kind::Number) {
    out.statics[option.name] = value.get<double>();
    return true;
  }
  InterfaceTexture texture = interfaceTexture(value);
  TextureFile checked;
  std::string why = checkTextureSource(texture.source, folderOf(file), &checked);
  if (why.empty() && r.accept) why = r.accept(checked);
  if (!why.empty()) {
    diags.error(DiagCode::InstanceTextureUnusable, where,
                (r.instance ? "instance '" + r.instanceId + "': " : std::string()) + label + " cannot be used: " + why,
                r.instanceId, label);
    return false;
  }
  texture.source = relativeToTop(texture.source, folderOf(file), r.topDirectory);
  out.textures[option.name] = BoundTexture{std::move(texture), where};
  return true;
}

}  // namespace

std::string_view interfaceOptionKindName(InterfaceOption::Kind kind) {
  switch (kind) {
    case InterfaceOption::Kind::Choice: return "choice";
    case InterfaceOption::Kind::Number: return "number";
    case InterfaceOption::Kind::Texture: return "texture";
  }
  return "choice";
}

std::optional<InterfaceOption::Kind> parseInterfaceOptionKind(std::string_view name) {
  for (auto k : {InterfaceOption::Kind::Choice, InterfaceOption::Kind::Number, InterfaceOption::Kind::Texture})
    if (interfaceOptionKindName(k) == name) return k;
  return std::nullopt;
}

std::string interfaceOptionValueProblem(const InterfaceOption& option, const json& value) {
  switch (option.kind) {
    case InterfaceOption::Kind::Choice: {
      if (!value.is_string()) return "must be one of " + quotedList(option.choices) + ", found " + value.dump();
      const auto& v = value.get_ref<const std::string&>();
      if (std::find(option.choices.begin(), option.choices.end(), v) != option.choices.end()) return "";
      return "is '" + v + "', not one of its choices " + quotedList(option.choices) + didYouMean(v, option.choices);
    }
    case InterfaceOption::Kind::Number: {
      if (!value.is_number()) return "must be a number, found " + value.dump();
      double x = value.get<double>();
      if (!std::isfinite(x) || std::fabs(x) > std::numeric_limits<float>::max())
        return "is " + value.dump() + ", not a finite float32 number";
      if ((option.min && x < *option.min) || (option.max && x > *option.max))
        return "is " + formatNumber(x) + ", outside its range " + optionRangeText(option);
      return "";
    }
    case InterfaceOption::Kind::Texture: {
      std::string why = interfaceTextureFormProblem(value);
      return why;
    }
  }
  return "";
}

InterfaceTexture interfaceTexture(const json& value) {
  InterfaceTexture t;
  if (value.is_string()) {
    t.source = value.get<std::string>();
    return t;
  }
  t.source = value.at("file").get<std::string>();
  if (auto it = value.find("wrap"); it != value.end()) t.wrap = parseWrap(it->get_ref<const std::string&>());
  if (auto it = value.find("filter"); it != value.end()) t.filter = parseFilter(it->get_ref<const std::string&>());
  if (auto it = value.find("color_space"); it != value.end())
    t.colorSpace = parseColorSpace(it->get_ref<const std::string&>());
  return t;
}

std::optional<InstanceBindings> bindInstanceOptions(const InstanceOptionRequest& r, Diagnostics& diags) {
  InstanceBindings out;
  bool ok = true;
  const auto& declared = r.interface.options;
  auto find = [&](std::string_view name) -> const InterfaceOption* {
    for (const auto& o : declared)
      if (o.name == name) return &o;
    return nullptr;
  };
  std::vector<std::string> names;
  for (const auto& o : declared) names.push_back(o.name);
  if (r.instance) {
    for (const NodeOption& given : r.instance->options) {
      const InterfaceOption* option = find(given.name);
      const std::string label = "option '" + given.name + "'";
      if (!option) {
        diags.error(DiagCode::InstanceOptionUnknown, given.keyWhere,
                    "instance '" + r.instanceId + "': the interface of '" + r.instance->type + "' declares no " + label +
                        (names.empty() ? std::string(" (it declares none)") : " (it declares " + quotedList(names) + ")") +
                        didYouMean(given.name, names),
                    r.instanceId, label);
        ok = false;
        continue;
      }
      if (std::string why = interfaceOptionValueProblem(*option, given.value); !why.empty()) {
        diags.error(DiagCode::InstanceOptionValue, given.where, "instance '" + r.instanceId + "': " + label + " " + why,
                    r.instanceId, label);
        ok = false;
        continue;
      }
      ok = bindValue(r, *option, given.value, given.where, r.instanceFile, out, diags) && ok;
    }
  }
  for (const auto& option : declared) {
    if (out.statics.count(option.name) || out.textures.count(option.name)) continue;
    if (r.instance && std::any_of(r.instance->options.begin(), r.instance->options.end(),
                                  [&](const NodeOption& o) { return o.name == option.name; }))
      continue;  // given, and refused above
    const std::string label = "option '" + option.name + "'";
    if (option.defaultValue.is_null()) {
      if (r.instance)
        diags.error(DiagCode::InstanceOptionMissing, r.instance->where,
                    "instance '" + r.instanceId + "' of '" + r.instance->type + "' does not set " + label +
                        ", which its interface declares without a default",
                    r.instanceId, label);
      else
        diags.error(DiagCode::InstanceOptionMissing, option.where,
                    label + " has no default, so the graph cannot be compiled on its own: give it a \"default\" "
                            "(each instance sets it)",
                    "", label);
      ok = false;
      continue;
    }
    // A default was checked by the loader against the declaration; its texture is
    // relative to the function graph's own file.
    ok = bindValue(r, option, option.defaultValue, option.defaultWhere, r.interfaceFile, out, diags) && ok;
  }
  if (!ok) return std::nullopt;
  return out;
}

std::optional<std::string_view> interfaceTextureReference(const json& optionValue) {
  if (!optionValue.is_string()) return std::nullopt;
  const auto& s = optionValue.get_ref<const std::string&>();
  if (s.size() < 2 || s[0] != '$' || !isIdentifier(std::string_view(s).substr(1))) return std::nullopt;
  return std::string_view(s).substr(1);
}

}  // namespace wg
