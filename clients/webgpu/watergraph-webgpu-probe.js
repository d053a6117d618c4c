// Runs a probe module (`watergraph probe --target wgsl`: the probe plan's WGSL, entry points
// vs_main and fs_main) over its cases in WebGPU, as the GL and Vulkan probes run theirs: one
// pixel of an RGBA32F target per case (up to 1024 a row), drawn by the module's full-screen
// triangle with the viewport restricted to that pixel, so @builtin(position) is the pixel's
// centre, the case's u_probe_pixel. The job (from executor_server.mjs, made by the compiler):
//   what: the shader's name in errors; wgsl: the module; uniformSize: the uniform buffer's
//   bytes (0: none);
//   textures: [{binding, cube, kind: "scene"}] a 1x1 RGBA32F texture per case holding the
//     case's texel, sampled nearest (every fetch returns it, as the double reference assumes);
//     [{binding, kind: "file", width, height, rgba (base64, row 0 first), wrap, filter, srgb}]
//     a node texture as the runtime uploads it (a mipmapped one with its full chain);
//     [{binding, kind: "ocean", name}] the map its ocean manifest's texture `name` names, of
//     the spectral ocean the job's `ocean` describes, simulated at each case's time;
//   ocean (only with ocean maps): {manifest: a manifest of the probe's oceans and ocean maps,
//     module: the <graph>.ocean.js text}; check's 'scene' job must have come first (the
//     simulation runs the description's pass shaders, watergraph-webgpu-ocean.js);
//   cases: [{uniforms: the buffer's 32-bit words, texels: per scene texture 4 float32 bit
//     patterns, time: seconds (the ocean's)}].
// Returns the pixels as 4 float32 bit patterns per case (NaN and Inf survive the trip).
import { probeOceanSimulation } from './watergraph-webgpu-check.js';
import { fullChainLevels, generateMipmaps } from './watergraph-webgpu-mipmaps.js';

const ADDRESS_MODES = { repeat: 'repeat', clamp: 'clamp-to-edge', mirror: 'mirror-repeat' };

function bytesOfBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

export async function runProbeCases(device, job) {
  const module = device.createShaderModule({ code: job.wgsl, label: job.what });
  const errors = (await module.getCompilationInfo()).messages.filter((m) => m.type === 'error');
  if (errors.length) throw new Error(`Tint rejected ${job.what}: ${errors.map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`).join('; ')}`);
  device.pushErrorScope('validation');
  const owned = [];  // destroyed once the pixels are read
  const own = (x) => { owned.push(x); return x; };
  const visibility = GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT;
  const layoutEntries = [];
  if (job.uniformSize > 0) layoutEntries.push({ binding: 0, visibility, buffer: { type: 'uniform' } });
  // Entries every case shares (node textures and their samplers), and the scene textures' slots.
  const shared = [];
  const sceneSlots = [];
  const ocean = job.ocean ? await probeOceanSimulation(device, job.ocean.manifest, job.ocean.module) : null;
  for (const t of job.textures) {
    const dimension = t.cube ? 'cube' : '2d';
    if (t.kind === 'ocean') {
      // Read with textureLoad, as the water reads the maps: unfilterable, the sampler unused.
      const map = ocean && job.ocean.manifest.textures.find((m) => m.name === t.name);
      if (!map) throw new Error(`${job.what}: the ocean map ${t.name} is not in the job's ocean manifest`);
      layoutEntries.push({ binding: t.binding, visibility, texture: { sampleType: 'unfilterable-float' } });
      layoutEntries.push({ binding: t.binding + 1, visibility, sampler: { type: 'non-filtering' } });
      shared.push({ binding: t.binding, resource: ocean.map(map.ocean).createView() });
      shared.push({ binding: t.binding + 1, resource: device.createSampler({ magFilter: 'nearest', minFilter: 'nearest' }) });
      continue;
    }
    if (t.kind === 'scene') {
      layoutEntries.push({ binding: t.binding, visibility, texture: { sampleType: 'unfilterable-float', viewDimension: dimension } });
      layoutEntries.push({ binding: t.binding + 1, visibility, sampler: { type: 'non-filtering' } });
      shared.push({ binding: t.binding + 1, resource: device.createSampler({ magFilter: 'nearest', minFilter: 'nearest' }) });
      sceneSlots.push(t);
      continue;
    }
    if (t.cube) throw new Error(`${job.what}: a node texture is a 2D image`);
    const format = t.srgb ? 'rgba8unorm-srgb' : 'rgba8unorm';
    const mipmapped = t.filter === 'mipmapped';
    const mipLevelCount = mipmapped ? fullChainLevels(t.width, t.height) : 1;
    const texture = own(device.createTexture({ size: [t.width, t.height], format, mipLevelCount,
      usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST | (mipmapped ? GPUTextureUsage.RENDER_ATTACHMENT : 0) }));
    device.queue.writeTexture({ texture }, bytesOfBase64(t.rgba), { bytesPerRow: 4 * t.width }, [t.width, t.height]);
    if (mipmapped) generateMipmaps(device, texture, format, mipLevelCount);
    const filter = t.filter === 'nearest' ? 'nearest' : 'linear';
    const mipmapFilter = mipmapped ? 'linear' : 'nearest';
    const address = ADDRESS_MODES[t.wrap] ?? 'repeat';
    layoutEntries.push({ binding: t.binding, visibility, texture: { sampleType: 'float' } });
    layoutEntries.push({ binding: t.binding + 1, visibility, sampler: { type: 'filtering' } });
    shared.push({ binding: t.binding, resource: texture.createView() });
    shared.push({ binding: t.binding + 1, resource: device.createSampler({ addressModeU: address, addressModeV: address, magFilter: filter, minFilter: filter, mipmapFilter }) });
  }
  const bindGroupLayout = device.createBindGroupLayout({ entries: layoutEntries });
  const pipeline = device.createRenderPipeline({
    layout: device.createPipelineLayout({ bindGroupLayouts: [bindGroupLayout] }),
    vertex: { module, entryPoint: 'vs_main' },
    fragment: { module, entryPoint: 'fs_main', targets: [{ format: 'rgba32float' }] },
    primitive: { topology: 'triangle-list', cullMode: 'none' },
  });
  const n = job.cases.length;
  const width = Math.min(n, 1024), height = Math.ceil(n / 1024);
  const target = own(device.createTexture({ size: [width, height], format: 'rgba32float',
    usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC }));
  // One render pass per run of cases at one ocean time (one for all without an ocean), each
  // after the simulation's passes for that time.
  let encoder = device.createCommandEncoder();
  let pass = null;
  let passTime;
  job.cases.forEach((c, i) => {
    if (!pass || (ocean && c.time !== passTime)) {
      if (pass) {
        pass.end();
        device.queue.submit([encoder.finish()]);
        encoder = device.createCommandEncoder();
      }
      if (ocean) ocean.encode(encoder, c.time);
      passTime = c.time;
      pass = encoder.beginRenderPass({ colorAttachments: [{ view: target.createView(), clearValue: [0, 0, 0, 0],
        loadOp: i === 0 ? 'clear' : 'load', storeOp: 'store' }] });
      pass.setPipeline(pipeline);
    }
    const entries = [...shared];
    if (job.uniformSize > 0) {
      const buffer = own(device.createBuffer({ size: job.uniformSize, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST }));
      device.queue.writeBuffer(buffer, 0, new Uint32Array(c.uniforms));
      entries.push({ binding: 0, resource: { buffer } });
    }
    sceneSlots.forEach((t, k) => {
      const layers = t.cube ? 6 : 1;
      const texture = own(device.createTexture({ size: [1, 1, layers], format: 'rgba32float',
        usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST }));
      const texel = new Uint32Array(c.texels[k]);
      for (let layer = 0; layer < layers; ++layer)
        device.queue.writeTexture({ texture, origin: [0, 0, layer] }, texel, { bytesPerRow: 16 }, [1, 1, 1]);
      entries.push({ binding: t.binding, resource: texture.createView({ dimension: t.cube ? 'cube' : '2d' }) });
    });
    pass.setBindGroup(0, device.createBindGroup({ layout: bindGroupLayout, entries }));
    pass.setViewport(i % 1024, Math.floor(i / 1024), 1, 1, 0, 1);
    pass.draw(3);
  });
  pass?.end();
  const bytesPerRow = Math.ceil((width * 16) / 256) * 256;
  const readback = own(device.createBuffer({ size: bytesPerRow * height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ }));
  encoder.copyTextureToBuffer({ texture: target }, { buffer: readback, bytesPerRow }, [width, height]);
  device.queue.submit([encoder.finish()]);
  const failure = await device.popErrorScope();
  if (failure) {
    owned.forEach((x) => x.destroy());
    throw new Error(`WebGPU validation of ${job.what}: ${failure.message}`);
  }
  await readback.mapAsync(GPUMapMode.READ);
  const words = new Uint32Array(readback.getMappedRange().slice(0));
  readback.unmap();
  owned.forEach((x) => x.destroy());
  const pixels = new Array(4 * n);
  for (let i = 0; i < n; ++i) {
    const row = Math.floor(i / 1024), column = i % 1024;
    for (let ch = 0; ch < 4; ++ch) pixels[4 * i + ch] = words[(row * bytesPerRow) / 4 + 4 * column + ch];
  }
  return pixels;
}
