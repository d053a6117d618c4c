// The WebGPU ocean simulation's plumbing without a browser (node --test): the pass order of a
// filtered and an unfiltered cascade, the pyramids' mip levels, and which level each pass
// samples and draws, against a device that records what it is asked for.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { cascadePasses, pyramidLevels, WebgpuOceanError, WebgpuOceanSimulation } from '../watergraph-webgpu-ocean.js';

globalThis.GPUTextureUsage ??= { TEXTURE_BINDING: 4, RENDER_ATTACHMENT: 16, COPY_DST: 2, COPY_SRC: 1 };
globalThis.GPUShaderStage ??= { FRAGMENT: 2 };
globalThis.GPUBufferUsage ??= { UNIFORM: 64 };

// Each pass shader's samplers and scalars as oceanPassesWgsl gives them (names as the
// runtime's shaders declare them, runtime/ocean_gpu_shaders.cpp).
function passesOf() {
  const shape = {
    ocean_evolve: [['u_h0', 'u_frequency'], ['u_tau', 'u_dk', 'u_n']],
    ocean_evolve_displacement: [['u_h0', 'u_frequency'], ['u_tau', 'u_dk', 'u_n']],
    ocean_stockham: [['u_a', 'u_b', 'u_twiddle'], ['u_n', 'u_ns', 'u_vertical']],
    ocean_stockham_single: [['u_a', 'u_twiddle'], ['u_n', 'u_ns', 'u_vertical']],
    ocean_pack: [['u_a', 'u_b'], ['u_lambda']],
    ocean_pack_displacement: [['u_a'], ['u_lambda']],
    ocean_pack_filtered: [['u_a', 'u_b'], ['u_lambda']],
    ocean_downsample: [['u_slopes', 'u_moments'], []],
  };
  const out = {};
  for (const [name, [textures, uniforms]] of Object.entries(shape))
    out[name] = { wgsl: name, samplerBinding: 1 + textures.length, size: 16,
      textures: textures.map((t, i) => ({ name: t, binding: 1 + i, sampleType: 'unfilterable-float' })),
      uniforms: uniforms.map((u, i) => ({ name: u, type: u === 'u_n' || u === 'u_ns' || u === 'u_vertical' ? 'int' : 'float', offset: 4 * i })) };
  return out;
}

// A device and encoder recording every texture made and every draw: its pass, its sampled
// views by name and its attachments' views (a view: {texture, ...its descriptor}).
function recordingDevice(colorBytes = 128) {
  const textures = [], draws = [];
  const device = {
    limits: { maxColorAttachmentBytesPerSample: colorBytes },
    queue: { writeTexture() {} },
    createTexture(desc) {
      const t = { ...desc, createView: (v = {}) => ({ texture: t, ...v }) };
      textures.push(t);
      return t;
    },
    createSampler: () => ({ sampler: true }),
    createShaderModule: (d) => ({ label: d.label }),
    createBindGroupLayout: (d) => d,
    createPipelineLayout: (d) => d,
    createRenderPipeline: (d) => ({ name: d.fragment.module.label }),
    createBuffer: (d) => ({ getMappedRange: () => new ArrayBuffer(d.size), unmap() {} }),
    createBindGroup: (d) => d,
  };
  const encoder = {
    beginRenderPass(desc) {
      const record = { attachments: desc.colorAttachments.map((a) => a.view) };
      return {
        setPipeline(p) { record.pass = p.name; },
        setBindGroup(_, g) { record.entries = g.entries; },
        draw() { draws.push(record); },
        end() {},
      };
    },
  };
  return { device, encoder, textures, draws };
}

// An ocean module and manifest of one cascade per ocean, 8 texels for the first ocean and 4
// for the others: `oceans` lists each ocean's "filtered" (the compiler's value) and the maps
// its textures read.
function simulationOf(device, oceans) {
  const size = (o) => (o === 0 ? 8 : 4);
  const module = {
    oceans: oceans.map((_, o) => ({
      node: `sea${o}`, tileLengths: [100], sizes: [size(o)], dk: [0.06], choppiness: 1, foam: { cascades: 0 },
      cascades: () => [{ h0: new Float32Array(4 * size(o) * size(o)), frequency: new Uint32Array(size(o) * size(o)) }],
    })),
    twiddles: (n) => new Float32Array(n),
    phaseTau: (t) => t,
  };
  const manifest = { graph: 'g', oceans: oceans.map(({ filtered }, o) => ({ node: `sea${o}`, filtered })),
    textures: oceans.flatMap(({ maps }, o) => maps.map((map) => ({ name: `t${o}_${map}`, ocean: { ocean: o, cascade: 0, map } }))) };
  return new WebgpuOceanSimulation(device, manifest, module, passesOf());
}

test('pass order: a filtered cascade packs three maps and downsamples L times, an unfiltered one never', () => {
  assert.deepEqual([1, 4, 8, 256].map(pyramidLevels), [1, 3, 4, 9]);
  assert.throws(() => pyramidLevels(12), /must be a power of two \(got 12\)/);
  const names = (plan) => plan.map((p) => p.shader);
  assert.deepEqual(names(cascadePasses(4, { slopes: false, filtered: true })),
    ['ocean_evolve', 'ocean_stockham', 'ocean_stockham', 'ocean_stockham', 'ocean_stockham', 'ocean_pack_filtered', 'ocean_downsample', 'ocean_downsample']);
  assert.deepEqual(names(cascadePasses(4, { slopes: true, filtered: false })),
    ['ocean_evolve', 'ocean_stockham', 'ocean_stockham', 'ocean_stockham', 'ocean_stockham', 'ocean_pack']);
  assert.deepEqual(names(cascadePasses(4, { slopes: false, filtered: false })),
    ['ocean_evolve_displacement', ...Array(4).fill('ocean_stockham_single'), 'ocean_pack_displacement']);
});

test('a filtered cascade: level 0 from the pack, level l drawn from a view of level l - 1 alone', () => {
  const { device, encoder, textures, draws } = recordingDevice();
  const sim = simulationOf(device, [{ filtered: true, maps: ['displacement', 'slopes', 'moments'] },
    { filtered: false, maps: ['displacement', 'slopes'] }]);
  const filtered = sim.oceans[0].cascades[0], plain = sim.oceans[1].cascades[0];
  const [displacement, slopes, moments] = filtered.maps;
  // Storage: the slope and moments maps with every level (8, 4, 2, 1), the rest one.
  assert.deepEqual([displacement, slopes, moments].map((t) => t.mipLevelCount), [1, 4, 4]);
  assert.ok(plain.maps.every((t) => t.mipLevelCount === 1));
  assert.equal(textures.filter((t) => t.mipLevelCount > 1).length, 2);
  sim.encode(encoder, 3.5);
  // The filtered ocean's cascade's passes in its plan's order, then the other's (no downsample).
  assert.deepEqual(draws.map((d) => d.pass), [...filtered.plan, ...plain.plan].map((p) => p.shader));
  const first = draws.slice(0, filtered.plan.length);
  const pack = first.find((d) => d.pass === 'ocean_pack_filtered');
  assert.deepEqual(pack.attachments, [{ texture: displacement }, { texture: slopes, baseMipLevel: 0, mipLevelCount: 1 },
    { texture: moments, baseMipLevel: 0, mipLevelCount: 1 }]);
  const down = first.filter((d) => d.pass === 'ocean_downsample');
  assert.equal(down.length, 3);
  down.forEach((d, i) => {
    const l = i + 1;
    assert.deepEqual(d.attachments, [{ texture: slopes, baseMipLevel: l, mipLevelCount: 1 }, { texture: moments, baseMipLevel: l, mipLevelCount: 1 }]);
    const sampled = Object.fromEntries(d.entries.filter((e) => e.resource.texture).map((e) => [e.binding, e.resource]));
    assert.deepEqual(sampled, { 1: { texture: slopes, baseMipLevel: l - 1, mipLevelCount: 1 }, 2: { texture: moments, baseMipLevel: l - 1, mipLevelCount: 1 } });
  });
  // What the water binds: the moments texture, whose default view holds every level.
  assert.equal(sim.map({ ocean: 0, cascade: 0, map: 'moments' }), moments);
  assert.equal(sim.map({ ocean: 0, cascade: 0, map: 'slopes' }), slopes);
  assert.throws(() => sim.map({ ocean: 1, cascade: 0, map: 'moments' }), /not computed/);
});

test('a filtered ocean on a device held to WebGPU\'s default 32 colour bytes a sample is a clear error', () => {
  assert.throws(() => simulationOf(recordingDevice(32).device, [{ filtered: true, maps: ['slopes', 'moments'] }]),
    (e) => e instanceof WebgpuOceanError && /writes 48 bytes of colour a sample; this device allows 32/.test(e.message));
  // Unfiltered, 32 bytes are enough (two RGBA32F targets at most).
  assert.doesNotThrow(() => simulationOf(recordingDevice(32).device, [{ filtered: false, maps: ['slopes'] }, { filtered: false, maps: ['slopes'] }]));
});

test('"filtered" is the manifest\'s value: an ocean marked filtered keeps pyramids for every cascade, read or not', () => {
  const { device } = recordingDevice();
  // The moments map listed but the ocean not marked filtered: no pyramids (the compiler's
  // manifest never has this; checkManifest refuses it before a simulation is made).
  const unmarked = simulationOf(device, [{ filtered: false, maps: ['slopes', 'moments'] }]);
  assert.equal(unmarked.oceans[0].cascades[0].filtered, false);
  assert.ok(!unmarked.oceans[0].cascades[0].plan.some((p) => p.shader === 'ocean_downsample'));
  const marked = simulationOf(device, [{ filtered: true, maps: ['displacement'] }]);
  assert.equal(marked.oceans[0].cascades[0].filtered, true);
  assert.equal(marked.oceans[0].cascades[0].slopes, true);
  assert.equal(marked.oceans[0].cascades[0].plan.filter((p) => p.shader === 'ocean_downsample').length, 3);
});
