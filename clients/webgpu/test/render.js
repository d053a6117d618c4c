// The page's script: one frame of a graph's WGSL in WebGPU with every pass its manifest lists,
// in the built-in scene or (scene=none) with none drawn, through `--tonemap none --exposure 0`
// (as `watergraph render --tonemap none --exposure 0 [--scene none]`). The uniform values (camera
// matrices, time phases, sun, parameters), the water grid and the pass plan come from the
// three.js client, whose values tests/ecosystem/three_client_test.cpp checks against the runtime;
// the runtime's scene shaders are translated to WGSL by naga; the graph's shaders, bindings and
// drawing are WebGPU's. render_webgpu.mjs calls window.wgRender(job) once per frame in one
// page; what does not depend on the job (naga's module, a scene description and its shaders
// translated by naga) is made once and kept, each frame gets its own device. Each call
// resolves to { ok, png (base64), adapter } or { ok: false, error }.
import { loadWaterGraph, createWaterGridGeometry } from '/three/watergraph-three.js';
import { loadSceneDescription, presetCamera } from '/three/watergraph-scene.js';
import { glPerspective, planPasses } from '/three/watergraph-passes.js';
import { init as initNaga, parseGlsl, validate, writeWgsl } from '/webgpu/node_modules/naga-wasm/dist/index.js';
import { renderGraph } from '/webgpu/watergraph-webgpu.js';
import { oceanPassesWgsl, WebgpuOceanSimulation } from '/webgpu/watergraph-webgpu-ocean.js';
import { SceneShaderCache } from '/webgpu/watergraph-webgpu-scene-shaders.js';

// What frames share: naga's module, and each description (by URL) with its scene shaders
// translated by naga (SceneShaderCache).
let nagaReady = null;
const descriptions = new Map();
const naga = { parseGlsl, validate, writeWgsl };

function sharedDescription(url) {
  if (!descriptions.has(url)) descriptions.set(url, { description: loadSceneDescription(url), sceneShaders: null });
  return descriptions.get(url);
}

// The client's THREE.BufferGeometry (attributes named as the manifest's inputs) as plain arrays.
function runnerGeometry(g) {
  return { position: g.attributes.a_position.array, normal: g.attributes.a_normal.array, uv: g.attributes.a_uv.array,
    index: Uint32Array.from(g.index.array) };
}

async function renderJob(job) {
  const q = new Map(Object.entries(job).map(([k, v]) => [k, String(v)]));
  if (!navigator.gpu) throw new Error('no navigator.gpu: WebGPU is not enabled in this browser');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('no WebGPU adapter');
  // A filtered ocean cascade's pack writes three RGBA32F targets (48 bytes a sample; the default limit is 32).
  const device = await adapter.requestDevice({ requiredLimits: { maxColorAttachmentBytesPerSample: adapter.limits.maxColorAttachmentBytesPerSample } });
  const width = Number(q.get('width')), height = Number(q.get('height'));
  const shared = sharedDescription(q.get('description'));
  const description = await shared.description;
  const camera = presetCamera(description, q.get('camera'), width / height);
  // The runtime's projection (glm::perspective), for the water's uniforms and the scene alike.
  glPerspective(camera.fov, camera.aspect, camera.near, camera.far, camera.projectionMatrix);
  camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
  const manifestUrl = new URL(q.get('manifest'), location.href);
  const water = await loadWaterGraph(manifestUrl.href, { description });
  water.setViewportSize(width, height);
  water.update(Number(q.get('time')), camera);
  const manifest = await (await fetch(manifestUrl)).json();
  const wgsl = await (await fetch(new URL(manifest.targets.wgsl.vert, manifestUrl))).text();
  const textures = {};
  for (const t of manifest.textures) {
    if (!t.file) continue;
    const blob = await (await fetch(new URL(t.file, manifestUrl))).blob();
    textures[t.name] = await createImageBitmap(blob, { imageOrientation: 'flipY', premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
  }
  nagaReady ??= initNaga({ module_or_path: new URL('/webgpu/node_modules/naga-wasm/dist/wasm/naga_bg.wasm', location.href) });
  await nagaReady;
  shared.sceneShaders ??= new SceneShaderCache(description, naga);
  const sceneShaders = shared.sceneShaders.forManifest(manifest);
  // A spectral ocean: the runtime's pass shaders through naga, the compiler's ocean module.
  const ocean = manifest.oceans
    ? new WebgpuOceanSimulation(device, manifest, await import(new URL(manifest.oceans[0].module, manifestUrl).href),
      oceanPassesWgsl(description, naga))
    : null;
  const plan = planPasses(manifest, description, { width, height, environmentSize: description.environment.size });
  const { srgb8 } = await renderGraph(device, {
    manifest, wgsl, plan, description, sceneShaders, textures,
    drawScene: q.get('scene') !== 'none',
    camera: { view: camera.matrixWorldInverse.toArray(), projection: camera.projectionMatrix.toArray(),
      position: camera.getWorldPosition(camera.position.clone()).toArray() },
    uniformValue: (name) => water.uniforms[name].value,
    ocean, time: Number(q.get('time')),
    geometry: runnerGeometry(createWaterGridGeometry(Number(q.get('grid')), description.water.half_size)),
  });
  const canvas = new OffscreenCanvas(width, height);
  canvas.getContext('2d').putImageData(new ImageData(srgb8, width, height), 0, 0);
  const blob = await canvas.convertToBlob({ type: 'image/png' });
  const bytes = new Uint8Array(await blob.arrayBuffer());
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return { png: btoa(binary), adapter: (await adapter.requestAdapterInfo?.())?.architecture ?? adapter.info?.architecture ?? '' };
}

window.wgRender = (job) => renderJob(job).then(
  (r) => ({ ok: true, ...r }),
  (e) => ({ ok: false, error: `${e.name}: ${e.message}` }));
window.wgReady = true;
