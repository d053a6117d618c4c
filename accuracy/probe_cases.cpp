#include "accuracy/probe_cases.h"

#include "core/file_read.h"
#include "core/load_limits.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/json_source.h"

namespace wg::accuracy {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Reads the values of one cases file, reporting at the JSON position of each problem.
class CaseReader {
 public:
  CaseReader(const JsonSource& src, Diagnostics& diags) : src_(src), diags_(diags) {}

  bool ok() const { return ok_; }

  void error(const std::string& pointer, const std::string& message, bool atKey = false) {
    SourceRef where = atKey ? src_.key(pointer) : src_.value(pointer);
    diags_.error(DiagCode::InvalidProbeCases, where, message);
    ok_ = false;
  }

  // A number, or "inf" / "-inf".
  std::optional<double> number(const nlohmann::json& v, const std::string& pointer, const std::string& what) {
    if (v.is_number()) return v.get<double>();
    if (v.is_string() && v.get<std::string>() == "inf") return kInf;
    if (v.is_string() && v.get<std::string>() == "-inf") return -kInf;
    error(pointer, what + " must be a number (or \"inf\", \"-inf\")");
    return std::nullopt;
  }

  // `count` numbers (a single number for count 1).
  std::optional<Value> vector(const nlohmann::json& v, const std::string& pointer, const std::string& what, int count) {
    if (count == 1 && !v.is_array()) {
      auto x = number(v, pointer, what);
      if (!x) return std::nullopt;
      return Value::scalar(*x);
    }
    if (!v.is_array() || static_cast<int>(v.size()) != count) {
      error(pointer, what + " must be " + (count == 1 ? "a number" : "an array of " + std::to_string(count) + " numbers"));
      return std::nullopt;
    }
    Value out = count == 16 ? Value::ofType(Type::Mat4) : Value::ofType(count == 2 ? Type::Vec2 : count == 3 ? Type::Vec3 : Type::Vec4);
    for (int i = 0; i < count; ++i) {
      auto x = number(v[static_cast<size_t>(i)], pointer + "/" + std::to_string(i), what + " component " + std::to_string(i));
      if (!x) return std::nullopt;
      out[i] = *x;
    }
    return out;
  }

  // A parameter value: a number or 2..4 numbers.
  std::optional<Value> anyVector(const nlohmann::json& v, const std::string& pointer, const std::string& what) {
    if (v.is_array() && v.size() >= 2 && v.size() <= 4) return vector(v, pointer, what, static_cast<int>(v.size()));
    if (v.is_array()) {
      error(pointer, what + " must be a number or 2 to 4 numbers");
      return std::nullopt;
    }
    return vector(v, pointer, what, 1);
  }

  bool object(const nlohmann::json& v, const std::string& pointer, const std::string& what) {
    if (v.is_object()) return true;
    error(pointer, what + " must be an object");
    return false;
  }

  void unknownKeys(const nlohmann::json& obj, const std::string& pointer, const std::set<std::string>& known,
                   const std::string& where) {
    for (auto it = obj.begin(); it != obj.end(); ++it)
      if (!known.count(it.key())) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        error(pointer + "/" + jsonPointerEscape(it.key()), "unknown key '" + it.key() + "' in " + where + " (known: " + list + ")",
              true);
      }
  }

 private:
  const JsonSource& src_;
  Diagnostics& diags_;
  bool ok_ = true;
};

Value normalized(const Value& v) {
  double len = 0;
  for (int i = 0; i < v.size(); ++i) len += v[i] * v[i];
  len = std::sqrt(len);
  Value out = v;
  if (len > 0)
    for (int i = 0; i < v.size(); ++i) out[i] = v[i] / len;
  return out;
}

Value sub3(const Value& a, const Value& b) { return Value::vector({a[0] - b[0], a[1] - b[1], a[2] - b[2]}); }

}  // namespace

Value toFloat32(const Value& v) {
  Value out = v;
  for (int i = 0; i < v.size(); ++i) out[i] = static_cast<double>(static_cast<float>(v[i]));
  return out;
}

Value lookAtMatrix(const Value& eye, const Value& target) {
  Value f = normalized(sub3(target, eye));
  // Up is +y unless the camera looks straight up or down; then +z keeps the basis valid.
  Value up = std::abs(f[1]) > 0.999999 ? Value::vector({0, 0, 1}) : Value::vector({0, 1, 0});
  Value s = normalized(Value::vector({f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]}));
  Value u = Value::vector({s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]});
  Value m = Value::ofType(Type::Mat4);
  // Column-major: m[col * 4 + row].
  for (int i = 0; i < 3; ++i) {
    m[i * 4 + 0] = s[i];
    m[i * 4 + 1] = u[i];
    m[i * 4 + 2] = -f[i];
  }
  m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
  m[15] = 1;
  return m;
}

Value perspectiveMatrix(double fovYDegrees, double aspect, double nearPlane, double farPlane) {
  double t = 1.0 / std::tan(fovYDegrees * 3.14159265358979323846 / 360.0);
  Value m = Value::ofType(Type::Mat4);
  m[0] = t / aspect;
  m[5] = t;
  m[11] = -1;
  if (std::isinf(farPlane)) {
    m[10] = -1;
    m[14] = -2 * nearPlane;
  } else {
    m[10] = -(farPlane + nearPlane) / (farPlane - nearPlane);
    m[14] = -2 * farPlane * nearPlane / (farPlane - nearPlane);
  }
  return m;
}

EvalEnvironment defaultProbeEnvironment() {
  EvalEnvironment env;
  env.view = lookAtMatrix(env.cameraPosition, Value::vector({0, 0, -10}));
  env.projection = perspectiveMatrix(55, 16.0 / 9.0, env.cameraNearFar[0], env.cameraNearFar[1]);
  return env;
}

std::optional<ProbeCaseFile> parseProbeCases(const std::string& text, const std::string& file, Diagnostics& diags) {
  auto src = parseJsonWithPositions(text, file, diags);
  if (!src) return std::nullopt;
  CaseReader r(*src, diags);
  const nlohmann::json& root = src->root;
  if (!r.object(root, "", "a probe cases file")) return std::nullopt;
  r.unknownKeys(root, "", {"cases", "description", "tolerance"}, "the cases file");
  ProbeCaseFile out;
  out.file = file;
  if (root.contains("tolerance")) {
    auto t = r.number(root["tolerance"], "/tolerance", "\"tolerance\"");
    if (t && !(*t >= 0)) r.error("/tolerance", "\"tolerance\" must not be negative");
    out.tolerance = t;
  }
  if (!root.contains("cases") || !root["cases"].is_array() || root["cases"].empty()) {
    r.error(root.contains("cases") ? "/cases" : "", "a cases file needs \"cases\": a non-empty array of case objects");
    return std::nullopt;
  }
  std::set<std::string> names;
  const auto& cases = root["cases"];
  for (size_t i = 0; i < cases.size(); ++i) {
    std::string p = "/cases/" + std::to_string(i);
    const auto& c = cases[i];
    if (!r.object(c, p, "a case")) continue;
    r.unknownKeys(c, p,
                  {"name", "expect", "region", "uv", "uv_dx", "uv_dy", "world_position", "normal", "view_direction", "camera_position", "time",
                   "screen_uv", "frag_depth", "near_far", "sun_direction", "view", "projection", "camera", "scene", "parameters", "range",
                   "tolerance", "inputs", "options", "ranges", "nodes"},
                  "a case");
    ProbeCase pc;
    pc.where = src->value(p);
    pc.env = defaultProbeEnvironment();
    if (!c.contains("name") || !c["name"].is_string() || c["name"].get<std::string>().empty()) {
      r.error(c.contains("name") ? p + "/name" : p, "a case needs \"name\": a non-empty string");
    } else {
      pc.name = c["name"].get<std::string>();
      // The name is printed in every report line: a newline or an escape sequence in it
      // would forge lines or colour the terminal.
      if (std::any_of(pc.name.begin(), pc.name.end(), [](char ch) { return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f; }))
        r.error(p + "/name", "a case name may not hold a control character");
      else if (!names.insert(pc.name).second)
        r.error(p + "/name", "a second case named '" + pc.name + "'");
    }
    if (c.contains("expect")) {
      if (c["expect"].is_string()) pc.expect = c["expect"].get<std::string>();
      else r.error(p + "/expect", "\"expect\" must be a string");
    }
    if (c.contains("region")) {
      if (c["region"].is_string() && !c["region"].get<std::string>().empty()) pc.region = c["region"].get<std::string>();
      else r.error(p + "/region", "\"region\" must be a non-empty string");
    }
    EvalEnvironment& env = pc.env;
    bool derivesView = false;
    if (c.contains("camera") && r.object(c["camera"], p + "/camera", "\"camera\"")) {
      const auto& cam = c["camera"];
      std::string cp = p + "/camera";
      r.unknownKeys(cam, cp, {"position", "target", "fov", "near", "far", "aspect"}, "\"camera\"");
      Value pos = env.cameraPosition, target = Value::vector({0, 0, 0});
      double fov = 55, nearPlane = 0.1, farPlane = 100, aspect = 16.0 / 9.0;
      if (cam.contains("position"))
        if (auto v = r.vector(cam["position"], cp + "/position", "camera position", 3)) pos = *v;
      if (cam.contains("target"))
        if (auto v = r.vector(cam["target"], cp + "/target", "camera target", 3)) target = *v;
      if (cam.contains("fov"))
        if (auto v = r.number(cam["fov"], cp + "/fov", "camera fov")) fov = *v;
      if (cam.contains("near"))
        if (auto v = r.number(cam["near"], cp + "/near", "camera near")) nearPlane = *v;
      if (cam.contains("far"))
        if (auto v = r.number(cam["far"], cp + "/far", "camera far")) farPlane = *v;
      if (cam.contains("aspect"))
        if (auto v = r.number(cam["aspect"], cp + "/aspect", "camera aspect")) aspect = *v;
      if (!(fov > 0 && fov < 180)) r.error(cp, "camera fov must be between 0 and 180 degrees");
      if (!(nearPlane > 0 && farPlane > nearPlane)) r.error(cp, "camera needs 0 < near < far");
      if (!(aspect > 0) || std::isinf(aspect)) r.error(cp, "camera aspect must be positive");
      env.cameraPosition = pos;
      env.view = lookAtMatrix(pos, target);
      env.projection = perspectiveMatrix(fov, aspect, nearPlane, farPlane);
      env.cameraNearFar = Value::vector({nearPlane, farPlane});
      derivesView = true;
      pc.given.insert("camera");
    }
    struct Field {
      const char* key;
      Value* target;
      int count;
    };
    const Field fields[] = {{"uv", &env.uv, 2},
                            {"uv_dx", &env.uvDx, 2},
                            {"uv_dy", &env.uvDy, 2},
                            {"world_position", &env.worldPosition, 3},
                            {"normal", &env.normal, 3},
                            {"view_direction", &env.viewDirection, 3},
                            {"camera_position", &env.cameraPosition, 3},
                            {"time", &env.time, 1},
                            {"screen_uv", &env.screenUv, 2},
                            {"frag_depth", &env.fragDepth, 1},
                            {"near_far", &env.cameraNearFar, 2},
                            {"view", &env.view, 16},
                            {"projection", &env.projection, 16},
                            {"sun_direction", &env.sunDirection, 3},
                            {"pixel_angle", &env.pixelAngle, 1}};
    for (const auto& f : fields) {
      if (!c.contains(f.key)) continue;
      if (auto v = r.vector(c[f.key], p + "/" + f.key, std::string("\"") + f.key + "\"", f.count)) *f.target = *v;
      std::string key = f.key;
      pc.given.insert(key);
      derivesView |= key == "camera_position" || key == "world_position";
    }
    // The view direction follows the camera and the surface point unless given.
    if (derivesView && !c.contains("view_direction"))
      env.viewDirection = normalized(sub3(env.cameraPosition, env.worldPosition));
    if (c.contains("scene") && r.object(c["scene"], p + "/scene", "\"scene\"")) {
      const auto& s = c["scene"];
      std::string sp = p + "/scene";
      r.unknownKeys(s, sp, {"depth", "color", "reflection", "refraction", "environment"}, "\"scene\"");
      const Field sceneFields[] = {{"depth", &env.sceneDepth, 1},
                                   {"color", &env.sceneColor, 3},
                                   {"reflection", &env.reflectionColor, 3},
                                   {"refraction", &env.refractionColor, 3},
                                   {"environment", &env.environmentColor, 3}};
      for (const auto& f : sceneFields)
        if (s.contains(f.key)) {
          pc.given.insert(std::string("scene.") + f.key);
          if (auto v = r.vector(s[f.key], sp + "/" + f.key, std::string("scene \"") + f.key + "\"", f.count)) *f.target = *v;
        }
    }
    if (c.contains("parameters") && r.object(c["parameters"], p + "/parameters", "\"parameters\"")) {
      const auto& ps = c["parameters"];
      for (auto it = ps.begin(); it != ps.end(); ++it)
        if (auto v = r.anyVector(it.value(), p + "/parameters/" + jsonPointerEscape(it.key()), "parameter '" + it.key() + "'"))
          pc.parameters.emplace_back(it.key(), toFloat32(*v));
    }
    if (c.contains("inputs") && r.object(c["inputs"], p + "/inputs", "\"inputs\"")) {
      const auto& ins = c["inputs"];
      for (auto it = ins.begin(); it != ins.end(); ++it)
        if (auto v = r.anyVector(it.value(), p + "/inputs/" + jsonPointerEscape(it.key()), "input '" + it.key() + "'"))
          pc.inputs.emplace_back(it.key(), toFloat32(*v));
    }
    if (c.contains("options") && r.object(c["options"], p + "/options", "\"options\"")) {
      for (auto it = c["options"].begin(); it != c["options"].end(); ++it)
        r.object(it.value(), p + "/options/" + jsonPointerEscape(it.key()), "the options for node type '" + it.key() + "'");
      pc.options = c["options"];
    }
    if (c.contains("ranges") && r.object(c["ranges"], p + "/ranges", "\"ranges\"")) {
      for (auto it = c["ranges"].begin(); it != c["ranges"].end(); ++it) {
        std::string rp = p + "/ranges/" + jsonPointerEscape(it.key());
        auto v = r.vector(it.value(), rp, "range '" + it.key() + "'", 2);
        if (v && !((*v)[0] <= (*v)[1])) r.error(rp, "a range must be [lo, hi] with lo <= hi");
        else if (v) pc.ranges[it.key()] = {(*v)[0], (*v)[1]};
      }
    }
    if (c.contains("nodes")) {
      bool ok = c["nodes"].is_array();
      if (ok)
        for (const auto& n : c["nodes"]) ok &= n.is_string();
      if (!ok) r.error(p + "/nodes", "\"nodes\" must be an array of node type names");
      else
        for (const auto& n : c["nodes"]) pc.nodes.push_back(n.get<std::string>());
    }
    if (c.contains("range")) {
      auto v = r.vector(c["range"], p + "/range", "\"range\"", 2);
      if (v && !((*v)[0] <= (*v)[1])) r.error(p + "/range", "\"range\" must be [lo, hi] with lo <= hi");
      else if (v) pc.range = std::make_pair((*v)[0], (*v)[1]);
    }
    if (c.contains("tolerance")) {
      auto t = r.number(c["tolerance"], p + "/tolerance", "\"tolerance\"");
      if (t && !(*t >= 0)) r.error(p + "/tolerance", "\"tolerance\" must not be negative");
      pc.tolerance = t;
    }
    // What the GPU sees is float32; the reference gets the same inputs.
    for (Value* v : {&env.uv, &env.uvDx, &env.uvDy, &env.worldPosition, &env.normal, &env.viewDirection, &env.cameraPosition, &env.time,
                     &env.screenUv, &env.fragDepth, &env.cameraNearFar, &env.view, &env.projection, &env.sunDirection, &env.pixelAngle, &env.sceneDepth,
                     &env.sceneColor, &env.reflectionColor, &env.refractionColor, &env.environmentColor})
      *v = toFloat32(*v);
    out.cases.push_back(std::move(pc));
  }
  if (!r.ok()) return std::nullopt;
  return out;
}

std::optional<ProbeCaseFile> loadProbeCases(const std::string& path, Diagnostics& diags) {
  FileReadRule rule;
  rule.maxBytes = kMaxFileBytes;
  FileReadFailure failure;
  auto file = readFileChecked(path, rule, &failure);  // one open, one read (core/file_read.h)
  if (!file) {
    diags.error(DiagCode::FileRead, SourceRef{path, 0, 0}, "cannot read the cases file: " + failure.why());
    return std::nullopt;
  }
  return parseProbeCases(file->bytes, path, diags);
}

}  // namespace wg::accuracy
