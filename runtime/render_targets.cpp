// The render targets of a pass plan (runtime/render_targets.h).
#include "runtime/render_targets.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

size_t internalFormatBytes(GLint f) {
  switch (f) {
    case GL_RGBA8: return 4;
    case GL_RGBA16F: return 8;
    case GL_RGBA32F: return 16;
    case GL_DEPTH_COMPONENT32F: return 4;
    default: return 0;
  }
}

// Bytes of level 0 of the bound texture as the driver reports it (all faces of a cube).
size_t measuredBytes(GLenum bindTarget) {
  GLenum level = bindTarget == GL_TEXTURE_CUBE_MAP ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X) : bindTarget;
  GLint w = 0, h = 0, f = 0;
  glGetTexLevelParameteriv(level, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(level, 0, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(level, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
  return static_cast<size_t>(w) * static_cast<size_t>(h) * internalFormatBytes(f) * (bindTarget == GL_TEXTURE_CUBE_MAP ? 6 : 1);
}

GLenum colorInternalFormat(ColorFormat f) {
  return f == ColorFormat::Rgba32f ? GL_RGBA32F : f == ColorFormat::Rgba16f ? GL_RGBA16F : GL_RGBA8;
}

void setFilter(GLenum target, GLint filter) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (target == GL_TEXTURE_CUBE_MAP) glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

}  // namespace

void RenderTargets::create(const PassPlan& plan, bool es) {
  floatLinear_ = !es || epoxy_has_gl_extension("GL_OES_texture_float_linear");
  for (const TargetSpec& spec : plan.targets) {
    GpuTarget t;
    t.spec = spec;
    t.fbo = makeFramebuffer();
    GLenum texTarget = spec.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    if (spec.color != ColorFormat::None) {
      t.color = makeTexture();
      glBindTexture(texTarget, t.color.id());
      glTexStorage2D(texTarget, 1, colorInternalFormat(spec.color), spec.width, spec.height);
      setFilter(texTarget, sampledNearest(spec, floatLinear_) ? GL_NEAREST : GL_LINEAR);
      t.allocatedBytes += measuredBytes(texTarget);
    }
    if (spec.depth != DepthFormat::None) {
      t.depth = makeTexture();
      glBindTexture(GL_TEXTURE_2D, t.depth.id());
      glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, spec.width, spec.height);
      setFilter(GL_TEXTURE_2D, GL_NEAREST);
      t.allocatedBytes += measuredBytes(GL_TEXTURE_2D);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
    if (t.color) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                             spec.cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X : GL_TEXTURE_2D, t.color.id(), 0);
      GLenum buf = GL_COLOR_ATTACHMENT0;
      glDrawBuffers(1, &buf);
      if (spec.name == sceneSamplerRow(SceneSampler::WaterSurface).target) {  // the G-buffer draws into water_normal as well
        GpuTarget* normal = find(SceneSampler::WaterNormalUv);
        if (!normal) throw std::logic_error("the plan creates water_position without water_normal");
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, normal->color.id(), 0);
        GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glDrawBuffers(2, bufs);
      }
    } else {
      GLenum none = GL_NONE;
      glDrawBuffers(1, &none);
      glReadBuffer(GL_NONE);
    }
    if (t.depth) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, t.depth.id(), 0);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%04x", status);
      throw RuntimeError(RuntimeError::Kind::Driver,
                         "render target '" + spec.name + "' is incomplete on this driver (status " + buf + ")");
    }
    targets_.push_back(std::move(t));
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGl("creating render targets");
}

GpuTarget* RenderTargets::find(SceneSampler s) {
  const std::string_view name = sceneSamplerRow(s).target;
  for (auto& t : targets_)
    if (t.spec.name == name) return &t;
  return nullptr;
}

const GpuTarget* RenderTargets::picture(const PassPlan& plan) const {
  const TargetSpec* p = plan.picture();
  for (const auto& t : targets_)
    if (p && t.spec.name == p->name) return &t;
  return nullptr;
}

namespace {

// GL's rows are bottom-up; images are top-down.
template <class T>
void flipRows(std::vector<T>& v, int height, size_t rowElements) {
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(v.begin() + static_cast<ptrdiff_t>(y * rowElements), v.begin() + static_cast<ptrdiff_t>((y + 1) * rowElements),
                     v.begin() + static_cast<ptrdiff_t>((height - 1 - y) * rowElements));
}

}  // namespace

Image readTargetColor(const GpuTarget& t, bool asFloat) {
  Image img;
  img.width = t.spec.width;
  img.height = t.spec.height;
  const size_t n = static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 4;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.fbo.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (asFloat) {
    img.rgba32f.resize(n);
    glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, img.rgba32f.data());
    flipRows(img.rgba32f, img.height, static_cast<size_t>(img.width) * 4);
  } else {
    img.rgba8.resize(n);
    glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba8.data());
    flipRows(img.rgba8, img.height, static_cast<size_t>(img.width) * 4);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  checkGl("reading the frame back");
  return img;
}

std::vector<float> readTargetDepth(const GpuTarget& t) {
  const int w = t.spec.width, h = t.spec.height;
  std::vector<float> depth(static_cast<size_t>(w) * static_cast<size_t>(h));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.fbo.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  checkGl("reading the depth buffer back");
  flipRows(depth, h, static_cast<size_t>(w));
  return depth;
}

}  // namespace wg::rt
