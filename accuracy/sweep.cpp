#include "accuracy/sweep.h"

#include <cmath>
#include <cstdio>

#include "accuracy/number_text.h"

namespace wg::accuracy {
namespace {

Value* builtinField(EvalEnvironment& env, const std::string& key) {
  if (key == "uv") return &env.uv;
  if (key == "world_position") return &env.worldPosition;
  if (key == "normal") return &env.normal;
  if (key == "view_direction") return &env.viewDirection;
  if (key == "camera_position") return &env.cameraPosition;
  if (key == "time") return &env.time;
  if (key == "screen_uv") return &env.screenUv;
  if (key == "frag_depth") return &env.fragDepth;
  if (key == "near_far") return &env.cameraNearFar;
  if (key == "sun_direction") return &env.sunDirection;
  return nullptr;
}

}  // namespace

bool isSweepBuiltinKey(const std::string& key) {
  EvalEnvironment env;
  return builtinField(env, key) != nullptr;
}

namespace {

void setInput(ProbeCase& c, const std::string& port, const Value& v) {
  for (auto& [name, value] : c.inputs)
    if (name == port) {
      value = v;
      return;
    }
  c.inputs.emplace_back(port, v);
}

Value inputOrDefault(const NodePorts& ports, const ProbeCase& c, int port) {
  for (const auto& [name, value] : c.inputs)
    if (name == ports.inputs[static_cast<size_t>(port)].name) return value;
  const PortSpec& p = ports.inputs[static_cast<size_t>(port)];
  if (p.defaultValue) return *p.defaultValue;
  if (p.defaultBuiltin) return c.env.builtin(*p.defaultBuiltin);
  return Value::ofType(p.type == Type::Invalid ? Type::Float : p.type);
}

}  // namespace

std::optional<SweepAxis> parseSweepAxis(const std::string& text, std::string& error) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == ':') {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  if (parts.size() != 4 || parts[0].empty()) {
    error = "--sweep must be NAME[.x|.y|.z|.w]:FROM:TO:COUNT (got '" + text + "')";
    return std::nullopt;
  }
  SweepAxis a;
  a.name = parts[0];
  if (auto dot = a.name.find('.'); dot != std::string::npos) {
    std::string c = a.name.substr(dot + 1);
    a.name = a.name.substr(0, dot);
    if (c.size() != 1 || std::string("xyzw").find(c[0]) == std::string::npos) {
      error = "--sweep: component must be x, y, z or w (got '" + c + "')";
      return std::nullopt;
    }
    a.component = static_cast<int>(std::string("xyzw").find(c[0]));
  }
  try {
    size_t n1 = 0, n2 = 0, n3 = 0;
    a.from = std::stod(parts[1], &n1);
    a.to = std::stod(parts[2], &n2);
    long count = std::stol(parts[3], &n3);
    if (n1 != parts[1].size() || n2 != parts[2].size() || n3 != parts[3].size() || count < 1 || count > 10000000)
      throw std::invalid_argument("");
    a.count = static_cast<int>(count);
  } catch (const std::exception&) {
    error = "--sweep: FROM and TO must be numbers and COUNT a whole number from 1 (got '" + text + "')";
    return std::nullopt;
  }
  if (!std::isfinite(a.from) || !std::isfinite(a.to)) {
    error = "--sweep: FROM and TO must be finite";
    return std::nullopt;
  }
  return a;
}

std::vector<ProbeCase> sweepCases(const NodePorts& ports, const SweepAxis& axis, const ProbeCase& base) {
  std::vector<ProbeCase> out;
  out.reserve(static_cast<size_t>(axis.count));
  int port = ports.inputIndex(axis.name);
  for (int i = 0; i < axis.count; ++i) {
    double x = axis.at(i);
    ProbeCase c = base;
    c.name = axis.name + (axis.component >= 0 ? std::string(".") + "xyzw"[axis.component] : "") + "=" + significantDigits(x, 9);
    if (axis.name == "angle") {
      double r = x * M_PI / 180.0;
      Value n = toFloat32(Value::vector({0, 1, 0})), v = toFloat32(Value::vector({std::sin(r), std::cos(r), 0}));
      c.env.normal = n;
      c.env.viewDirection = v;
      c.given.insert({"normal", "view_direction"});
      if (ports.inputIndex("normal") >= 0) setInput(c, "normal", n);
      if (ports.inputIndex("view") >= 0) setInput(c, "view", v);
    } else if (port >= 0) {
      Value v = inputOrDefault(ports, c, port);
      for (int k = 0; k < v.size(); ++k)
        if (axis.component < 0 || axis.component == k) v[k] = x;
      setInput(c, axis.name, toFloat32(v));
    } else if (Value* b = builtinField(c.env, axis.name)) {
      for (int k = 0; k < b->size(); ++k)
        if (axis.component < 0 || axis.component == k) (*b)[k] = x;
      *b = toFloat32(*b);
      c.given.insert(axis.name == "near_far" ? "near_far" : axis.name);
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::string sweepTable(const SweepAxis& axis, const ProbeReport& report) {
  std::string out = "# " + report.output + " on " + report.target + ": " + axis.name +
                    (axis.component >= 0 ? std::string(".") + "xyzw"[axis.component] : "") +
                    " gpu reference abs_error bound\n";
  for (size_t i = 0; i < report.cases.size(); ++i) {
    const ProbeCaseResult& c = report.cases[i];
    size_t k = 0;  // the component the report names (closest to its bound)
    for (int j = 0; j < c.components; ++j)
      if (std::abs(c.gpu[static_cast<size_t>(j)] - c.reference[static_cast<size_t>(j)]) == c.absError) k = static_cast<size_t>(j);
    for (double x : {axis.at(static_cast<int>(i)), c.gpu[k], c.reference[k], c.absError}) out += significantDigits(x, 9) + " ";
    out += significantDigits(c.bound, 9) + "\n";
  }
  return out;
}

}  // namespace wg::accuracy
