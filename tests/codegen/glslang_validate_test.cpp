// validateShaders(): glslang compile + link for every target, SPIR-V + spirv-val for vk450.
#include "codegen/glslang_validate.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace wg {
namespace {

const char* kVert330 = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform float u_time;
out vec2 v_uv;
void main() {
  v_uv = a_position.xz + vec2(u_time);
  gl_Position = vec4(a_position, 1.0);
}
)";

const char* kFrag330 = R"(#version 330 core
in vec2 v_uv;
uniform sampler2D u_normals;
out vec4 fragColor;
void main() {
  fragColor = texture(u_normals, v_uv);
}
)";

const char* kVertEs300 = R"(#version 300 es
precision highp float;
layout(location = 0) in vec3 a_position;
uniform float u_time;
out vec2 v_uv;
void main() {
  v_uv = a_position.xz + vec2(u_time);
  gl_Position = vec4(a_position, 1.0);
}
)";

const char* kFragEs300 = R"(#version 300 es
precision highp float;
in vec2 v_uv;
uniform sampler2D u_normals;
out vec4 fragColor;
void main() {
  fragColor = texture(u_normals, v_uv);
}
)";

const char* kVertVk450 = R"(#version 450
layout(location = 0) in vec3 a_position;
layout(std140, set = 0, binding = 0) uniform WgUniforms { float u_time; };
layout(location = 0) out vec2 v_uv;
void main() {
  v_uv = a_position.xz + vec2(u_time);
  gl_Position = vec4(a_position, 1.0);
}
)";

const char* kFragVk450 = R"(#version 450
layout(location = 0) in vec2 v_uv;
layout(std140, set = 0, binding = 0) uniform WgUniforms { float u_time; };
layout(set = 0, binding = 1) uniform sampler2D u_normals;
layout(location = 0) out vec4 fragColor;
void main() {
  fragColor = texture(u_normals, v_uv) * u_time;
}
)";

std::vector<ShaderSource> pairFor(Target t) {
  std::string base = "lake." + std::string(targetName(t)) + ".";
  switch (t) {
    case Target::Glsl330:
      return {{ShaderStage::Vertex, base + "vert", kVert330},
              {ShaderStage::Fragment, base + "frag", kFrag330}};
    case Target::Es300:
      return {{ShaderStage::Vertex, base + "vert", kVertEs300},
              {ShaderStage::Fragment, base + "frag", kFragEs300}};
    case Target::Vk450:
      return {{ShaderStage::Vertex, base + "vert", kVertVk450},
              {ShaderStage::Fragment, base + "frag", kFragVk450}};
  }
  return {};
}

std::string describe(const ValidationResult& r) {
  std::string s;
  for (const auto& e : r.errors) s += e.fileName + ":" + std::to_string(e.line) + ": " + e.text + "\n";
  return s;
}

class ValidateTarget : public ::testing::TestWithParam<Target> {};

TEST_P(ValidateTarget, TrivialPairIsValid) {
  ValidationResult r = validateShaders(GetParam(), pairFor(GetParam()));
  EXPECT_TRUE(r.ok) << describe(r);
  EXPECT_TRUE(r.errors.empty()) << describe(r);
  if (GetParam() == Target::Vk450) {
    ASSERT_EQ(r.spirv.size(), 2u);
    for (const auto& m : r.spirv) {
      ASSERT_FALSE(m.empty());
      EXPECT_EQ(m[0], 0x07230203u);
    }
  } else {
    EXPECT_TRUE(r.spirv.empty());
  }
}

TEST_P(ValidateTarget, UndeclaredIdentifierReportsFileAndLine) {
  std::vector<ShaderSource> shaders = pairFor(GetParam());
  std::string& frag = shaders[1].text;
  // Replace the body so that line 5 (1-based) uses an undeclared identifier in every target.
  std::vector<std::string> lines;
  size_t start = 0;
  for (size_t nl; (nl = frag.find('\n', start)) != std::string::npos; start = nl + 1)
    lines.push_back(frag.substr(start, nl - start));
  ASSERT_GE(lines.size(), 5u);
  lines.insert(lines.begin() + 4, "float wg_bogus_helper() { return wg_missing_value; }");
  frag.clear();
  for (const auto& l : lines) frag += l + "\n";

  ValidationResult r = validateShaders(GetParam(), shaders);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.spirv.empty());
  ASSERT_FALSE(r.errors.empty());
  bool found = false;
  for (const auto& e : r.errors) {
    if (e.fileName == shaders[1].fileName && e.line == 5 &&
        e.text.find("wg_missing_value") != std::string::npos &&
        e.text.find("undeclared identifier") != std::string::npos)
      found = true;
    EXPECT_EQ(e.text.find("compilation errors"), std::string::npos) << e.text;
  }
  EXPECT_TRUE(found) << describe(r);
}

INSTANTIATE_TEST_SUITE_P(AllTargets, ValidateTarget,
                         ::testing::Values(Target::Glsl330, Target::Es300, Target::Vk450),
                         [](const auto& info) { return std::string(targetName(info.param)); });

TEST(GlslangValidate, VaryingNeverWrittenIsALinkError) {
  std::vector<ShaderSource> shaders = pairFor(Target::Glsl330);
  shaders[1].text = R"(#version 330 core
in vec2 v_uv;
in float v_foam;
out vec4 fragColor;
void main() {
  fragColor = vec4(v_uv, v_foam, 1.0);
}
)";
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.errors.empty());
  bool found = false;
  for (const auto& e : r.errors)
    if (e.fileName.empty() && e.line == 0 && e.text.find("v_foam") != std::string::npos) found = true;
  EXPECT_TRUE(found) << describe(r);
}

TEST(GlslangValidate, UnusedUnmatchedInputIsNotAnError) {
  std::vector<ShaderSource> shaders = pairFor(Target::Glsl330);
  shaders[1].text = R"(#version 330 core
in vec2 v_uv;
in float v_foam;
out vec4 fragColor;
void main() {
  fragColor = vec4(v_uv, 0.0, 1.0);
}
)";
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_TRUE(r.ok) << describe(r);
}

TEST(GlslangValidate, VaryingTypeMismatchIsALinkError) {
  std::vector<ShaderSource> shaders = pairFor(Target::Glsl330);
  shaders[1].text = R"(#version 330 core
in vec3 v_uv;
out vec4 fragColor;
void main() {
  fragColor = vec4(v_uv, 1.0);
}
)";
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors[0].fileName, "");
  EXPECT_EQ(r.errors[0].line, 0);
  EXPECT_NE(r.errors[0].text.find("v_uv"), std::string::npos) << describe(r);
}

TEST(GlslangValidate, Vk450LocationMismatchIsALinkError) {
  std::vector<ShaderSource> shaders = pairFor(Target::Vk450);
  std::string& frag = shaders[1].text;
  frag.replace(frag.find("location = 0) in vec2"), 12, "location = 3");
  ValidationResult r = validateShaders(Target::Vk450, shaders);
  EXPECT_FALSE(r.ok) << describe(r);
  EXPECT_TRUE(r.spirv.empty());

  // Vulkan matches stage interfaces by location, not by name: a renamed input at the
  // right location links; one at a location nobody writes does not.
  std::vector<ShaderSource> renamed = pairFor(Target::Vk450);
  std::string& f = renamed[1].text;
  for (size_t at; (at = f.find("v_uv")) != std::string::npos;) f.replace(at, 4, "f_uv");
  EXPECT_TRUE(validateShaders(Target::Vk450, renamed).ok);
  f.replace(f.find("location = 0) in vec2"), 12, "location = 3");
  ValidationResult r2 = validateShaders(Target::Vk450, renamed);
  EXPECT_FALSE(r2.ok);
  ASSERT_FALSE(r2.errors.empty());
  EXPECT_NE(r2.errors[0].text.find("f_uv"), std::string::npos) << describe(r2);
}

TEST(GlslangValidate, UnnamedShaderUsesDefaultFileName) {
  std::vector<ShaderSource> shaders = {{ShaderStage::Fragment, "", R"(#version 330 core
out vec4 c;
void main() { c = vec4(wg_zz); }
)"}};
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.errors.size(), 1u) << describe(r);
  EXPECT_EQ(r.errors[0].fileName, "");
  EXPECT_EQ(r.errors[0].line, 3);
}

TEST(GlslangValidate, InterfaceBlocksMatchByBlockName) {
  std::vector<ShaderSource> shaders = {
      {ShaderStage::Vertex, "b.vert", R"(#version 330 core
layout(location = 0) in vec3 a_position;
out WgVarying { vec2 uv; } vOut;
void main() { vOut.uv = a_position.xy; gl_Position = vec4(a_position, 1.0); }
)"},
      {ShaderStage::Fragment, "b.frag", R"(#version 330 core
in WgVarying { vec2 uv; } fIn;
out vec4 c;
void main() { c = vec4(fIn.uv, 0.0, 1.0); }
)"}};
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_TRUE(r.ok) << describe(r);
}

TEST(GlslangValidate, TessellationPipelineVk450) {
  std::vector<ShaderSource> shaders = {
      {ShaderStage::Vertex, "t.vert", R"(#version 450
layout(location = 0) in vec3 a_position;
layout(location = 0) out vec2 v_uv;
void main() { v_uv = a_position.xy; gl_Position = vec4(a_position, 1.0); }
)"},
      {ShaderStage::TessControl, "t.tesc", R"(#version 450
layout(vertices = 3) out;
layout(location = 0) in vec2 v_uv[];
layout(location = 0) out vec2 c_uv[];
void main() {
  c_uv[gl_InvocationID] = v_uv[gl_InvocationID];
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  gl_TessLevelOuter[0] = 4.0; gl_TessLevelOuter[1] = 4.0; gl_TessLevelOuter[2] = 4.0;
  gl_TessLevelInner[0] = 4.0;
}
)"},
      {ShaderStage::TessEvaluation, "t.tese", R"(#version 450
layout(triangles, equal_spacing, ccw) in;
layout(location = 0) in vec2 c_uv[];
layout(location = 0) out vec2 e_uv;
void main() {
  e_uv = c_uv[0] * gl_TessCoord.x + c_uv[1] * gl_TessCoord.y + c_uv[2] * gl_TessCoord.z;
  gl_Position = gl_in[0].gl_Position;
}
)"},
      {ShaderStage::Fragment, "t.frag", R"(#version 450
layout(location = 0) in vec2 e_uv;
layout(location = 0) out vec4 c;
void main() { c = vec4(e_uv, 0.0, 1.0); }
)"}};
  ValidationResult r = validateShaders(Target::Vk450, shaders);
  EXPECT_TRUE(r.ok) << describe(r);
  ASSERT_EQ(r.spirv.size(), 4u);
  for (const auto& m : r.spirv) {
    ASSERT_FALSE(m.empty());
    EXPECT_EQ(m[0], 0x07230203u);
  }
}

TEST(GlslangValidate, Es300RequiresFloatPrecisionInFragment) {
  std::vector<ShaderSource> shaders = pairFor(Target::Es300);
  std::string& frag = shaders[1].text;
  frag.erase(frag.find("precision highp float;\n"), std::string("precision highp float;\n").size());
  ValidationResult r = validateShaders(Target::Es300, shaders);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors[0].fileName, "lake.es300.frag");
  EXPECT_GT(r.errors[0].line, 0);
  // The same text is valid desktop GLSL once the #version says so.
  std::vector<ShaderSource> desktop = pairFor(Target::Glsl330);
  desktop[1].text = "#version 330 core\n" + frag.substr(frag.find('\n') + 1);
  EXPECT_TRUE(validateShaders(Target::Glsl330, desktop).ok);
}

TEST(GlslangValidate, Es300RejectsDesktopOnlyConstruct) {
  std::vector<ShaderSource> shaders = pairFor(Target::Es300);
  std::string& frag = shaders[1].text;
  // double is desktop-only.
  frag.replace(frag.find("void main() {"), 13, "void main() {\n  double d = 1.0;");
  ValidationResult r = validateShaders(Target::Es300, shaders);
  EXPECT_FALSE(r.ok) << describe(r);
}

TEST(GlslangValidate, Vk450RejectsLooseUniform) {
  std::vector<ShaderSource> shaders = pairFor(Target::Vk450);
  shaders[1].text.replace(shaders[1].text.find("layout(location = 0) out vec4"), 0,
                          "uniform float u_loose;\n");
  ValidationResult r = validateShaders(Target::Vk450, shaders);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors[0].fileName, "lake.vk450.frag");
  EXPECT_EQ(r.errors[0].line, 5);
}

TEST(GlslangValidate, WarningsAreNotErrors) {
  std::vector<ShaderSource> shaders = pairFor(Target::Glsl330);
  // An unknown extension with "warn" behaviour only produces a WARNING line.
  shaders[1].text.insert(shaders[1].text.find('\n') + 1, "#extension GL_WG_not_real : warn\n");
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_TRUE(r.ok) << describe(r);
  EXPECT_TRUE(r.errors.empty());
}

TEST(GlslangValidate, ManyCallsStayCorrect) {
  for (int i = 0; i < 200; ++i) {
    Target t = allTargets()[i % 3];
    std::vector<ShaderSource> shaders = pairFor(t);
    bool breakIt = (i % 2) == 1;
    if (breakIt) shaders[0].text.replace(shaders[0].text.find("v_uv = "), 7, "v_uv = wg_nope + ");
    ValidationResult r = validateShaders(t, shaders);
    ASSERT_EQ(r.ok, !breakIt) << "iteration " << i << "\n" << describe(r);
    if (breakIt) {
      ASSERT_FALSE(r.errors.empty());
      ASSERT_EQ(r.errors[0].fileName, shaders[0].fileName);
      ASSERT_GT(r.errors[0].line, 0);
    } else if (t == Target::Vk450) {
      ASSERT_EQ(r.spirv.size(), 2u);
    }
  }
}

TEST(GlslangValidate, StageWithoutEntryPointIsReported) {
  std::vector<ShaderSource> shaders = pairFor(Target::Glsl330);
  shaders[1].text = "#version 330 core\nout vec4 fragColor;\n";
  ValidationResult r = validateShaders(Target::Glsl330, shaders);
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.errors.empty());
}

}  // namespace
}  // namespace wg
