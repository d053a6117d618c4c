// A small WebGPU runner of a compiled graph's GRAPH.wgsl (watergraph compile --target wgsl):
// builds the bind group from the manifest's "webgpu" section, fills the uniform buffer at the
// offsets it states, draws a mesh into an RGBA16F target with a depth buffer, and reads the
// frame back. It runs the water_surface pass alone: a graph whose manifest lists other passes
// (scene depth, reflection, environment ...) is refused with their names, since this runner
// renders no scene. Conventions (manifest "webgpu".conventions): GL matrices, y negated in
// clip space by the module, so the target's row 0 is the view's bottom row and frontFace is "cw".
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

// Renders the water alone over opaque black. `uniformValue(name)` gives each uniform's value;
// `geometry` holds Float32Arrays position, normal, uv and a Uint32Array index; `textures` maps a
// node texture's name to an ImageBitmap (bottom row first). Returns {linear: Float32Array RGBA
// with row 0 at the bottom, srgb8: Uint8ClampedArray RGBA top row first, through clamp and the
// sRGB encoding}.
export async function renderWaterOnly(device, { manifest, wgsl, uniformValue, geometry, width, height, textures = {} }) {
  const webgpu = manifest.webgpu;
  if (!webgpu) throw new WebgpuRunnerError(`graph '${manifest.graph}' was not compiled for wgsl (--target wgsl)`);
  const others = manifest.passes.filter((p) => p !== 'water_surface');
  if (others.length) throw new WebgpuRunnerError(`graph '${manifest.graph}' needs passes this runner does not render: ${others.join(', ')}`);
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ code: wgsl });
  const info = await module.getCompilationInfo();
  const errors = info.messages.filter((m) => m.type === 'error');
  if (errors.length) throw new WebgpuRunnerError(`Tint rejected ${manifest.graph}.wgsl: ${errors.map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`).join('; ')}`);

  const entries = [], layoutEntries = [];
  const visibility = GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT;
  for (const b of webgpu.bindings) {
    if (b.kind === 'uniform_buffer') {
      const buffer = device.createBuffer({ size: webgpu.uniform_buffer.size, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
      const bytes = new ArrayBuffer(webgpu.uniform_buffer.size);
      const view = new DataView(bytes);
      for (const m of webgpu.uniform_buffer.members) writeUniform(view, m, uniformValue(m.name));
      device.queue.writeBuffer(buffer, 0, bytes);
      entries.push({ binding: b.binding, resource: { buffer } });
      layoutEntries.push({ binding: b.binding, visibility, buffer: { type: 'uniform' } });
      continue;
    }
    const t = manifest.textures.find((x) => x.name === b.texture);
    const sampler = { wrap: 'repeat', filter: 'linear', color_space: 'linear', ...(t.sampler ?? {}) };
    if (b.kind === 'sampler') {
      if (sampler.filter === 'mipmapped') throw new WebgpuRunnerError(`texture ${t.name}: mipmapped sampling is not in this runner`);
      const filter = sampler.filter === 'nearest' ? 'nearest' : 'linear';
      const s = device.createSampler({ addressModeU: ADDRESS[sampler.wrap], addressModeV: ADDRESS[sampler.wrap], magFilter: filter, minFilter: filter });
      entries.push({ binding: b.binding, resource: s });
      layoutEntries.push({ binding: b.binding, visibility, sampler: { type: 'filtering' } });
      continue;
    }
    const bitmap = textures[t.name];
    if (b.kind !== 'texture_2d' || !bitmap) throw new WebgpuRunnerError(`texture ${t.name} (${t.source || 'a scene texture'}) is not given to this runner`);
    const format = sampler.color_space === 'srgb' ? 'rgba8unorm-srgb' : 'rgba8unorm';
    const tex = device.createTexture({ size: [bitmap.width, bitmap.height], format,
      usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST | GPUTextureUsage.RENDER_ATTACHMENT });
    device.queue.copyExternalImageToTexture({ source: bitmap }, { texture: tex }, [bitmap.width, bitmap.height]);
    entries.push({ binding: b.binding, resource: tex.createView() });
    layoutEntries.push({ binding: b.binding, visibility, texture: { sampleType: 'float' } });
  }
  const bindGroupLayout = device.createBindGroupLayout({ entries: layoutEntries });
  const bindGroup = device.createBindGroup({ layout: bindGroupLayout, entries });

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

  const pipeline = device.createRenderPipeline({
    layout: device.createPipelineLayout({ bindGroupLayouts: [bindGroupLayout] }),
    vertex: { module, entryPoint: webgpu.entry_points.vertex, buffers: layouts },
    fragment: { module, entryPoint: webgpu.entry_points.fragment, targets: [{ format: 'rgba16float' }] },
    primitive: { topology: 'triangle-list', cullMode: 'none', frontFace: 'cw' },
    depthStencil: { format: 'depth32float', depthWriteEnabled: true, depthCompare: 'less-equal' },
  });
  const color = device.createTexture({ size: [width, height], format: 'rgba16float', usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
  const depth = device.createTexture({ size: [width, height], format: 'depth32float', usage: GPUTextureUsage.RENDER_ATTACHMENT });
  const bytesPerRow = Math.ceil((width * 8) / 256) * 256;
  const readback = device.createBuffer({ size: bytesPerRow * height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
  const encoder = device.createCommandEncoder();
  const pass = encoder.beginRenderPass({
    colorAttachments: [{ view: color.createView(), clearValue: [0, 0, 0, 1], loadOp: 'clear', storeOp: 'store' }],
    depthStencilAttachment: { view: depth.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' },
  });
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, bindGroup);
  buffers.forEach((b, i) => pass.setVertexBuffer(i, b));
  pass.setIndexBuffer(index, 'uint32');
  pass.drawIndexed(geometry.index.length);
  pass.end();
  encoder.copyTextureToBuffer({ texture: color }, { buffer: readback, bytesPerRow }, [width, height]);
  device.queue.submit([encoder.finish()]);
  const failure = await device.popErrorScope();
  if (failure) throw new WebgpuRunnerError(`WebGPU validation: ${failure.message}`);
  await readback.mapAsync(GPUMapMode.READ);
  const halves = new Uint16Array(readback.getMappedRange().slice(0));
  readback.unmap();
  const linear = new Float32Array(width * height * 4);
  const srgb8 = new Uint8ClampedArray(width * height * 4);
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width * 4; ++x) {
      const value = halfToFloat(halves[(y * bytesPerRow) / 2 + x]);
      linear[y * width * 4 + x] = value;
      // The output transform `render --tonemap none --exposure 0` applies: clamp, then sRGB (alpha kept).
      const c = Math.min(Math.max(Number.isNaN(value) ? 0 : value, 0), 1);
      srgb8[(height - 1 - y) * width * 4 + x] = Math.round(255 * ((x & 3) === 3 ? c : srgbEncode(c)));
    }
  }
  return { linear, srgb8 };
}
