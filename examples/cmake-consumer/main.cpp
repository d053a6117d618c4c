// Reads the shaders watergraph generated at build time (see CMakeLists.txt) and prints what
// a renderer would load: each file's size and #version line, the manifest's uniforms, the
// node textures it names, and
// the derived uniforms it would set before each draw, computed by the generated
// pond.derived.h (the c-header target).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "pond.derived.h"

namespace {

bool readFile(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

}  // namespace

int main() {
  const std::string dir = POND_SHADER_DIR;
  int missing = 0;
  for (const char* name : {"pond.glsl330.vert", "pond.glsl330.frag", "pond.es300.vert", "pond.es300.frag"}) {
    std::string text;
    if (!readFile(dir + "/" + name, text) || text.empty()) {
      std::cerr << "pond_info: missing " << dir << "/" << name << "\n";
      ++missing;
      continue;
    }
    std::cout << name << ": " << text.size() << " bytes, " << text.substr(0, text.find('\n')) << "\n";
  }
  std::string manifest;
  if (!readFile(dir + "/pond.manifest.json", manifest)) {
    std::cerr << "pond_info: missing " << dir << "/pond.manifest.json\n";
    return 1;
  }
  // A real program would parse the JSON; this one only lists the parameter uniforms.
  for (size_t at = manifest.find("\"name\": \"p_"); at != std::string::npos; at = manifest.find("\"name\": \"p_", at + 1)) {
    size_t start = at + 9, end = manifest.find('"', start);
    std::cout << "uniform " << manifest.substr(start, end - start) << "\n";
  }
  // The node textures to upload (TEXTURES): each manifest texture with a "file", beside it.
  for (size_t at = manifest.find("\"file\": \""); at != std::string::npos; at = manifest.find("\"file\": \"", at + 1)) {
    size_t start = at + 9, end = manifest.find('"', start);
    const std::string file = manifest.substr(start, end - start);
    std::string png;
    if (!readFile(dir + "/" + file, png) || png.compare(0, 4, "\x89PNG") != 0) {
      std::cerr << "pond_info: missing texture " << dir << "/" << file << "\n";
      ++missing;
      continue;
    }
    std::cout << "texture " << file << ": " << png.size() << " bytes\n";
  }
  // The shimmering sky colour is the same for every pixel of a draw: the shader reads it as
  // u_derived0, and the renderer computes it once per draw, here at t = 2 s.
  wg_pond_parameters parameters;
  wg_pond_default_parameters(&parameters);
  wg_pond_draw draw{};
  draw.time = 2.0;
  wg_pond_derived derived;
  wg_pond_compute_derived(&parameters, &draw, &derived);
  std::printf("u_derived0 at t = 2 s: %.6f %.6f %.6f\n", derived.u_derived0[0], derived.u_derived0[1],
              derived.u_derived0[2]);
  return missing ? 1 : 0;
}
