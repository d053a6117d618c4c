// A small WebGPU runner of a compiled graph's GRAPH.wgsl (watergraph compile --target wgsl):
// runs the passes of the manifest in the runtime's order (runtime/renderer.cpp) — the scene
// passes (watergraph-webgpu-passes.js) with the runtime's own shaders, then the water, forward
// or deferred — builds the water's bind group from the manifest's "webgpu" section, fills the
// uniform buffer at the offsets it states, and reads the frame back: RGBA16F for pictures,
// RGBA32F for `watergraph check --target wgsl` (watergraph-webgpu-check.js). Conventions
// (manifest "webgpu".conventions): GL matrices, y negated in clip space by every module, so a
// target's row 0 is the view's bottom row and frontFace is "cw".
import { beginTargetPass, createTargets, runScenePass, ScenePasses } from './watergraph-webgpu-passes.js';
import { fullChainLevels, generateMipmaps } from './watergraph-webgpu-mipmaps.js';

export class WebgpuRunnerError extends Error {
  constructor(message) {
    super(message);
    this.name = 'WebgpuRunnerError';
  }
}

const FORMATS = { float32: 4, float32x2: 8, float32x3: 12, float32x4: 16 };
const ADDRESS = { repeat: 'repeat', clamp: 'clamp-to-edge', mirror: 'mirror-repeat' };

// Writes one uniform's value (a number, an array, or an object with toArray()) at its offset.
function writeUniform(view, member, value) {
  const v = typeof value === 'number' || typeof value === 'boolean' ? [Number(value)]
    : Array.isArray(value) || ArrayBuffer.isView(value) ? Array.from(value) : value.toArray();
  const at = member.offset;
  switch (member.type) {
    case 'int': view.setInt32(at, v[0], true); return;
    case 'bool': view.setUint32(at, v[0] ? 1 : 0, true); return;
    case 'mat3':  // three columns, each padded to 16 bytes
      for (let c = 0; c < 3; ++c) for (let r = 0; r < 3; ++r) view.setFloat32(at + 16 * c + 4 * r, v[3 * c + r], true);
      return;
    default:
      for (let i = 0; i < v.length; ++i) view.setFloat32(at + 4 * i, v[i], true);
  }
}

function halfToFloat(h) {
  const s = h & 0x8000 ? -1 : 1, e = (h >> 10) & 0x1f, f = h & 0x3ff;
  if (e === 0) return s * f * 2 ** -24;
  if (e === 31) return f ? NaN : s * Infinity;
  return s * (1 + f / 1024) * 2 ** (e - 15);
}

const srgbEncode = (c) => (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055);

// The texture of a file the manifest names: an ImageBitmap, bottom row first, or its texels as
// {width, height, rgba: Uint8Array}, row 0 first (as the runtime uploads them).
function fileTexture(device, t, bitmap, colorSpace, mipmapped) {
  const format = colorSpace === 'srgb' ? 'rgba8unorm-srgb' : 'rgba8unorm';
  const mipLevelCount = mipmapped ? fullChainLevels(bitmap.width, bitmap.height) : 1;
  const tex = device.createTexture({ size: [bitmap.width, bitmap.height], format, mipLevelCount,
    usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST | GPUTextureUsage.RENDER_ATTACHMENT });
  if (bitmap.rgba) device.queue.writeTexture({ texture: tex }, bitmap.rgba, { bytesPerRow: 4 * bitmap.width }, [bitmap.width, bitmap.height]);
  else device.queue.copyExternalImageToTexture({ source: bitmap }, { texture: tex }, [bitmap.width, bitmap.height]);
  if (mipLevelCount > 1) generateMipmaps(device, tex, format, mipLevelCount);
  return tex.createView();
}

// The water's bind group: the uniform buffer, each file texture from `textures`, each scene
// texture from `resources` (createTargets; sampled as the runtime does: clamped, nearest where
// it is depth or 32-bit float, so unfilterable here).
function waterBindGroup(device, manifest, uniformValue, uniformBytes, textures, resources, ocean) {
  const webgpu = manifest.webgpu;
  const entries = [], layoutEntries = [];
  const visibility = GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT;
  for (const b of webgpu.bindings) {
    if (b.kind === 'uniform_buffer') {
      const buffer = device.createBuffer({ size: webgpu.uniform_buffer.size, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
      let bytes = uniformBytes;
      if (!bytes) {
        bytes = new ArrayBuffer(webgpu.uniform_buffer.size);
        const view = new DataView(bytes);
        for (const m of webgpu.uniform_buffer.members) writeUniform(view, m, uniformValue(m.name));
      } else if (bytes.byteLength !== webgpu.uniform_buffer.size) {
        throw new WebgpuRunnerError(`the uniform buffer holds ${webgpu.uniform_buffer.size} bytes; ${bytes.byteLength} were given`);
      }
      device.queue.writeBuffer(buffer, 0, bytes);
      entries.push({ binding: b.binding, resource: { buffer } });
      layoutEntries.push({ binding: b.binding, visibility, buffer: { type: 'uniform' } });
      continue;
    }
    const t = manifest.textures.find((x) => x.name === b.texture);
    if (t.ocean) {
      // A map of the ocean simulation (watergraph-webgpu-ocean.js), 32-bit float read with
      // textureLoad: unfilterable, its sampler (unused) nearest.
      if (!ocean) throw new WebgpuRunnerError(`texture ${t.name}: an ocean map needs the ocean simulation (options.ocean)`);
      if (b.kind === 'sampler') {
        entries.push({ binding: b.binding, resource: device.createSampler({ magFilter: 'nearest', minFilter: 'nearest' }) });
        layoutEntries.push({ binding: b.binding, visibility, sampler: { type: 'non-filtering' } });
      } else {
        entries.push({ binding: b.binding, resource: ocean.map(t.ocean).createView() });
        layoutEntries.push({ binding: b.binding, visibility, texture: { sampleType: 'unfilterable-float' } });
      }
      continue;
    }
    const scene = t.resource !== undefined ? resources[t.name] : undefined;
    if (t.resource !== undefined && !scene) throw new WebgpuRunnerError(`texture ${t.name}: no pass of the plan makes the scene resource ${t.resource}`);
    if (b.kind === 'sampler') {
      let s;
      if (scene) {
        const filter = scene.nearest ? 'nearest' : 'linear';
        s = device.createSampler({ addressModeU: 'clamp-to-edge', addressModeV: 'clamp-to-edge', addressModeW: 'clamp-to-edge', magFilter: filter, minFilter: filter });
        layoutEntries.push({ binding: b.binding, visibility, sampler: { type: scene.nearest ? 'non-filtering' : 'filtering' } });
      } else {
        const sampler = { wrap: 'repeat', filter: 'linear', ...(t.sampler ?? {}) };
        const filter = sampler.filter === 'nearest' ? 'nearest' : 'linear';
        // Mipmapped: trilinear, as the runtime's GL_LINEAR_MIPMAP_LINEAR.
        const mipmapFilter = sampler.filter === 'mipmapped' ? 'linear' : 'nearest';
        s = device.createSampler({ addressModeU: ADDRESS[sampler.wrap], addressModeV: ADDRESS[sampler.wrap], magFilter: filter, minFilter: filter, mipmapFilter });
        layoutEntries.push({ binding: b.binding, visibility, sampler: { type: 'filtering' } });
      }
      entries.push({ binding: b.binding, resource: s });
      continue;
    }
    if (scene) {
      if (b.kind !== (scene.cube ? 'texture_cube' : 'texture_2d')) throw new WebgpuRunnerError(`texture ${t.name}: binding kind ${b.kind} does not fit its scene target`);
      entries.push({ binding: b.binding, resource: scene.view, gbuffer: scene.gbuffer });
      layoutEntries.push({ binding: b.binding, visibility,
        texture: { sampleType: scene.nearest ? 'unfilterable-float' : 'float', viewDimension: scene.cube ? 'cube' : '2d' } });
      continue;
    }
    const bitmap = textures[t.name];
    if (b.kind !== 'texture_2d' || !bitmap) throw new WebgpuRunnerError(`texture ${t.name} (${t.source || 'a scene texture'}) is not given to this runner`);
    entries.push({ binding: b.binding, resource: fileTexture(device, t, bitmap, t.sampler?.color_space, t.sampler?.filter === 'mipmapped') });
    layoutEntries.push({ binding: b.binding, visibility, texture: { sampleType: 'float' } });
  }
  const layout = device.createBindGroupLayout({ entries: layoutEntries });
  const group = device.createBindGroup({ layout, entries: entries.map(({ binding, resource }) => ({ binding, resource })) });
  // For the G-buffer pass, which renders into the G-buffer textures: WebGPU forbids sampling a
  // texture a pass writes (GL allows it while the program does not read it), so there a 1x1
  // texture of the same format stands in for them.
  const gbufferGroup = device.createBindGroup({ layout, entries: entries.map(({ binding, resource, gbuffer }) => {
    if (!gbuffer) return { binding, resource };
    const stand = device.createTexture({ size: [1, 1], format: gbuffer, usage: GPUTextureUsage.TEXTURE_BINDING });
    return { binding, resource: stand.createView() };
  }) });
  return { layout, group, gbufferGroup };
}

// Deferred water's full-screen triangle (the runtime's fullscreen_vertex), writing zeros to the
// graph's varyings: the graph's fragment stage reads the G-buffer instead, but WebGPU wants
// every input it declares written.
const WGSL_TYPES = { float: 'f32', vec2: 'vec2<f32>', vec3: 'vec3<f32>', vec4: 'vec4<f32>' };
function fullscreenVertexWgsl(manifest) {
  const fields = manifest.webgpu.varyings.map((v) => {
    const type = WGSL_TYPES[manifest.varyings.find((x) => x.name === v.name)?.type];
    if (!type) throw new WebgpuRunnerError(`varying ${v.name}: its type is not in the manifest's "varyings"`);
    return { ...v, type };
  });
  return `struct WgFullscreenOut {\n  @builtin(position) position: vec4<f32>,\n${fields.map((f) => `  @location(${f.location}) ${f.name}: ${f.type},\n`).join('')}}\n` +
    '@vertex fn main(@builtin(vertex_index) i: u32) -> WgFullscreenOut {\n  var o: WgFullscreenOut;\n' +
    '  // One triangle covering the viewport; y negated as every module here does.\n' +
    '  o.position = vec4<f32>(select(-1.0, 3.0, i == 1u), -select(-1.0, 3.0, i == 2u), 0.5, 1.0);\n  return o;\n}\n';
}

async function compiledModule(device, code, what) {
  const module = device.createShaderModule({ code, label: what });
  const errors = (await module.getCompilationInfo()).messages.filter((m) => m.type === 'error');
  if (errors.length) throw new WebgpuRunnerError(`Tint rejected ${what}: ${errors.map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`).join('; ')}`);
  return module;
}

// The water mesh's vertex buffers, in the manifest's "webgpu".vertex_inputs order.
function waterGeometry(device, webgpu, geometry) {
  const arrays = { a_position: geometry.position, a_normal: geometry.normal, a_uv: geometry.uv };
  const buffers = [], layouts = [];
  for (const input of webgpu.vertex_inputs) {
    const data = arrays[input.name];
    if (!data) throw new WebgpuRunnerError(`no geometry for vertex input ${input.name}`);
    const buffer = device.createBuffer({ size: data.byteLength, usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(buffer, 0, data);
    buffers.push(buffer);
    layouts.push({ arrayStride: FORMATS[input.format], attributes: [{ shaderLocation: input.location, offset: 0, format: input.format }] });
  }
  const index = device.createBuffer({ size: geometry.index.byteLength, usage: GPUBufferUsage.INDEX | GPUBufferUsage.COPY_DST });
  device.queue.writeBuffer(index, 0, geometry.index);
  return { buffers, layouts, index, count: geometry.index.length };
}

function drawWaterMesh(pass, mesh) {
  mesh.buffers.forEach((b, i) => pass.setVertexBuffer(i, b));
  pass.setIndexBuffer(mesh.index, 'uint32');
  pass.drawIndexed(mesh.count);
}

// The colour blended by the water's alpha, the frame's alpha kept opaque (the runtime's
// glBlendFuncSeparate(SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ONE, ONE_MINUS_SRC_ALPHA)).
const WATER_BLEND = { color: { srcFactor: 'src-alpha', dstFactor: 'one-minus-src-alpha' },
  alpha: { srcFactor: 'one', dstFactor: 'one-minus-src-alpha' } };

// The frame formats this runner renders and reads back.
const FRAME_FORMATS = { rgba16f: { format: 'rgba16float', bytes: 8 }, rgba32f: { format: 'rgba32float', bytes: 16 } };

// Renders one frame of a graph and reads it back. Options:
//   manifest, wgsl: the compiled graph; plan: clients/three's planPasses(manifest, description,
//   {width, height, environmentSize}); description: the scene description (`watergraph scene`);
//   sceneShaders: sceneShadersWgsl(description, naga, gbuffer inputs); drawScene: false draws
//   no scene (the runtime's `--scene none`: scene targets cleared only); camera: {view,
//   projection, position} as OpenGL matrices (column-major) and the eye; uniformValue(name): each
//   water uniform's value, or uniformBytes: the whole uniform buffer (an ArrayBuffer laid out
//   as "webgpu".uniform_buffer states); sun: the direction towards the sun for the scene's
//   shaders (default the description's sun_direction); geometry: the water grid (Float32Arrays position, normal, uv and a
//   Uint32Array index); textures: a node texture's name -> ImageBitmap (bottom row first);
//   ocean, time: for a manifest with "oceans", its WebgpuOceanSimulation
//   (watergraph-webgpu-ocean.js) and the frame's time in seconds; keepAlive: for a series of
//   frames of one graph (check's), an object given to each: it holds the scene passes (reused
//   while the description and scene shaders are the same objects) and the frame's modules and
//   pipelines until the next frame has made its own, since a WebGPU implementation hands back
//   the pipeline it made for the same descriptor while that one lives (Dawn does): the frames
//   compile their shaders once instead of once each.
// The plan's frame is RGBA16F or RGBA32F (planPasses' frameFormat); an RGBA32F frame needs a
// device with "float32-blendable" (the water blends into it).
// Returns {linear: Float32Array RGBA with row 0 at the bottom, srgb8: Uint8ClampedArray RGBA top
// row first, through clamp and the sRGB encoding}.
export async function renderGraph(device, options) {
  const { manifest, wgsl, plan, description, sceneShaders, drawScene = true, camera, uniformValue, geometry, textures = {},
    ocean = null, time = 0, uniformBytes = null, sun = null, keepAlive = null } = options;
  if (manifest.oceans && !ocean) throw new WebgpuRunnerError(`graph '${manifest.graph}' has a spectral ocean: give its simulation (options.ocean)`);
  const webgpu = manifest.webgpu;
  if (!webgpu) throw new WebgpuRunnerError(`graph '${manifest.graph}' was not compiled for wgsl (--target wgsl)`);
  const deferred = plan.passes.includes('deferred_water');
  const frameTarget = plan.targets.find((t) => t.name === 'frame');
  const { width, height } = frameTarget;
  const frame = FRAME_FORMATS[frameTarget.color];
  if (!frame) throw new WebgpuRunnerError(`the plan's frame is ${frameTarget.color}; this runner renders RGBA16F or RGBA32F`);
  if (frame.format === 'rgba32float' && !device.features.has('float32-blendable'))
    throw new WebgpuRunnerError('an RGBA32F frame needs the device feature float32-blendable (the water blends into the frame)');
  device.pushErrorScope('validation');
  const module = await compiledModule(device, wgsl, `${manifest.graph}.wgsl`);
  const { targets, resources } = createTargets(device, plan);
  const kept = keepAlive?.scene;
  const scene = !drawScene ? null
    : kept && kept.description === description && kept.shaders === sceneShaders ? kept : new ScenePasses(device, description, sceneShaders);
  const made = [module];  // what keepAlive holds until the next frame
  if (scene && sun) scene.sun = sun;
  const water = waterBindGroup(device, manifest, uniformValue, uniformBytes, textures, resources, ocean);
  const mesh = waterGeometry(device, webgpu, geometry);
  const layout = device.createPipelineLayout({ bindGroupLayouts: [water.layout] });
  const primitive = { topology: 'triangle-list', cullMode: 'none', frontFace: 'cw' };
  const waterPipeline = device.createRenderPipeline({
    layout,
    vertex: deferred ? { module: await compiledModule(device, fullscreenVertexWgsl(manifest), 'the full-screen vertex stage'), entryPoint: 'main' }
      : { module, entryPoint: webgpu.entry_points.vertex, buffers: mesh.layouts },
    fragment: { module, entryPoint: webgpu.entry_points.fragment, targets: [{ format: frame.format, blend: WATER_BLEND }] },
    primitive,
    // Deferred water shades every pixel with the depth test off (the G-buffer has the surface).
    depthStencil: { format: 'depth32float', depthWriteEnabled: !deferred, depthCompare: deferred ? 'always' : 'less-equal' },
  });
  made.push(waterPipeline);

  const encoder = device.createCommandEncoder();
  const clear = description?.clear_color ?? [0, 0, 0, 1];
  for (const passName of plan.passes) {
    if (passName === 'output_transform') continue;  // applied on the read-back frame below
    if (passName === 'ocean_simulation') {  // every ocean's maps at the frame's time, first
      ocean.encode(encoder, time);
      continue;
    }
    if (passName === 'deferred_water') {
      // The G-buffer: the graph's vertex stage (displacement included) writes the surface's
      // position and depth, normal and uv; where no water is, depth w = 1.
      if (!sceneShaders?.water_gbuffer_fragment) throw new WebgpuRunnerError('deferred water needs the runtime\'s G-buffer shader (sceneShaders)');
      const gbuffer = await compiledModule(device, sceneShaders.water_gbuffer_fragment.wgsl, 'the runtime\'s water G-buffer');
      const pipeline = device.createRenderPipeline({
        layout, primitive,
        vertex: { module, entryPoint: webgpu.entry_points.vertex, buffers: mesh.layouts },
        fragment: { module: gbuffer, entryPoint: 'main', targets: [{ format: 'rgba32float' }, { format: 'rgba32float' }] },
        depthStencil: { format: 'depth32float', depthWriteEnabled: true, depthCompare: 'less-equal' },
      });
      made.push(gbuffer, pipeline);
      const position = targets.water_position, normal = targets.water_normal;
      const pass = encoder.beginRenderPass({
        colorAttachments: [{ view: position.color.createView(), clearValue: [0, 0, 0, 1], loadOp: 'clear', storeOp: 'store' },
          { view: normal.color.createView(), clearValue: [0, 0, 0, 0], loadOp: 'clear', storeOp: 'store' }],
        depthStencilAttachment: { view: position.depth.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' },
      });
      pass.setPipeline(pipeline);
      pass.setBindGroup(0, water.gbufferGroup);
      drawWaterMesh(pass, mesh);
      pass.end();
      continue;
    }
    if (passName === 'water_surface') {
      const pass = beginTargetPass(encoder, targets.frame, clear, { load: true });
      pass.setPipeline(waterPipeline);
      pass.setBindGroup(0, water.group);
      if (deferred) pass.draw(3);
      else drawWaterMesh(pass, mesh);
      pass.end();
      continue;
    }
    runScenePass(device, encoder, passName, { targets, scene, camera, description, frameFormat: frame.format });
  }
  const bytesPerRow = Math.ceil((width * frame.bytes) / 256) * 256;
  const readback = device.createBuffer({ size: bytesPerRow * height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
  encoder.copyTextureToBuffer({ texture: targets.frame.color }, { buffer: readback, bytesPerRow }, [width, height]);
  device.queue.submit([encoder.finish()]);
  if (keepAlive) {
    keepAlive.scene = scene;
    keepAlive.made = made;
  }
  const failure = await device.popErrorScope();
  if (failure) throw new WebgpuRunnerError(`WebGPU validation: ${failure.message}`);
  await readback.mapAsync(GPUMapMode.READ);
  const mapped = readback.getMappedRange().slice(0);
  readback.unmap();
  // Freed now, not when collected: check renders tens of frames a graph.
  readback.destroy();
  for (const entry of Object.values(targets)) {
    entry.color?.destroy();
    entry.depth?.destroy();
  }
  const halves = frame.bytes === 8 ? new Uint16Array(mapped) : null, floats = halves ? null : new Float32Array(mapped);
  const rowFloats = bytesPerRow / 4;
  const linear = new Float32Array(width * height * 4);
  const srgb8 = new Uint8ClampedArray(width * height * 4);
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width * 4; ++x) {
      const value = halves ? halfToFloat(halves[(y * bytesPerRow) / 2 + x]) : floats[y * rowFloats + x];
      linear[y * width * 4 + x] = value;
      // The output transform `render --tonemap none --exposure 0` applies: clamp, then sRGB (alpha kept).
      const c = Math.min(Math.max(Number.isNaN(value) ? 0 : value, 0), 1);
      srgb8[(height - 1 - y) * width * 4 + x] = Math.round(255 * ((x & 3) === 3 ? c : srgbEncode(c)));
    }
  }
  return { linear, srgb8 };
}
