#pragma once
// Short constructors for the ports and options of a NodeSpec, so a node file reads as a
// declaration.
#include <functional>
#include <string>

#include "core/node_spec.h"

namespace wg::ports {

inline PortSpec fixed(std::string name, Type t, std::string doc) {
  PortSpec p;
  p.name = std::move(name);
  p.kind = PortKind::Fixed;
  p.type = t;
  p.doc = std::move(doc);
  return p;
}
inline PortSpec fixed(std::string name, Type t, Value def, std::string doc) {
  PortSpec p = fixed(std::move(name), t, std::move(doc));
  p.defaultValue = def;
  return p;
}
inline PortSpec fromBuiltin(std::string name, Type t, Builtin b, std::string doc) {
  PortSpec p = fixed(std::move(name), t, std::move(doc));
  p.defaultBuiltin = b;
  return p;
}
// An input the node computes itself, once per draw (PortSpec::derived, NodeSpec::derive).
inline PortSpec derived(std::string name, Type t, std::string doc) {
  PortSpec p = fixed(std::move(name), t, std::move(doc));
  p.derived = true;
  return p;
}
// A colour input (PortSpec::color): literals and the default are sRGB-authored.
inline PortSpec color(PortSpec p) {
  p.color = true;
  return p;
}
inline PortSpec gen(std::string name, std::string doc) {
  PortSpec p;
  p.name = std::move(name);
  p.kind = PortKind::Gen;
  p.doc = std::move(doc);
  return p;
}
inline PortSpec gen(std::string name, double def, std::string doc) {
  PortSpec p = gen(std::move(name), std::move(doc));
  p.defaultValue = Value::scalar(def);
  return p;
}
inline PortSpec custom(std::string name, std::string doc) {
  PortSpec p;
  p.name = std::move(name);
  p.kind = PortKind::Custom;
  p.doc = std::move(doc);
  return p;
}

inline OptionSpec choice(std::string name, std::vector<std::string> choices, std::string def, std::string doc) {
  OptionSpec o;
  o.name = std::move(name);
  o.kind = OptionSpec::Kind::Enum;
  o.choices = std::move(choices);
  o.defaultValue = std::move(def);
  o.doc = std::move(doc);
  return o;
}
inline OptionSpec number(std::string name, double def, double min, double max, std::string doc) {
  OptionSpec o;
  o.name = std::move(name);
  o.kind = OptionSpec::Kind::Number;
  o.defaultValue = def;
  o.min = min;
  o.max = max;
  o.doc = std::move(doc);
  return o;
}
inline OptionSpec flag(std::string name, bool def, std::string doc) {
  OptionSpec o;
  o.name = std::move(name);
  o.kind = OptionSpec::Kind::Bool;
  o.defaultValue = def;
  o.doc = std::move(doc);
  return o;
}

// A Texture option: "builtin:<name>" or a .png path relative to the graph.
inline OptionSpec texture(std::string name, std::string def, std::string doc) {
  OptionSpec o;
  o.name = std::move(name);
  o.kind = OptionSpec::Kind::Texture;
  o.defaultValue = std::move(def);
  o.doc = std::move(doc);
  return o;
}
// A Json or Text option that checks its own value: `validate` returns "" or why it is refused.
inline OptionSpec checked(OptionSpec::Kind kind, std::string name, nlohmann::json def,
                          std::function<std::string(const nlohmann::json&)> validate, std::string doc) {
  OptionSpec o;
  o.name = std::move(name);
  o.kind = kind;
  o.defaultValue = std::move(def);
  o.validate = std::move(validate);
  o.doc = std::move(doc);
  return o;
}
// An Integer option within [min, max] (quality levels, counts).
inline OptionSpec integer(std::string name, int def, int min, int max, std::string doc) {
  OptionSpec o;
  o.name = std::move(name);
  o.kind = OptionSpec::Kind::Integer;
  o.defaultValue = def;
  o.min = min;
  o.max = max;
  o.doc = std::move(doc);
  return o;
}

// Marks `o` a quality knob with `levels` from the cheapest to the most exact.
inline OptionSpec knob(OptionSpec o, std::vector<nlohmann::json> levels) {
  o.levels = std::move(levels);
  return o;
}

}  // namespace wg::ports
