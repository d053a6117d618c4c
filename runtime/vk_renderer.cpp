#include "runtime/vk_renderer.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <cstring>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "codegen/shader_interface.h"
#include "runtime/memory_budget.h"
#include "runtime/oblique_projection.h"
#include "runtime/runtime_error.h"
#include "runtime/tessellation_budget.h"
#include "runtime/vk_mesh.h"
#include "runtime/vk_ocean_simulation.h"
#include "runtime/vk_output_transform.h"
#include "runtime/vk_render_targets.h"
#include "runtime/vk_resources.h"
#include "runtime/vk_scene_spirv.h"
#include "runtime/vk_water_bindings.h"

namespace wg::rt {

glm::mat4 vulkanDepthRangeCorrection() {
  glm::mat4 c(1.0f);
  c[2][2] = 0.5f;  // z' = 0.5 z + 0.5 w
  c[3][2] = 0.5f;
  return c;
}

namespace {

// The floating buoys are drawn by the GL runtime only (runtime/floating_buoys.h).
void refuseBuoys(const SceneOptions& scene) {
  if (!scene.buoys.empty())
    manifestError("the floating buoys are drawn by the GL runtime (glsl330, es300), not yet by the Vulkan runtime");
}

// The scene's push constants, laid out as the blocks of scene.h (SceneShaderApi::Vulkan450).
struct SkyConstants {
  glm::mat4 inverseViewProjection;
  glm::vec3 sun;
};
struct OpaqueConstants {
  glm::mat4 viewProjection;
  glm::vec4 clipPlane;
  glm::vec3 sun;
};
constexpr uint32_t kPushConstantBytes = sizeof(OpaqueConstants);
static_assert(sizeof(SkyConstants) <= kPushConstantBytes && kPushConstantBytes <= 128, "within every device's push constants");

}  // namespace

struct VkRenderer::Impl {
  VkContext& ctx;
  RenderSettings settings;
  PassPlan plan;
  // The plan's share of the memory budget, reserved before any target is made.
  std::optional<MemoryReservation> memory;
  Camera camera;
  glm::mat4 view{1.0f}, projection{1.0f}, viewProjection{1.0f};  // GL's
  glm::vec3 sun{0.0f, 1.0f, 0.0f};
  bool deferred = false, tessellated = false;

  using Target = VkTarget;
  VkRenderTargets targets;
  VkMesh sceneMesh, waterMesh;
  VkSceneSpirv sceneSpirv;
  std::vector<VkShaderCode> waterStages;
  std::vector<VkVertexInputAttributeDescription> waterAttributes;
  std::unique_ptr<VkWaterBindings> bindings;
  std::shared_ptr<VkOceanSimulation> oceans;  // when the plan runs ocean_simulation; may be shared
  VkPipelineLayoutHandle sceneLayout, waterLayout;
  // Scene pipelines by the formats of the target they draw into.
  std::map<std::pair<VkFormat, bool>, VkPipelineHandle> skyPipelines, opaquePipelines;
  VkPipelineHandle waterPipeline, gbufferPipeline;
  VkCommandBuffer cmd = VK_NULL_HANDLE;  // the frame being recorded

  explicit Impl(VkContext& c) : ctx(c) {}

  Target* find(SceneSampler s) { return targets.find(s); }
  Target& frame() { return targets.frame(); }
  const Target& frame() const { return targets.frame(); }
  // The target whose colour is the 8-bit picture (PassPlan::picture), or null.
  Target* picture() { return targets.picture(plan); }
  std::unique_ptr<VkOutputTransform> output;  // when the plan runs the output transform

  // --- Pipelines.
  VkPipelineLayoutHandle makeLayout(const std::vector<VkDescriptorSetLayout>& sets, uint32_t pushBytes) {
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, pushBytes};
    VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.setLayoutCount = static_cast<uint32_t>(sets.size());
    lci.pSetLayouts = sets.data();
    lci.pushConstantRangeCount = pushBytes ? 1 : 0;
    lci.pPushConstantRanges = &range;
    VkPipelineLayout l = VK_NULL_HANDLE;
    checkVk(vkCreatePipelineLayout(ctx.device(), &lci, nullptr, &l), "creating a pipeline layout");
    return VkPipelineLayoutHandle(ctx.device(), l);
  }

  VkPipeline scenePipeline(bool sky, const Target& t) {
    const VkFormat color = t.color ? t.color.spec().format : VK_FORMAT_UNDEFINED;
    const bool depth = static_cast<bool>(t.depth);
    auto& cache = sky ? skyPipelines : opaquePipelines;
    auto it = cache.find({color, depth});
    if (it != cache.end()) return it->second.get();
    VkPipelineDescription d;
    d.layout = sceneLayout.get();
    if (color != VK_FORMAT_UNDEFINED) d.colorFormats = {color};
    d.depthFormat = depth ? kVkDepthFormat : VK_FORMAT_UNDEFINED;
    if (sky) {
      // At the far plane, after the opaque scene, without depth writes: only uncovered pixels.
      d.stages = {sceneSpirv.skyVertex, sceneSpirv.skyFragment};
      d.depthWrite = false;
    } else {
      // Into a depth-only target (the depth prepass) without a fragment shader: it would
      // write a colour no attachment takes.
      d.stages = {sceneSpirv.opaqueVertex};
      if (color != VK_FORMAT_UNDEFINED) d.stages.push_back(sceneSpirv.opaqueFragment);
      d.vertexStride = static_cast<uint32_t>(7 * sizeof(float));  // position, normal, material
      d.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
                      {static_cast<uint32_t>(kSceneMaterialLocation), 0, VK_FORMAT_R32_SFLOAT, 24}};
    }
    auto p = createGraphicsPipeline(ctx.device(), d, sky ? "the runtime's sky pass" : "the runtime's opaque scene");
    return cache.emplace(std::make_pair(color, depth), std::move(p)).first->second.get();
  }

  void createWaterPipelines(const Manifest& manifest) {
    waterLayout = makeLayout({bindings->setLayout()}, 0);
    const Target& f = frame();
    VkPipelineDescription water;
    water.layout = waterLayout.get();
    water.colorFormats = {f.color.spec().format};
    water.depthFormat = kVkDepthFormat;
    water.blend = true;  // colour by the water's alpha; the frame's alpha stays 1
    VkPipelineDescription geometry = water;  // the mesh: the graph's vertex (and tessellation) stages
    geometry.vertexStride = static_cast<uint32_t>(8 * sizeof(float));
    geometry.attributes = waterAttributes;
    geometry.patches = tessellated;
    if (!deferred) {
      geometry.stages = waterStages;
      waterPipeline = createGraphicsPipeline(ctx.device(), geometry, "the graph's water surface");
      return;
    }
    // Deferred: the graph's fragment shader full-screen without depth test; its other
    // stages write the G-buffer behind the runtime's G-buffer fragment shader.
    water.stages = {sceneSpirv.fullscreenVertex};
    for (const auto& s : waterStages) (s.stage == ShaderStage::Fragment ? water.stages : geometry.stages).push_back(s);
    water.depthTest = false;
    waterPipeline = createGraphicsPipeline(ctx.device(), water, "the graph's deferred water pass (full-screen)");
    geometry.stages.push_back(sceneSpirv.waterGbufferFragment);
    Target* g = find(SceneSampler::WaterSurface);
    Target* n = find(SceneSampler::WaterNormalUv);
    if (!g || !n) throw std::logic_error("the plan runs deferred_water without the water G-buffer");
    geometry.colorFormats = {g->color.spec().format, n->color.spec().format};
    geometry.blend = false;
    gbufferPipeline = createGraphicsPipeline(ctx.device(), geometry, "the graph's water G-buffer");
    (void)manifest;
  }

  // --- Recording helpers.
  struct Attachment {
    VkImageOwner* image = nullptr;
    uint32_t layer = 0;
    bool clear = false;
    VkClearValue value{};
  };

  void beginRendering(const std::vector<Attachment>& colors, const Attachment& depth, int width, int height) {
    std::vector<VkRenderingAttachmentInfo> colorInfos;
    for (const Attachment& a : colors) {
      // A full barrier before each use (a cube map's later faces are other layers: the
      // barrier before its first face covers them).
      if (a.layer == 0) a.image->transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
      VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
      info.imageView = a.image->layerView(a.layer);
      info.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
      info.loadOp = a.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
      info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
      info.clearValue = a.value;
      colorInfos.push_back(info);
    }
    VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (depth.image) {
      depth.image->transition(cmd, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
      depthInfo.imageView = depth.image->layerView(0);
      depthInfo.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
      depthInfo.loadOp = depth.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
      depthInfo.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
      depthInfo.clearValue.depthStencil = {1.0f, 0};
    }
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {static_cast<uint32_t>(width), static_cast<uint32_t>(height)}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = static_cast<uint32_t>(colorInfos.size());
    ri.pColorAttachments = colorInfos.data();
    ri.pDepthAttachment = depth.image ? &depthInfo : nullptr;
    vkCmdBeginRendering(cmd, &ri);
    // GL's viewport: framebuffer row y is GL's window row y (see vk_renderer.h).
    VkViewport viewport{0, 0, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {static_cast<uint32_t>(width), static_cast<uint32_t>(height)}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
  }

  // A target's colour (cleared to opaque black when `clearColor`) and depth (cleared to 1).
  void beginTarget(Target& t, bool clearColor) {
    std::vector<Attachment> colors;
    if (t.color) colors.push_back({&t.color, 0, clearColor, VkClearValue{{{0, 0, 0, 1}}}});
    beginRendering(colors, {t.depth ? &t.depth : nullptr, 0, true, {}}, t.spec.width, t.spec.height);
  }

  void drawSky(const Target& t, const glm::mat4& vpGl) {
    if (!settings.scene.drawScene) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scenePipeline(true, t));
    // The sky reconstructs view directions from GL's NDC (z from -1 to 1) and sits at
    // depth 1 in either API: it takes the uncorrected matrix.
    SkyConstants c{glm::mat4(glm::inverse(glm::dmat4(vpGl))), sun};  // in double, as the GL runtime's
    vkCmdPushConstants(cmd, sceneLayout.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof c, &c);
    vkCmdDraw(cmd, 3, 1, 0, 0);
  }

  // Keeps the side where dot(plane, (p, 1)) >= 0; `vpGl` without the depth correction.
  void drawOpaque(const Target& t, const glm::mat4& vpGl, const glm::vec4& plane) {
    if (!settings.scene.drawScene) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scenePipeline(false, t));
    OpaqueConstants c{vulkanDepthRangeCorrection() * vpGl, plane, sun};
    vkCmdPushConstants(cmd, sceneLayout.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof c, &c);
    bindMesh(sceneMesh);
    vkCmdDrawIndexed(cmd, sceneMesh.indexCount, 1, 0, 0, 0);
  }

  void bindMesh(const VkMesh& m) {
    VkBuffer b = m.vertices.buffer();
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &b, &offset);
    vkCmdBindIndexBuffer(cmd, m.indices.buffer(), 0, VK_INDEX_TYPE_UINT32);
  }

  void readyWaterTextures() {
    for (VkImageOwner* image : bindings->sampledSceneImages()) image->transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }

  float cameraSide() const { return camera.position.y >= 0.0f ? 1.0f : -1.0f; }
  static inline const glm::vec4 kNoClip = glm::vec4(0, 0, 0, 1);

  // --- One function per pass kind (PassKind), run in the plan's order, as the GL runtime.
  // Every ocean's cascades at the scene's time (runtime/vk_ocean_simulation.h).
  void oceanSimulationPass() {
    oceans->setFoamHistory(settings.animation ? FoamHistory::Continue : FoamHistory::Replay);
    oceans->record(cmd, settings.scene.time);
  }

  void environmentPass() {
    Target& t = *find(SceneSampler::Environment);
    static const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    glm::mat4 p = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f);
    t.color.transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    for (uint32_t f = 0; f < 6; ++f) {
      // Opaque black stays where nothing is drawn (drawScene false).
      beginRendering({{&t.color, f, true, VkClearValue{{{0, 0, 0, 1}}}}}, {}, t.spec.width, t.spec.height);
      drawSky(t, p * glm::lookAt(glm::vec3(0.0f), dirs[f], ups[f]));
      vkCmdEndRendering(cmd);
    }
  }

  void depthPrepass() {
    Target& t = *find(SceneSampler::SceneDepth);
    beginTarget(t, false);
    drawOpaque(t, viewProjection, kNoClip);
    vkCmdEndRendering(cmd);
  }

  // The camera mirrored about y = 0; only what is on the camera's side of the water is reflected.
  void planarReflectionPass() {
    Target& t = *find(SceneSampler::Reflection);
    beginTarget(t, true);
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(1, -1, 1));
    const glm::mat4 mirrored = viewProjection * mirror;
    const glm::vec4 waterPlane(0, cameraSide(), 0, 0);
    if (settings.obliqueReflection) {
      glm::mat4 oblique = obliqueProjection(projection, planeToEye(view * mirror, waterPlane));
      drawOpaque(t, oblique * view * mirror, kNoClip);
    } else {
      drawOpaque(t, mirrored, waterPlane);
    }
    drawSky(t, mirrored);
    vkCmdEndRendering(cmd);
  }

  void refractionPass() {
    Target& t = *find(SceneSampler::Refraction);
    beginTarget(t, true);
    drawOpaque(t, viewProjection, glm::vec4(0, -cameraSide(), 0, 0));
    drawSky(t, viewProjection);
    vkCmdEndRendering(cmd);
  }

  void opaqueScenePass() {
    Target& t = frame();
    beginTarget(t, true);
    drawOpaque(t, viewProjection, kNoClip);
    drawSky(t, viewProjection);
    vkCmdEndRendering(cmd);
  }

  void sceneColorCopyPass() {
    Target& copy = *find(SceneSampler::SceneColor);
    frame().color.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    copy.color.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    if (copy.spec.width == settings.width && copy.spec.height == settings.height) {
      VkImageCopy region{};
      region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.extent = {static_cast<uint32_t>(settings.width), static_cast<uint32_t>(settings.height), 1};
      vkCmdCopyImage(cmd, frame().color.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, copy.color.image(),
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      return;
    }
    // A reduced scene resolution (manifest "pass_scales"): the frame shrunk by a blit,
    // filtered as the GL runtime's glBlitFramebuffer (nearest where float cannot be).
    VkImageBlit blit{};
    blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {settings.width, settings.height, 1};
    blit.dstOffsets[1] = {copy.spec.width, copy.spec.height, 1};
    vkCmdBlitImage(cmd, frame().color.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, copy.color.image(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                   sampledNearest(copy.spec, targets.floatLinear()) ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
  }

  // The water G-buffer: where no water is, the surface's depth w stays 1.
  void deferredWaterPass() {
    readyWaterTextures();
    Target& g = *find(SceneSampler::WaterSurface);
    Target& n = *find(SceneSampler::WaterNormalUv);
    beginRendering({{&g.color, 0, true, VkClearValue{{{0, 0, 0, 1}}}}, {&n.color, 0, true, VkClearValue{{{0, 0, 0, 0}}}}},
                   {&g.depth, 0, true, {}}, g.spec.width, g.spec.height);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, gbufferPipeline.get());
    bindings->bind(cmd, waterLayout.get());
    bindMesh(waterMesh);
    vkCmdDrawIndexed(cmd, waterMesh.indexCount, 1, 0, 0, 0);
    vkCmdEndRendering(cmd);
  }

  void waterSurfacePass() {
    readyWaterTextures();
    Target& t = frame();
    beginRendering({{&t.color, 0, false, {}}}, {&t.depth, 0, false, {}}, t.spec.width, t.spec.height);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, waterPipeline.get());
    bindings->bind(cmd, waterLayout.get());
    if (deferred) {
      vkCmdDraw(cmd, 3, 1, 0, 0);  // full-screen: the graph shades every pixel from textures
    } else {
      bindMesh(waterMesh);
      vkCmdDrawIndexed(cmd, waterMesh.indexCount, 1, 0, 0, 0);
    }
    vkCmdEndRendering(cmd);
  }

  // The frame's linear radiance through the view into the 8-bit display image.
  void outputTransformPass() {
    Target& d = *picture();
    frame().color.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    beginRendering({{&d.color, 0, false, {}}}, {}, d.spec.width, d.spec.height);
    output->draw(cmd, settings.view);
    vkCmdEndRendering(cmd);
  }

  FrameValues frameValues() const {
    FrameValues f;
    f.camera = camera;
    f.view = view;
    f.projection = vulkanDepthRangeCorrection() * projection;
    f.viewProjection = vulkanDepthRangeCorrection() * viewProjection;
    f.sun = sun;
    f.time = settings.scene.time;
    f.width = settings.width;
    f.height = settings.height;
    return f;
  }

  double renderOneFrame() {
    using PassFunction = void (Impl::*)();
    static constexpr PassFunction kPassFunctions[] = {
        &Impl::oceanSimulationPass,
        &Impl::environmentPass, &Impl::depthPrepass,       &Impl::planarReflectionPass, &Impl::refractionPass,
        &Impl::opaqueScenePass, &Impl::sceneColorCopyPass, &Impl::deferredWaterPass,    &Impl::waterSurfacePass,
        &Impl::outputTransformPass,
    };
    static_assert(std::size(kPassFunctions) == kRenderPassCount);
    auto start = std::chrono::steady_clock::now();
    bindings->writeUniforms(frameValues());
    try {
      ctx.submit([&](VkCommandBuffer c) {
        cmd = c;
        for (PassKind pass : plan.passes) (this->*kPassFunctions[static_cast<size_t>(pass)])();
        cmd = VK_NULL_HANDLE;
      });
    } catch (...) {
      if (oceans) oceans->forgetHeldTime();  // what it recorded may not have run
      throw;
    }
    auto end = std::chrono::steady_clock::now();
    ctx.throwOnValidationMessages("rendering a frame");
    return std::chrono::duration<double, std::milli>(end - start).count();
  }

  // Level 0 of an image, rows top to bottom (Vulkan's row 0 is GL's bottom row here).
  template <typename T>
  std::vector<T> readFlipped(VkImageOwner& image) const {
    std::vector<unsigned char> bytes = readBack(ctx, image);
    ctx.throwOnValidationMessages("reading the frame back");
    const size_t rowBytes = bytes.size() / image.spec().height;
    std::vector<T> out(bytes.size() / sizeof(T));
    for (uint32_t y = 0; y < image.spec().height; ++y)
      std::memcpy(reinterpret_cast<unsigned char*>(out.data()) + y * rowBytes,
                  bytes.data() + (image.spec().height - 1 - y) * rowBytes, rowBytes);
    return out;
  }
};

VkRenderer::VkRenderer(VkContext& context, const Manifest& manifest, std::vector<VkShaderCode> water,
                       const RenderSettings& settings, const std::map<std::string, TextureOrigin>& origins,
                       std::shared_ptr<VkOceanSimulation> oceans)
    : impl_(std::make_unique<Impl>(context)) {
  Impl& r = *impl_;
  r.settings = settings;
  auto cam = settings.customCamera ? settings.customCamera : cameraPreset(settings.camera);
  if (!cam) manifestError("unknown camera preset '" + settings.camera + "'");
  r.camera = *cam;
  r.view = r.camera.view();
  r.projection = r.camera.projection(static_cast<float>(settings.width) / static_cast<float>(std::max(settings.height, 1)));
  r.viewProjection = r.projection * r.view;
  r.sun = sunDirection(settings.scene);
  refuseBuoys(settings.scene);

  r.plan = planPasses(manifest, planOptionsFor(settings));
  r.memory.emplace(rendererBytes(r.plan, settings.floatColor),
                   "render targets and read-back at " + std::to_string(settings.width) + "x" + std::to_string(settings.height));
  r.deferred = r.plan.runs(PassKind::DeferredWater);

  // The grid's attributes the graph reads, at the manifest's locations.
  for (const AttributeInfo& a : manifest.attributes) {
    if (a.name == iface::kPositionAttribute && a.location == iface::kPositionLocation)
      r.waterAttributes.push_back({static_cast<uint32_t>(a.location), 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
    else if (a.name == iface::kNormalAttribute && a.location == iface::kNormalLocation)
      r.waterAttributes.push_back({static_cast<uint32_t>(a.location), 0, VK_FORMAT_R32G32B32_SFLOAT, 12});
    else if (a.name == iface::kUvAttribute && a.location == iface::kUvLocation)
      r.waterAttributes.push_back({static_cast<uint32_t>(a.location), 0, VK_FORMAT_R32G32_SFLOAT, 24});
    else
      manifestError("the water grid has no attribute " + a.name + " at location " + std::to_string(a.location));
  }
  bool vertex = false, fragment = false;
  for (const auto& s : water) {
    r.tessellated |= s.stage == ShaderStage::TessControl || s.stage == ShaderStage::TessEvaluation;
    vertex |= s.stage == ShaderStage::Vertex;
    fragment |= s.stage == ShaderStage::Fragment;
  }
  if (!vertex || !fragment) manifestError("the vk450 target lacks a vertex or fragment shader");
  r.waterStages = std::move(water);

  // The G-buffer shader reads the graph's varyings where its vertex stage writes them: at
  // their index in the manifest's varyings.
  GbufferInputLocations gbuffer;
  if (r.deferred) {
    auto location = [&](const char* name) {
      for (size_t i = 0; i < manifest.varyings.size(); ++i)
        if (manifest.varyings[i].name == name) return static_cast<int>(i);
      manifestError(std::string("the deferred water's vertex stage writes no ") + name);
    };
    gbuffer = {location("v_world_position"), location("v_normal"), location("v_uv")};
  }
  r.sceneSpirv = compileSceneSpirv(gbuffer);

  r.targets.create(r.ctx, r.plan);
  r.sceneMesh = uploadVkMesh(context, buildSceneMesh());
  int gridQuads = settings.waterGridQuads;
  if (r.tessellated && manifest.tessellation) gridQuads = tessellatedGridQuads(gridQuads, manifest.tessellation->settings.factor);
  r.waterMesh = uploadVkMesh(context, buildWaterGrid(gridQuads));
  if (r.plan.runs(PassKind::OceanSimulation)) {
    if (oceans && oceans->identity() != VkOceanSimulation::identity(manifest.oceans, manifest.textures))
      throw std::logic_error("a shared ocean simulation simulates other oceans than this manifest's");
    r.oceans = oceans ? std::move(oceans) : std::make_shared<VkOceanSimulation>(context, manifest.oceans, manifest.textures);
  }
  r.bindings = std::make_unique<VkWaterBindings>(
      context, manifest,
      [&r](SceneSampler s) {
        VkWaterBindings::SceneImage out;
        Impl::Target* t = r.find(s);
        if (!t) return out;
        out.image = t->color ? &t->color : &t->depth;
        out.nearest = sampledNearest(t->spec, r.targets.floatLinear());
        return out;
      },
      [&r](const OceanMapRef& ref) { return r.oceans ? &r.oceans->map(ref) : nullptr; }, origins);
  r.sceneLayout = r.makeLayout({}, kPushConstantBytes);
  r.createWaterPipelines(manifest);
  if (Impl::Target* d = r.plan.runs(PassKind::OutputTransform) ? r.picture() : nullptr)
    r.output = std::make_unique<VkOutputTransform>(context, r.sceneSpirv, r.frame().color, d->color.spec().format);
  // Every image starts in a defined layout, so the first frame's barriers name real ones.
  context.submit([&](VkCommandBuffer c) {
    for (auto& t : r.targets) {
      if (t.color) t.color.transition(c, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
      if (t.depth) t.depth.transition(c, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
  });
  context.throwOnValidationMessages("building the Vulkan renderer");
}

VkRenderer::~VkRenderer() {
  if (impl_) vkDeviceWaitIdle(impl_->ctx.device());
}

double VkRenderer::renderFrame() { return impl_->renderOneFrame(); }

void VkRenderer::setCamera(const Camera& camera) {
  Impl& r = *impl_;
  r.camera = camera;
  r.view = camera.view();
  r.projection = camera.projection(static_cast<float>(r.settings.width) / static_cast<float>(std::max(r.settings.height, 1)));
  r.viewProjection = r.projection * r.view;
}

void VkRenderer::setScene(const SceneOptions& scene) {
  refuseBuoys(scene);
  impl_->settings.scene = scene;
  impl_->sun = sunDirection(scene);
}

void VkRenderer::setView(const ViewTransform& view) { impl_->settings.view = view; }

Image VkRenderer::readRgba8() const {
  Impl::Target* d = impl_->picture();
  if (!d) throw RuntimeError(RuntimeError::Kind::Manifest, "an 8-bit read-back needs a renderer made without floatColor");
  Image img;
  img.width = impl_->settings.width;
  img.height = impl_->settings.height;
  img.rgba8 = impl_->readFlipped<uint8_t>(d->color);
  return img;
}

Image VkRenderer::readRgba32f() const {
  Image img;
  img.width = impl_->settings.width;
  img.height = impl_->settings.height;
  auto& color = const_cast<VkImageOwner&>(impl_->frame().color);
  if (impl_->frame().spec.color == ColorFormat::Rgba32f) {
    img.rgba32f = impl_->readFlipped<float>(color);
  } else {  // RGBA16F: widened exactly
    for (uint16_t h : impl_->readFlipped<uint16_t>(color)) img.rgba32f.push_back(glm::unpackHalf1x16(h));
  }
  return img;
}

std::vector<float> VkRenderer::readDepth() const {
  return impl_->readFlipped<float>(const_cast<VkImageOwner&>(impl_->frame().depth));
}

const PassPlan& VkRenderer::plan() const { return impl_->plan; }
std::shared_ptr<VkOceanSimulation> VkRenderer::oceanSimulation() const { return impl_->oceans; }

bool VkRenderer::samplesNearest(SceneSampler s) const {
  const Impl::Target* t = impl_->find(s);
  if (!t) throw std::logic_error("samplesNearest: the plan has no target for this sampler");
  return sampledNearest(t->spec, impl_->targets.floatLinear());
}
int VkRenderer::createdTargetCount() const { return static_cast<int>(impl_->targets.size()); }
size_t VkRenderer::createdTargetBytes() const {
  size_t n = 0;
  for (const auto& t : impl_->targets) n += (t.color ? t.color.bytes() : 0) + (t.depth ? t.depth.bytes() : 0);
  return n;
}

}  // namespace wg::rt
