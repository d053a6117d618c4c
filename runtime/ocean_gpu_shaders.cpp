// The spectral ocean's GPU passes as GLSL for both runtimes (runtime/ocean_gpu_shaders.h).
#include "runtime/ocean_gpu_shaders.h"

#include <stdexcept>

namespace wg::rt::oceangpu {
namespace {

// Each bin's phase is the 32-bit product n tau (uint arithmetic wraps modulo 2^32, as the
// reference's does); its top 24 bits become a float exactly, so the only rounding is the
// product by 2 pi / 2^24 and the sine and cosine.
constexpr const char* kEvolveBody = R"glsl(
layout(location = 0) out vec4 o_a;
#if WG_OCEAN_SLOPES && !WG_OCEAN_JACOBIAN_ONLY
layout(location = 1) out vec4 o_b;
#endif

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 timesI(vec2 a) { return vec2(-a.y, a.x); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 h0 = texelFetch(u_h0, p, 0);  // h0(k) and conj(h0(-k))
  uint turns = texelFetch(u_frequency, p, 0).r * u_tau;
  float phase = float(turns >> 8u) * (6.283185307179586 / 16777216.0);
  vec2 turn = vec2(cos(phase), sin(phase));
  vec2 h = cmul(h0.xy, vec2(turn.x, -turn.y)) + cmul(h0.zw, turn);
  ivec2 m = ivec2(p.x < u_n / 2 ? p.x : p.x - u_n, p.y < u_n / 2 ? p.y : p.y - u_n);
  vec2 k = vec2(m) * u_dk;
  float kl = length(k);
  vec2 unit = kl > 0.0 ? k / kl : vec2(0.0);
  vec2 ih = timesI(h);
  vec2 dx = unit.x * ih, dz = unit.y * ih;          // i k/|k| h
  vec2 sx = k.x * ih, sz = k.y * ih;                // i k h
  vec2 dxx = -k.x * unit.x * h, dzz = -k.y * unit.y * h, dxz = -k.x * unit.y * h;
#if WG_OCEAN_JACOBIAN_ONLY
  // The second texture alone, in the first output: the fields the foam's J needs.
  o_a = vec4(sz + timesI(dxx), dzz + timesI(dxz));
#else
  o_a = vec4(h + timesI(dx), dz + timesI(sx));
#if WG_OCEAN_SLOPES
  o_b = vec4(sz + timesI(dxx), dzz + timesI(dxz));
#endif
#endif
}
)glsl";

// One radix-2 Stockham stage of the inverse DFT (sum of x_k exp(+2 pi i k j / N)) along x
// or z, for sub-transforms of length Ns: output i takes inputs j and j + N/2 with
// j = (i / 2Ns) Ns + i mod Ns, and the twiddle exp(2 pi i (i mod Ns) / 2Ns), negated for
// the second half of each block. After log2 N stages the result is in natural order.
constexpr const char* kStockhamBody = R"glsl(
layout(location = 0) out vec4 o_a;
#if WG_OCEAN_SLOPES
layout(location = 1) out vec4 o_b;
#endif

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = u_vertical == 1 ? p.y : p.x;
  int r = i % u_ns;
  int j = (i / (2 * u_ns)) * u_ns + r;
  ivec2 first = u_vertical == 1 ? ivec2(p.x, j) : ivec2(j, p.y);
  ivec2 second = u_vertical == 1 ? ivec2(p.x, j + u_n / 2) : ivec2(j + u_n / 2, p.y);
  vec2 w = texelFetch(u_twiddle, ivec2(r * (u_n / (2 * u_ns)), 0), 0).xy;
  if ((i / u_ns) % 2 == 1) w = -w;
  vec4 a0 = texelFetch(u_a, first, 0), a1 = texelFetch(u_a, second, 0);
  o_a = vec4(a0.xy + cmul(w, a1.xy), a0.zw + cmul(w, a1.zw));
#if WG_OCEAN_SLOPES
  vec4 b0 = texelFetch(u_b, first, 0), b1 = texelFetch(u_b, second, 0);
  o_b = vec4(b0.xy + cmul(w, b1.xy), b0.zw + cmul(w, b1.zw));
#endif
}
)glsl";

constexpr const char* kPackBody = R"glsl(
layout(location = 0) out vec4 o_displacement;
#if WG_OCEAN_SLOPES
layout(location = 1) out vec4 o_slopes;
#endif
#if WG_OCEAN_MOMENTS
layout(location = 2) out vec4 o_moments;
#endif

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(u_a, p, 0);
  float h = a.x, dx = a.y, dz = a.z;
#if WG_OCEAN_SLOPES
  vec4 b = texelFetch(u_b, p, 0);
  float sx = a.w, sz = b.x, dxx = b.y, dzz = b.z, dxz = b.w;
  // The derivatives of the displacement, not J: J of several cascades is J of their sums,
  // which a sum of per-cascade Js is not.
  o_displacement = vec4(u_lambda * dx, h, u_lambda * dz, u_lambda * dxz);
  o_slopes = vec4(sx, sz, u_lambda * dxx, u_lambda * dzz);
#if WG_OCEAN_MOMENTS
  // What the filtered reader needs beside the mean slopes: the slopes' second moments
  // (their box means minus the squared mean slopes are the variance a footprint averages
  // away) and lambda dDx/dz, the normal's one field the slope map does not hold.
  o_moments = vec4(sx * sx, sz * sz, sx * sz, u_lambda * dxz);
#endif
#else
  // Nothing reads the slopes, so nothing reads w either (wg_ocean_normal and
  // wg_ocean_jacobian take both maps).
  o_displacement = vec4(u_lambda * dx, h, u_lambda * dz, 0.0);
#endif
}
)glsl";

// f_(m+1) = min(1, f_m keep + gain max(0, threshold - J)), J from the transformed fields
// (dh/dz, dDx/dx, dDz/dz, dDx/dz) as the pack pass forms it.
constexpr const char* kFoamStepBody = R"glsl(
layout(location = 0) out vec4 o_foam;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 b = texelFetch(u_fields, p, 0);
  float lxx = u_lambda * b.y, lzz = u_lambda * b.z, lxz = u_lambda * b.w;
  float j = (1.0 + lxx) * (1.0 + lzz) - lxz * lxz;
  float f = texelFetch(u_previous, p, 0).r * u_keep + u_gain * max(u_threshold - j, 0.0);
  o_foam = vec4(min(f, 1.0), 0.0, 0.0, 1.0);
}
)glsl";

// The foam at the frame's time: f_n + (f_(n+1) - f_n) fraction at each texel.
constexpr const char* kFoamBlendBody = R"glsl(
layout(location = 0) out vec4 o_foam;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float a = texelFetch(u_current, p, 0).r, b = texelFetch(u_next, p, 0).r;
  o_foam = vec4(a + (b - a) * u_fraction, 0.0, 0.0, 1.0);
}
)glsl";

// One level of the filtered reader's pyramid: each texel the mean of the 2x2 texels of the
// level above, ((t00 + t10) + (t01 + t11)) / 4 (the product by 1/4 is exact). Each sampler
// shows the level above alone, as its level 0 (GL: the texture's base and max level; Vulkan
// and WebGPU: a view of that level), while the pass draws into the next level.
constexpr const char* kDownsampleBody = R"glsl(
layout(location = 0) out vec4 o_slopes;
layout(location = 1) out vec4 o_moments;

void main() {
  ivec2 q = 2 * ivec2(gl_FragCoord.xy);
  ivec2 qx = q + ivec2(1, 0), qz = q + ivec2(0, 1), qxz = q + ivec2(1, 1);
  o_slopes = ((texelFetch(u_slopes, q, 0) + texelFetch(u_slopes, qx, 0)) +
              (texelFetch(u_slopes, qz, 0) + texelFetch(u_slopes, qxz, 0))) * 0.25;
  o_moments = ((texelFetch(u_moments, q, 0) + texelFetch(u_moments, qx, 0)) +
               (texelFetch(u_moments, qz, 0) + texelFetch(u_moments, qxz, 0))) * 0.25;
}
)glsl";

// A declaration: GLSL type and name.
struct OceanDeclaration {
  const char* type;
  const char* name;
};

struct OceanPassText {
  std::vector<OceanDeclaration> samplers;  // binding order; `optional` ones last
  std::vector<OceanDeclaration> constants;
  const char* body;
};

OceanPassText oceanPassText(OceanPass pass, const OceanPassVariant& v) {
  switch (pass) {
    case OceanPass::Evolve:
      return {{{"sampler2D", "u_h0"}, {"usampler2D", "u_frequency"}},
              {{"uint", "u_tau"}, {"float", "u_dk"}, {"int", "u_n"}},
              kEvolveBody};
    case OceanPass::Stockham: {
      OceanPassText t{{{"sampler2D", "u_a"}, {"sampler2D", "u_twiddle"}},
                      {{"int", "u_ns"}, {"int", "u_n"}, {"int", "u_vertical"}},
                      kStockhamBody};
      if (v.slopes) t.samplers.push_back({"sampler2D", "u_b"});
      return t;
    }
    case OceanPass::Pack: {
      OceanPassText t{{{"sampler2D", "u_a"}}, {{"float", "u_lambda"}}, kPackBody};
      if (v.slopes) t.samplers.push_back({"sampler2D", "u_b"});
      return t;
    }
    case OceanPass::FoamStep:
      return {{{"sampler2D", "u_fields"}, {"sampler2D", "u_previous"}},
              {{"float", "u_lambda"}, {"float", "u_keep"}, {"float", "u_gain"}, {"float", "u_threshold"}},
              kFoamStepBody};
    case OceanPass::FoamBlend:
      return {{{"sampler2D", "u_current"}, {"sampler2D", "u_next"}}, {{"float", "u_fraction"}}, kFoamBlendBody};
    case OceanPass::Downsample:
      return {{{"sampler2D", "u_slopes"}, {"sampler2D", "u_moments"}}, {}, kDownsampleBody};
  }
  throw std::logic_error("an unknown ocean pass");
}

}  // namespace

std::vector<std::string> oceanPassSamplers(OceanPass pass, const OceanPassVariant& variant) {
  std::vector<std::string> out;
  for (const OceanDeclaration& d : oceanPassText(pass, variant).samplers) out.emplace_back(d.name);
  return out;
}

std::vector<std::string> oceanPassConstants(OceanPass pass) {
  std::vector<std::string> out;
  for (const OceanDeclaration& d : oceanPassText(pass, {}).constants) out.emplace_back(d.name);
  return out;
}

ShaderInterface oceanPassInterface(OceanPass pass, const OceanPassVariant& variant) {
  const OceanPassText t = oceanPassText(pass, variant);
  ShaderInterface i{"WgOceanPassConstants", {}, {}, {}, {}};
  for (const OceanDeclaration& c : t.constants) i.constants.push_back({c.type, c.name});
  for (const OceanDeclaration& d : t.samplers) i.textures.push_back({d.type, d.name});
  return i;
}

std::string oceanPassFragment(OceanPass pass, SceneShaderApi api, const OceanPassVariant& variant) {
  return glslVersionLine(api) + oceanPassFragmentBody(pass, api, variant);
}

std::string oceanPassFragmentBody(OceanPass pass, SceneShaderApi api, const OceanPassVariant& variant) {
  const OceanPassText t = oceanPassText(pass, variant);
  std::string s = sceneShaderPreamble(api) + "#define WG_OCEAN_SLOPES " + (variant.slopes ? "1" : "0") +
                  "\n#define WG_OCEAN_JACOBIAN_ONLY " + (variant.jacobianOnly ? "1" : "0") +
                  "\n#define WG_OCEAN_MOMENTS " + (variant.moments ? "1" : "0") + "\n";
  // WebGPU: the declarations of the pass's interface (runtime/webgpu_shader_form.h).
  if (api == SceneShaderApi::WebGpu450) return s + webgpuDeclarations(oceanPassInterface(pass, variant)) + t.body;
  const bool vulkan = api == SceneShaderApi::Vulkan450;
  for (size_t i = 0; i < t.samplers.size(); ++i)
    s += (vulkan ? "layout(set = 0, binding = " + std::to_string(i) + ") " : std::string()) + "uniform highp " +
         t.samplers[i].type + " " + t.samplers[i].name + ";\n";
  const bool block = vulkan && !t.constants.empty();  // GLSL has no empty block
  if (block) s += "layout(push_constant) uniform WgOceanPassConstants {\n";
  for (const OceanDeclaration& c : t.constants) s += std::string(vulkan ? "  " : "uniform ") + c.type + " " + c.name + ";\n";
  if (block) s += "};\n";
  return s + t.body;
}

namespace {

struct NamedOceanPass {
  const char* name;
  OceanPass pass;
  OceanPassVariant variant;
};

NamedOceanPass namedOceanPass(OceanPassShader shader) {
  switch (shader) {
    case OceanPassShader::Evolve: return {"ocean_evolve", OceanPass::Evolve, {true, false}};
    case OceanPassShader::EvolveDisplacement: return {"ocean_evolve_displacement", OceanPass::Evolve, {false, false}};
    case OceanPassShader::EvolveJacobian: return {"ocean_evolve_jacobian", OceanPass::Evolve, {false, true}};
    case OceanPassShader::Stockham: return {"ocean_stockham", OceanPass::Stockham, {true, false}};
    case OceanPassShader::StockhamSingle: return {"ocean_stockham_single", OceanPass::Stockham, {false, false}};
    case OceanPassShader::Pack: return {"ocean_pack", OceanPass::Pack, {true, false}};
    case OceanPassShader::PackDisplacement: return {"ocean_pack_displacement", OceanPass::Pack, {false, false}};
    case OceanPassShader::FoamStep: return {"ocean_foam_step", OceanPass::FoamStep, {}};
    case OceanPassShader::FoamBlend: return {"ocean_foam_blend", OceanPass::FoamBlend, {}};
    case OceanPassShader::PackFiltered: return {"ocean_pack_filtered", OceanPass::Pack, {true, false, true}};
    case OceanPassShader::Downsample: return {"ocean_downsample", OceanPass::Downsample, {}};
  }
  throw std::logic_error("an ocean pass shader that does not exist");
}

}  // namespace

const char* oceanPassShaderName(OceanPassShader shader) { return namedOceanPass(shader).name; }

std::string oceanPassFragment(SceneShaderApi api, OceanPassShader shader) {
  const NamedOceanPass n = namedOceanPass(shader);
  return oceanPassFragment(n.pass, api, n.variant);
}

std::string oceanPassFragmentBody(SceneShaderApi api, OceanPassShader shader) {
  const NamedOceanPass n = namedOceanPass(shader);
  return oceanPassFragmentBody(n.pass, api, n.variant);
}

ShaderInterface oceanPassInterface(OceanPassShader shader) {
  const NamedOceanPass n = namedOceanPass(shader);
  return oceanPassInterface(n.pass, n.variant);
}

}  // namespace wg::rt::oceangpu
