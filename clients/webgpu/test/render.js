// The page's script: one frame of a graph's WGSL in WebGPU, the water alone over opaque black
// (as `watergraph render --scene none --tonemap none --exposure 0`). The uniform values (camera
// matrices, time phases, sun, parameters) and the water grid come from the three.js client,
// whose values tests/ecosystem/three_client_test.cpp checks against the runtime; the shaders,
// bindings and drawing are WebGPU's. Reports through window.wgResult (the PNG as a data URL).
import { loadWaterGraph, createWaterGridGeometry } from '/three/watergraph-three.js';
import { loadSceneDescription, presetCamera } from '/three/watergraph-scene.js';
import { renderWaterOnly } from '/webgpu/watergraph-webgpu.js';

const q = new URLSearchParams(location.search);

// The client's THREE.BufferGeometry (attributes named as the manifest's inputs) as plain arrays.
function runnerGeometry(g) {
  return { position: g.attributes.a_position.array, normal: g.attributes.a_normal.array, uv: g.attributes.a_uv.array,
    index: Uint32Array.from(g.index.array) };
}

async function main() {
  if (!navigator.gpu) throw new Error('no navigator.gpu: WebGPU is not enabled in this browser');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('no WebGPU adapter');
  const device = await adapter.requestDevice();
  const width = Number(q.get('width')), height = Number(q.get('height'));
  const description = await loadSceneDescription(q.get('description'));
  const camera = presetCamera(description, q.get('camera'), width / height);
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
  const { srgb8 } = await renderWaterOnly(device, {
    manifest, wgsl, width, height, textures,
    uniformValue: (name) => water.uniforms[name].value,
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

main().then(
  (r) => { window.wgResult = { ok: true, ...r }; },
  (e) => { window.wgResult = { ok: false, error: `${e.name}: ${e.message}` }; });
