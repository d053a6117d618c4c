// Reads what watergraph generated at build time (see CMakeLists.txt) and prints what a
// renderer needs to draw it, all from the manifest: each target's shader files with their
// size and #version line; every uniform with what sets it (a graph parameter: its value and
// range, which PRESET may have changed; a builtin: what the renderer computes before each
// draw); and the node textures to upload, each a PNG beside the manifest (TEXTURES).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

bool readFile(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

// A number or a list of numbers, as "0.6 0.75 0.9".
std::string numbers(const nlohmann::json& v) {
  std::string s;
  for (const auto& x : v.is_array() ? v : nlohmann::json::array({v})) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x.get<double>());
    s += (s.empty() ? "" : " ") + std::string(text);
  }
  return s;
}

}  // namespace

int main() {
  const std::string dir = POND_SHADER_DIR;
  std::string text;
  if (!readFile(dir + "/pond.manifest.json", text)) {
    std::cerr << "pond_info: missing " << dir << "/pond.manifest.json\n";
    return 1;
  }
  const nlohmann::json manifest = nlohmann::json::parse(text, nullptr, false);
  if (manifest.is_discarded()) {
    std::cerr << "pond_info: " << dir << "/pond.manifest.json is not JSON\n";
    return 1;
  }
  int missing = 0;
  // "targets": {"glsl330": {"vert": "pond.glsl330.vert", "frag": ...}, "es300": ...}
  for (const auto& [target, files] : manifest.at("targets").items())
    for (const auto& [stage, file] : files.items()) {
      std::string shader;
      if (!readFile(dir + "/" + file.get<std::string>(), shader) || shader.empty()) {
        std::cerr << "pond_info: missing " << dir << "/" << file.get<std::string>() << "\n";
        ++missing;
        continue;
      }
      std::cout << file.get<std::string>() << ": " << shader.size() << " bytes, " << shader.substr(0, shader.find('\n'))
                << "\n";
    }
  for (const auto& u : manifest.at("uniforms")) {
    std::cout << "uniform " << u.at("name").get<std::string>() << " (" << u.at("type").get<std::string>() << "): ";
    if (u.contains("parameter")) {
      // The renderer uploads the value the user chose, clamped into [min, max]; the shader
      // may rely on the range.
      std::cout << "parameter " << u.at("parameter").get<std::string>() << " = " << numbers(u.at("default"));
      if (u.contains("min") || u.contains("max"))
        std::cout << " in [" << (u.contains("min") ? numbers(u["min"]) : "-inf") << ", "
                  << (u.contains("max") ? numbers(u["max"]) : "inf") << "]";
      if (u.value("color_space", "") == "srgb") std::cout << ", an sRGB colour";
      std::cout << "\n";
    } else {
      std::cout << "builtin " << u.at("builtin").get<std::string>() << ", set by the renderer before each draw\n";
    }
  }
  for (const auto& t : manifest.value("textures", nlohmann::json::array())) {
    if (!t.contains("file")) continue;  // a scene texture: a render target of the renderer's own passes
    const std::string file = t.at("file").get<std::string>();
    std::string png;
    if (!readFile(dir + "/" + file, png) || png.compare(0, 4, "\x89PNG") != 0) {
      std::cerr << "pond_info: missing texture " << dir << "/" << file << "\n";
      ++missing;
      continue;
    }
    std::cout << "texture " << t.at("name").get<std::string>() << " at binding " << t.at("binding").get<int>() << ": " << file
              << ", " << png.size() << " bytes\n";
  }
  return missing ? 1 : 0;
}
