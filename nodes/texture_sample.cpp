// texture_sample.cpp — a user PNG (or a builtin texture) sampled at uv with a chosen wrap
// mode, filter and colour space (issue 17 §3). The GLSL is GLSL's own texture(); the state
// is the texture's (EmitContext::texture with a SamplerState), so the emitter, manifest,
// runtime, probe and three.js client all set it from one value, and the double reference
// is GL's sampling rules (nodes/texture_sampling.h).
#include "core/emit_context.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

struct TextureSampleOptions {
  SamplerState sampler;
};

TextureSampleOptions parseTextureSampleOptions(const OptionReader& o) {
  SamplerState s;
  s.wrap = o.choice<TextureWrap>("wrap", {{wrapName(TextureWrap::Repeat), TextureWrap::Repeat},
                                          {wrapName(TextureWrap::Clamp), TextureWrap::Clamp},
                                          {wrapName(TextureWrap::Mirror), TextureWrap::Mirror}});
  s.filter = o.choice<TextureFilter>("filter", {{filterName(TextureFilter::Nearest), TextureFilter::Nearest},
                                                {filterName(TextureFilter::Linear), TextureFilter::Linear},
                                                {filterName(TextureFilter::Mipmapped), TextureFilter::Mipmapped}});
  s.colorSpace = o.choice<TextureColorSpace>(
      "color_space", {{colorSpaceName(TextureColorSpace::Srgb), TextureColorSpace::Srgb},
                      {colorSpaceName(TextureColorSpace::Linear), TextureColorSpace::Linear}});
  return {s};
}

template <class E, size_t N>
std::vector<std::string> samplerChoiceNames(std::string_view (*name)(E), const E (&values)[N]) {
  std::vector<std::string> out;
  for (E v : values) out.emplace_back(name(v));
  return out;
}

constexpr TextureWrap kWraps[] = {TextureWrap::Repeat, TextureWrap::Clamp, TextureWrap::Mirror};
constexpr TextureFilter kFilters[] = {TextureFilter::Nearest, TextureFilter::Linear, TextureFilter::Mipmapped};
constexpr TextureColorSpace kColorSpaces[] = {TextureColorSpace::Srgb, TextureColorSpace::Linear};

}  // namespace

NodeSpec textureSampleNode() {
  NodeSpec s;
  s.type = "texture_sample";
  s.family = "textures";
  s.summary = "A PNG from the graph's folder (or a builtin texture) sampled at uv: wrap, filter and colour space chosen.";
  s.formula =
      "rgba = texture(T, uv) with T's state as GL defines it: texel centres at (i + 0.5) / size; wrap repeat "
      "(i mod size), clamp (to the edge texels) or mirror (GL_MIRRORED_REPEAT); filter nearest, linear (bilinear) or "
      "mipmapped (GL_LINEAR_MIPMAP_LINEAR over the glGenerateMipmap chain, level of detail lambda = "
      "log2(max(|du/dx| w, |dv/dx| h, |du/dy| w, |dv/dy| h)) from the screen-space derivatives of uv; level 0 where "
      "lambda <= 0 and in the vertex stage); color_space srgb decodes r, g, b of each texel to linear before "
      "filtering (GL_SRGB8_ALPHA8), linear reads the bytes / 255 (data: flow, height). rgb = rgba.rgb, alpha = rgba.a. GPU against this reference: within 4/255, one 8-bit level for each of the u, v "
      "and mip-level filter weights (8-bit weights on 8-bit textures) and one for the 8-bit values of the generated mip "
      "levels. The reference takes the derivatives from the case (probe keys uv_dx, uv_dy; in `watergraph check`, "
      "those of the uv builtin over the flat water): with mipmapped filtering of a uv computed otherwise (a scaled "
      "world position) the GPU may pick another level than the reference, and check reports those pixels.";
  s.cost = "one texture fetch (mipmapped: two levels, eight texels; the runtime builds the chain once at upload)";
  s.inputs = {ports::fromBuiltin("uv", Type::Vec2, Builtin::Uv, "texture coordinate; (0, 0) is the picture's bottom left")};
  s.outputs = {ports::fixed("rgb", Type::Vec3, "the filtered colour, linear, in [0, 1]"),
               ports::fixed("alpha", Type::Float, "the filtered alpha (never colour-decoded), in [0, 1]"),
               ports::fixed("rgba", Type::Vec4, "rgb and alpha together")};
  s.options = {
      ports::texture("texture", "builtin:foam",
                     "a .png path relative to the graph file, inside its folder (or builtin:<name>)"),
      ports::choice("wrap", samplerChoiceNames(wrapName, kWraps), "repeat",
                    "outside [0, 1]: repeat, clamp to the edge texels, or mirror every other repeat"),
      ports::choice("filter", samplerChoiceNames(filterName, kFilters), "linear",
                    "nearest texel, bilinear, or trilinear over a mip chain (minified look-ups stay smooth)"),
      ports::choice("color_space", samplerChoiceNames(colorSpaceName, kColorSpaces), "srgb",
                    "srgb for a picture (decoded to linear per texel), linear for data such as a flow or height map"),
  };
  s.isSource = true;
  s.parseOptions = optionParser(parseTextureSampleOptions);
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    // Texels are 8-bit UNORM (or sRGB decoded into [0, 1]) and every filter is a convex blend.
    ValueFact unit{0, 1, false};
    return std::vector<ValueFact>{unit, unit, unit};
  };
  s.emit = [](EmitContext& ctx) {
    GlslExpr uv = ctx.input("uv");
    GlslExpr texel = ctx.temporary(Type::Vec4, ctx.sampleTexture("texture", ctx.options<TextureSampleOptions>().sampler, uv));
    ctx.output(0, texel + ".rgb");
    ctx.output(1, texel + ".a");
    ctx.output(2, texel);
  };
  s.eval = [](EvalContext& ctx) {
    const Value& uv = ctx.input("uv");
    // The derivatives of this node's uv input are taken to be the uv builtin's, which
    // holds when the input is the builtin (its default); they are zero, level 0, unless a
    // probe case gives them.
    const EvalEnvironment& env = ctx.environment();
    UvGradient g{env.uvDx[0], env.uvDx[1], env.uvDy[0], env.uvDy[1]};
    Value t = ctx.sampleTexture("texture", uv[0], uv[1], ctx.options<TextureSampleOptions>().sampler, g);
    ctx.output(0, Value::vector({t[0], t[1], t[2]}));
    ctx.output(1, Value::scalar(t[3]));
    ctx.output(2, t);
  };
  // 8-bit quantisation, one level (1/255) for each step that rounds to 8 bits on the GPU:
  // the u and v filter weights and the weight between two mip levels (llvmpipe filters
  // 8-bit textures with 8-bit weights), and the 8-bit values of the generated mip levels
  // (rounded at ties as the driver chooses): 4/255 ~ 0.0157. Nearest and level-0 linear
  // look-ups of linear data use fewer of them; the bound is the node's, for every mode.
  s.tolerance = 4.0 / 255.0;
  // Where float32 cannot place the coordinate: a uv of 1e6 has an ulp of 1/16 texture
  // unit (many texels), and a uv on a texel edge rounds to either side.
  s.conditionRoundings = 1;
  s.conditionWhy = "grows with |uv| (a float32 uv of 1e6 moves by 1/16 texture unit per ulp) and at texel edges";
  s.hardCases = {
      {"huge uv 1e6", {{"uv", Value::vector({1e6, 1e6})}}, {}, "finite, in [0, 1]", 0, 1, "rgba"},
      {"huge negative uv -1e6, mirror",
       {{"uv", Value::vector({-1e6, -1e6})}},
       {{"wrap", "mirror"}},
       "finite, in [0, 1]",
       0,
       1,
       "rgba"},
      {"huge uv 1e6, clamp", {{"uv", Value::vector({1e6, -1e6})}}, {{"wrap", "clamp"}}, "the edge texels", 0, 1, "rgba"},
      {"uv on texel edges, nearest",
       {{"uv", Value::vector({0.25, 0.5})}},
       {{"filter", "nearest"}},
       "a texel on either side, finite",
       0,
       1,
       "rgba"},
      {"uv exactly 0, clamp", {{"uv", Value::vector({0, 0})}}, {{"wrap", "clamp"}}, "the corner texel", 0, 1, "rgba"},
      {"uv exactly 1, mirror", {{"uv", Value::vector({1, 1})}}, {{"wrap", "mirror"}}, "the corner texel", 0, 1, "rgba"},
      {"negative uv, mirror", {{"uv", Value::vector({-0.3, -1.7})}}, {{"wrap", "mirror"}}, "finite, in [0, 1]", 0, 1,
       "rgba"},
      {"negative uv, mipmapped linear data",
       {{"uv", Value::vector({-2.6, -0.45})}},
       {{"filter", "mipmapped"}, {"color_space", "linear"}},
       "level 0 (no derivatives), finite",
       0,
       1,
       "rgba"},
  };
  return s;
}

}  // namespace wg::nodes
