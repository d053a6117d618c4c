#pragma once
// Executes one compiled graph in the built-in scene: plans the passes from the manifest,
// creates only the render targets those passes need, and renders frames into an
// offscreen framebuffer that can be read back: for pictures, linear radiance in RGBA16F
// targets and the output transform (core/view_transform.h) into an RGBA8 display image;
// for accuracy work, RGBA32F targets read back as they are, linear. A GL context (EglContext, or the editor's GlfwContext) whose API matches the
// shaders' target must be current.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "codegen/manifest.h"
#include "core/view_transform.h"
#include "runtime/gl_resources.h"
#include "runtime/pass_plan.h"
#include "runtime/scene.h"

namespace wg::rt {

class GpuCache;
class OceanSimulation;

struct RenderSettings {
  int width = 1280, height = 720;
  std::string camera = "above";  // a camera preset name (scene.h)
  std::optional<Camera> customCamera;  // when set, used instead of the preset (accuracy sweeps)
  SceneOptions scene;
  bool floatColor = false;       // RGBA32F colour targets and no output transform (accuracy work)
  ViewTransform view;            // exposure and tone mapper of the output transform
  // Only for measuring the colour pipeline's cost (PlanOptions): RGBA8 targets, no transform.
  ColorFormat pictureFormat = ColorFormat::Rgba16f;
  bool outputTransform = true;
  int environmentSize = 128;     // cube map face size for environment_cubemap
  // Quads per side of the 40 x 40 m water grid: 128 gives 0.31 m spacing (6+ vertices per
  // wavelength for waves of 2 m and longer). On llvmpipe triangle setup runs on one
  // thread: at 1280x720 the 128 grid costs ~15 CPU-ms a frame, 256 ~52.
  int waterGridQuads = 128;
  // Planar reflection clipped by an oblique near plane on the water (the stylized water shader) instead of
  // a user clip plane (the classic WebGL water renderer's gl_ClipDistance; discard on ES).
  bool obliqueReflection = false;
  // Frames that follow one another in time (a preview, an animation): the spectral ocean's
  // foam continues the previous frame's steps instead of replaying its history for each
  // frame (runtime/ocean_gpu_foam.h, FoamHistory). Off, a frame depends on its time alone.
  bool animation = false;
};

// A frame read back: rows top to bottom, 4 channels.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba8;    // filled by readRgba8
  std::vector<float> rgba32f;    // filled by readRgba32f
};

// Where a node texture named in the manifest ("source") comes from, for loading it and for
// errors that name the node: `owner` reads "lake.json:12:5: node 'foam'".
struct TextureOrigin {
  std::string graphDir;  // folder a relative .png path is resolved against
  std::string owner;
};

class Renderer {
 public:
  // `water` are the compiled shaders of one target (vertex and fragment), `manifest` the
  // compile's (CompileResult::manifest in the same process; Manifest::fromJson of a
  // manifest file). Throws RuntimeError: Manifest for passes, attributes, uniforms or
  // textures the runtime cannot provide; Driver when the GL driver rejects a shader or a
  // target is incomplete.
  // Node textures are loaded through wg::loadTexture (builtin:* or a PNG); `origins` maps
  // each manifest texture "source" to where it came from (missing: current folder).
  // With a `cache` (used only while constructing), programs whose texts it has linked
  // before and node textures it has uploaded are taken from it, not made again: an editor
  // rebuilding the Renderer after each edit keeps the scene's programs, and the water's
  // when only parameter values changed, with their machine code.
  // With `oceans` (another Renderer's oceanSimulation() for a manifest of the same
  // oceans and ocean maps: check's frames and its read-back frames), the two share one
  // simulation, which runs once per time for both; else the Renderer makes its own.
  Renderer(const Manifest& manifest, std::vector<ShaderSource> water, const RenderSettings& settings, bool es,
           const std::map<std::string, TextureOrigin>& origins = {}, GpuCache* cache = nullptr,
           std::shared_ptr<OceanSimulation> oceans = nullptr);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Runs every planned pass in order and waits for the GPU (glFinish). Returns the wall
  // time in milliseconds measured on the CPU around the frame and the glFinish.
  double renderFrame();

  Image readRgba8() const;     // the displayed image, after the output transform (not with floatColor)
  Image readRgba32f() const;   // the frame's linear radiance: RGBA32F with floatColor, else RGBA16F values
  // The frame's depth-buffer values, rows top to bottom. Desktop GL only (OpenGL ES cannot
  // read depth back): throws RuntimeError(Kind::Manifest) on ES.
  std::vector<float> readDepth() const;

  // Between frames (the editor): a free camera, the time and sun, and a new value for a
  // graph parameter that is a uniform. setParameter returns false when the parameter is
  // not a uniform of this compile (static, pruned) or the value has the wrong size; then
  // only a recompile can show the change.
  void setCamera(const Camera& camera);
  void setScene(const SceneOptions& scene);
  bool setParameter(const std::string& parameter, const std::vector<float>& value);
  // The displayed image's texture (RGBA8, sRGB-encoded; the linear RGBA32F frame with
  // floatColor), rows bottom-up, for showing it in a UI.
  GLuint frameTexture() const;
  // A new exposure or tone mapper for the next frames (the editor's view controls).
  void setView(const ViewTransform& view);
  // Whether the next frames follow one another in time (RenderSettings::animation): `tune`
  // times a configuration's frames as an animation and compares its still frames.
  void setAnimation(bool animation);

  const PassPlan& plan() const;
  // Whether the scene texture bound to `s` is sampled nearest (runtime/pass_plan.h); the
  // plan must create it.
  bool samplesNearest(SceneSampler s) const;
  int createdTargetCount() const;     // GL render targets actually allocated
  size_t createdTargetBytes() const;  // their image memory
  const RenderSettings& settings() const;
  // The spectral oceans' simulation (null when the manifest lists no ocean_simulation pass).
  std::shared_ptr<OceanSimulation> oceanSimulation() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wg::rt
