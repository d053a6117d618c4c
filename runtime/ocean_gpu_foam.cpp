// One cascade's persistent foam on the GPU (runtime/ocean_gpu_foam.h).
#include "runtime/ocean_gpu_foam.h"

#include <cmath>

#include "runtime/ocean_gpu_passes.h"
#include "runtime/ocean_gpu_shaders.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

using namespace oceangpu;

}  // namespace

OceanGpuFoam::OceanGpuFoam(int resolution, const ocean::FoamSettings& settings, SceneShaderApi api)
    : n_(resolution), settings_(settings) {
  for (int s = 0; s < 3; ++s) {
    states_[s] = floatTexture(n_, n_, GL_R32F);
    stateTargets_[s] = targetOf(states_[s], nullptr, "foam");
  }
  output_ = floatTexture(n_, n_, GL_R32F);
  outputTarget_ = targetOf(output_, nullptr, "foam");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  emptyVao_ = makeVertexArray();
  step_ = linkPass(api, oceanPassShaderName(OceanPassShader::FoamStep), oceanPassFragment(api, OceanPassShader::FoamStep));
  blend_ = linkPass(api, oceanPassShaderName(OceanPassShader::FoamBlend), oceanPassFragment(api, OceanPassShader::FoamBlend));
  checkGl("creating the ocean's foam");
}

void OceanGpuFoam::step(std::int64_t m, double choppiness, OceanGpuCascade& cascade) {
  const Texture& fields = cascade.jacobianFields(static_cast<double>(m) * settings_.step);
  const int written = 3 - current_ - next_;
  glUseProgram(step_.id());
  bindTexture(0, fields);
  bindTexture(1, states_[next_]);
  glUniform1i(location(step_, "u_fields"), 0);
  glUniform1i(location(step_, "u_previous"), 1);
  glUniform1f(location(step_, "u_lambda"), static_cast<float>(choppiness));
  glUniform1f(location(step_, "u_keep"), static_cast<float>(ocean::foamKeep(settings_)));
  glUniform1f(location(step_, "u_gain"), static_cast<float>(ocean::foamGain(settings_)));
  glUniform1f(location(step_, "u_threshold"), static_cast<float>(settings_.threshold));
  glBindFramebuffer(GL_FRAMEBUFFER, stateTargets_[written].id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  current_ = next_;
  next_ = written;
  ++lastSteps_;
}

void OceanGpuFoam::update(double time, double choppiness, OceanGpuCascade& cascade, FoamHistory history) {
  const std::int64_t n = ocean::stepIndex(settings_, time);
  const int k = ocean::historySteps(settings_);
  lastSteps_ = 0;
  const bool continues = valid_ && n >= at_ && (n == at_ || (history == FoamHistory::Continue && n - at_ <= k));
  if (continues) {
    for (std::int64_t m = at_ + 2; m <= n + 1; ++m) step(m, choppiness, cascade);
  } else {
    // f_(n-K) = 0 in next_, then K + 1 steps to f_(n+1).
    glBindFramebuffer(GL_FRAMEBUFFER, stateTargets_[next_].id());
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    for (std::int64_t m = n - k + 1; m <= n + 1; ++m) step(m, choppiness, cascade);
  }
  valid_ = true;
  at_ = n;

  glViewport(0, 0, n_, n_);
  glBindVertexArray(emptyVao_.id());
  glUseProgram(blend_.id());
  bindTexture(0, states_[current_]);
  bindTexture(1, states_[next_]);
  glUniform1i(location(blend_, "u_current"), 0);
  glUniform1i(location(blend_, "u_next"), 1);
  glUniform1f(location(blend_, "u_fraction"), static_cast<float>(ocean::foamFraction(settings_, time)));
  glBindFramebuffer(GL_FRAMEBUFFER, outputTarget_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  checkGl("the ocean's foam passes");
}

std::vector<float> OceanGpuFoam::readMap() const {
  // RGBA and float: the one read-back format every float colour buffer allows on ES.
  std::vector<float> rgba(static_cast<size_t>(n_) * n_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, outputTarget_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, n_, n_, GL_RGBA, GL_FLOAT, rgba.data());
  checkGl("reading the ocean's foam back");
  std::vector<float> out(rgba.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[i * 4];
  return out;
}

}  // namespace wg::rt
