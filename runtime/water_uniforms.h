#pragma once
// The water shaders' uniforms from a manifest: graph parameters (their values kept here, so
// the editor can change them between frames without a recompile) and builtins recomputed
// from the camera, time and sun every frame (runtime/uniform_values.h), set in every water
// program that uses them.
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "codegen/manifest.h"
#include "core/value.h"
#include "runtime/gl_resources.h"
#include "runtime/uniform_values.h"

namespace wg::rt {

struct WaterUniform {
  std::string name, parameter;
  Type type = Type::Float;
  BuiltinUniform builtin = BuiltinUniform::Time;  // when parameter is ""
  double angularFrequency = 0;                    // time_phase
  std::vector<float> value;                       // parameter values
  // The parameter's manifest min/max: every value is clamped into them on upload, as the
  // generated shader may rely on the range (codegen/value_facts.h).
  float lo = -std::numeric_limits<float>::infinity(), hi = std::numeric_limits<float>::infinity();
  std::vector<std::pair<GLuint, GLint>> locations;  // (program, location) where it is used
};

class WaterUniforms {
 public:
  // Reads the manifest's uniforms and finds them in `programs`; sets each once with `frame`
  // so that a uniform the runtime cannot set is a manifest error now, not at the first frame.
  void setup(const Manifest& manifest, const std::vector<GLuint>& programs, const FrameValues& frame);
  // Every frame: the camera, time and sun may have changed since the last one.
  void apply(const FrameValues& frame) const;
  // A parameter's new value (clamped into its range); false when no uniform holds the
  // parameter or the value has the wrong size.
  bool setParameter(const std::string& parameter, const std::vector<float>& value);

 private:
  std::vector<float> builtinValue(const WaterUniform& u, const FrameValues& frame) const;
  void set(const WaterUniform& u, const std::vector<float>& v) const;

  std::vector<WaterUniform> uniforms_;
};

}  // namespace wg::rt
