// `watergraph check --target wgsl`'s frames in WebGPU: the compiler (accuracy/wgsl_check_frames.cpp)
// sends the scene, then each water it renders (the graph's module, or one of its read-back tap
// modules) and each frame of it, through executor_server.mjs; this page renders them with the
// runner's renderGraph (watergraph-webgpu.js) into an RGBA32F frame and returns its floats
// exactly. Everything view-dependent is the compiler's (the runtime's values): the pass plan,
// the water grid, the camera matrices, the sun and the uniform buffer's bytes. Jobs:
//   {kind: "scene", description}: the scene description (`watergraph scene`) for every water;
//   {kind: "water", id, manifest, wgsl, plan: runtime/pass_plan's targets in planPasses' form,
//     grid: {vertices, indices (base64 float32 / uint32), floatsPerVertex}, textures:
//     [{name, width, height, rgba (base64, row 0 first)}], oceanModule: a spectral ocean's
//     <graph>.ocean.js text (watergraph-webgpu-ocean.js simulates it at each frame's time)};
//   {kind: "frame", water: id, uniforms (base64 bytes), camera: {view, projection, position},
//     sun, time} -> {frame: base64 of the float32 RGBA frame, row 0 at the bottom};
//   {kind: "drop", water: id}.
// Answers {ok: true} to the others; throws (the server answers {error}) for what it cannot run.
import { renderGraph } from './watergraph-webgpu.js';
import { oceanPassesWgsl, WebgpuOceanSimulation } from './watergraph-webgpu-ocean.js';
import { SceneShaderCache } from './watergraph-webgpu-scene-shaders.js';

function bytesOfBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

function base64OfBytes(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary);
}

// The water grid (runtime/scene.h buildWaterGrid: position, normal, uv interleaved) as the
// runner's separate arrays.
function gridGeometry(grid) {
  const v = new Float32Array(bytesOfBase64(grid.vertices).buffer), n = grid.floatsPerVertex;
  const count = v.length / n;
  const position = new Float32Array(3 * count), normal = new Float32Array(3 * count), uv = new Float32Array(2 * count);
  for (let i = 0; i < count; ++i) {
    position.set(v.subarray(i * n, i * n + 3), 3 * i);
    normal.set(v.subarray(i * n + 3, i * n + 6), 3 * i);
    uv.set(v.subarray(i * n + 6, i * n + 8), 2 * i);
  }
  return { position, normal, uv, index: new Uint32Array(bytesOfBase64(grid.indices).buffer) };
}

const state = { description: null, naga: null, sceneShaders: null, oceanPasses: null, waters: new Map() };

// A spectral ocean's simulation from the compiler's ocean module (its text, imported as a module).
async function oceanSimulation(device, manifest, moduleText) {
  if (!manifest.oceans) return null;
  state.oceanPasses ??= oceanPassesWgsl(state.description, state.naga);
  const url = URL.createObjectURL(new Blob([moduleText], { type: 'text/javascript' }));
  try {
    return new WebgpuOceanSimulation(device, manifest, await import(url), state.oceanPasses);
  } finally {
    URL.revokeObjectURL(url);
  }
}

// naga (the runtime's GLSL ES shaders to WGSL), loaded once for the page.
async function loadNaga() {
  if (!state.naga) {
    const naga = await import('./node_modules/naga-wasm/dist/index.js');
    await naga.init({ module_or_path: new URL('./node_modules/naga-wasm/dist/wasm/naga_bg.wasm', import.meta.url) });
    state.naga = { parseGlsl: naga.parseGlsl, validate: naga.validate, writeWgsl: naga.writeWgsl };
  }
  return state.naga;
}

// The runtime's scene shaders through naga, once per set of G-buffer inputs.
async function sceneShadersFor(manifest) {
  await loadNaga();
  state.sceneShaders ??= new SceneShaderCache(state.description, state.naga);
  return state.sceneShaders.forManifest(manifest);
}

// For the probe (watergraph-webgpu-probe.js): the simulation of the oceans a probe module
// reads, from the scene description check's 'scene' job sent and the probe's ocean module.
export async function probeOceanSimulation(device, manifest, moduleText) {
  if (!state.description) throw new Error('an ocean probe before the scene description');
  await loadNaga();
  return oceanSimulation(device, manifest, moduleText);
}

export async function runCheckJob(device, job) {
  switch (job.kind) {
    case 'scene':
      state.description = job.description;
      state.sceneShaders = null;  // both made from the description, so made again
      state.oceanPasses = null;
      return { ok: true };
    case 'water': {
      if (!state.description) throw new Error('a water before the scene');
      const textures = {};
      for (const t of job.textures) textures[t.name] = { width: t.width, height: t.height, rgba: bytesOfBase64(t.rgba) };
      const sceneShaders = await sceneShadersFor(job.manifest);
      state.waters.set(job.id, { manifest: job.manifest, wgsl: job.wgsl, plan: job.plan, textures,
        geometry: gridGeometry(job.grid), sceneShaders, keepAlive: {},
        ocean: await oceanSimulation(device, job.manifest, job.oceanModule) });
      return { ok: true };
    }
    case 'frame': {
      const w = state.waters.get(job.water);
      if (!w) throw new Error(`no water ${job.water}`);
      const { linear } = await renderGraph(device, {
        manifest: w.manifest, wgsl: w.wgsl, plan: w.plan, description: state.description, sceneShaders: w.sceneShaders,
        textures: w.textures, camera: job.camera, sun: job.sun, time: job.time, geometry: w.geometry, ocean: w.ocean,
        uniformBytes: bytesOfBase64(job.uniforms).buffer, keepAlive: w.keepAlive,
      });
      return { frame: base64OfBytes(new Uint8Array(linear.buffer)) };
    }
    case 'drop':
      state.waters.delete(job.water);
      return { ok: true };
    default:
      throw new Error(`unknown job kind ${job.kind}`);
  }
}
