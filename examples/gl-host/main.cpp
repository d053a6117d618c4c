// gl_host: draws a graph compiled by watergraph in a host of its own, from the files alone:
//
//   watergraph compile water.json -o out --target glsl330 --textures
//   watergraph scene -o out/scene.json
//   gl_host out/water.manifest.json out/scene.json --camera above --time 3.5 -o water.png
//
// The water is drawn over black (as `watergraph render --scene none`) into an RGBA16F frame
// of linear radiance; the output transform is the simplest one: clamp to [0, 1] and the
// sRGB curve (`render --tonemap none --exposure 0`). See README.md and docs/integration.md.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "water_draw.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "gl_host: %s\n", message.c_str());
  return 1;
}

glm::vec3 vec3Of(const nlohmann::json& j) { return {j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()}; }

// IEC 61966-2-1: linear [0, 1] to the sRGB encoding, 8 bits.
unsigned char srgbByte(float linear) {
  float x = std::isnan(linear) ? 0.0f : std::fmin(std::fmax(linear, 0.0f), 1.0f);
  double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(encoded * 255));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return fail("usage: gl_host GRAPH.manifest.json scene.json [--camera NAME] [--time S] [--size WxH] -o OUT.png");
  const std::string manifestPath = argv[1], scenePath = argv[2];
  std::string camera = "above", output;
  double time = 3.5;
  int width = 640, height = 360;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--camera") camera = value;
    else if (flag == "--time") time = std::strtod(value.c_str(), nullptr);
    else if (flag == "--size" && std::sscanf(value.c_str(), "%dx%d", &width, &height) == 2) continue;
    else if (flag == "-o") output = value;
    else return fail("unknown argument " + flag);
  }
  if (output.empty() || width < 1 || height < 1 || width > 8192 || height > 8192) return fail("give -o OUT.png and a size within 8192x8192");

  // The scene `watergraph scene` describes: the camera presets, the sun, the water grid.
  std::ifstream sceneFile(scenePath);
  const nlohmann::json scene = nlohmann::json::parse(sceneFile, nullptr, false);
  if (scene.is_discarded() || !scene.contains("cameras")) return fail(scenePath + ": not a scene file (watergraph scene -o)");
  if (!scene["cameras"].contains(camera)) return fail(scenePath + " has no camera '" + camera + "'");
  const auto& c = scene["cameras"][camera];
  DrawState state;
  state.camera = {vec3Of(c.at("position")), vec3Of(c.at("target")), vec3Of(c.at("up")), c.at("fov_y_degrees").get<float>(),
                  c.at("near").get<float>(), c.at("far").get<float>()};
  state.sunDirection = vec3Of(scene.at("sun_direction"));
  state.time = time;
  state.width = width;
  state.height = height;

  std::string why;
  Frame frame;
  if (!createHeadlessContext(why) || !createFrame(width, height, frame, why)) return fail(why);
  WaterDraw water;
  if (!water.load(manifestPath, scene["water"].at("grid_quads").get<int>(), scene["water"].at("half_size").get<float>(), why))
    return fail(why);
  const auto& clear = scene.at("clear_color");
  glClearColor(clear[0].get<float>(), clear[1].get<float>(), clear[2].get<float>(), clear[3].get<float>());
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  water.draw(state);
  if (glGetError() != GL_NO_ERROR) return fail("OpenGL reported an error while drawing");

  // The output transform, last: linear radiance to 8-bit sRGB. GL's row 0 is the bottom.
  std::vector<float> linear(static_cast<size_t>(width) * height * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, linear.data());
  std::vector<unsigned char> png(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* in = &linear[(static_cast<size_t>(height - 1 - y) * width + x) * 4];
      unsigned char* out = &png[(static_cast<size_t>(y) * width + x) * 4];
      for (int k = 0; k < 3; ++k) out[k] = srgbByte(in[k]);
      out[3] = 255;
    }
  if (!stbi_write_png(output.c_str(), width, height, 4, png.data(), width * 4)) return fail(output + ": cannot be written");
  std::printf("wrote %s (%dx%d, camera %s, t = %g s)\n", output.c_str(), width, height, camera.c_str(), time);
  return 0;
}
