// Reads the shaders watergraph generated at build time (see CMakeLists.txt) and prints what
// a renderer would load: each file's size and #version line, and the manifest's uniforms.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

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
  return missing ? 1 : 0;
}
