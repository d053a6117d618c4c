// The page's script: one frame of a graph, as `watergraph render` draws it. Without a
// description, the water alone over opaque black (`--scene none`) with the client drawing
// only water_surface; with `description` (a `watergraph scene` file), every pass the
// manifest lists, and with `builtin=1` the built-in scene around the water; `box=x,y,z,size`
// adds a user's own object, an unlit red cube, to the scene the passes draw. `tonemap` and
// `exposure` are the render options of the output transform; `nofloat=1` hides the
// extensions that make half floats renderable, as a context without them would;
// `hosttonemapping=1` makes the renderer as an HDR host might: three.js's own half-float
// output buffer, ACES tone mapping and sRGB output, which three.js applies to what is drawn
// to the canvas (the client's output must not change). Reports
// through window.wgResult for render_graph.mjs (with the frame's format and any
// warning the client gave).
import * as THREE from 'three';
import { loadWaterGraph, createWaterGridGeometry } from '../watergraph-three.js';
import { loadSceneDescription, createBuiltinScene } from '../watergraph-scene.js';

const q = new URLSearchParams(location.search);
const vec = (name) => q.get(name).split(',').map(Number);

// A context that cannot render half floats: the extensions are not offered.
function hideFloatRendering() {
  const hidden = new Set(['EXT_color_buffer_float', 'EXT_color_buffer_half_float']);
  const proto = WebGL2RenderingContext.prototype;
  const getExtension = proto.getExtension, supported = proto.getSupportedExtensions;
  proto.getExtension = function (name) { return hidden.has(name) ? null : getExtension.call(this, name); };
  proto.getSupportedExtensions = function () { return supported.call(this)?.filter((n) => !hidden.has(n)) ?? null; };
}

const warnings = [];
const warn = console.warn;
console.warn = (...args) => {
  warnings.push(args.join(' '));
  warn.apply(console, args);
};

async function main() {
  if (q.get('nofloat') === '1') hideFloatRendering();
  const width = Number(q.get('width')), height = Number(q.get('height'));
  const canvas = document.getElementById('view');
  const host = q.get('hosttonemapping') === '1';
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, alpha: false, preserveDrawingBuffer: true,
    ...(host ? { outputBufferType: THREE.HalfFloatType } : {}) });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  renderer.setClearColor(0x000000, 1);
  if (host) {
    renderer.toneMapping = THREE.ACESFilmicToneMapping;
    renderer.outputColorSpace = THREE.SRGBColorSpace;
  }

  const camera = new THREE.PerspectiveCamera(Number(q.get('fov')), width / height, Number(q.get('near')), Number(q.get('far')));
  camera.position.set(...vec('eye'));
  camera.up.set(...vec('up'));
  camera.lookAt(...vec('target'));

  const description = q.get('description') ? await loadSceneDescription(q.get('description')) : null;
  const water = await loadWaterGraph(q.get('manifest'), { description });
  const grid = Number(q.get('grid'));
  water.setGridQuads(grid);
  const scene = new THREE.Scene();
  if (q.get('builtin') === '1') scene.add(createBuiltinScene(description));
  if (q.get('box')) {
    const [x, y, z, size] = vec('box');
    const box = new THREE.Mesh(new THREE.BoxGeometry(size, size, size), new THREE.MeshBasicMaterial({ color: 0xff0000 }));
    box.position.set(x, y, z);
    scene.add(box);
  }
  scene.add(water.createMesh(createWaterGridGeometry(grid)));
  water.update(Number(q.get('time')), camera);
  const options = {};
  if (q.get('tonemap')) options.toneMapping = q.get('tonemap');
  if (q.get('exposure')) options.exposure = Number(q.get('exposure'));
  water.render(renderer, scene, camera, null, options);
  const gl = renderer.getContext();
  return {
    renderer: gl.getParameter(gl.getExtension('WEBGL_debug_renderer_info')?.UNMASKED_RENDERER_WEBGL ?? gl.RENDERER),
    frameFormat: water.frameFormat, frameFallback: water.frameFallback, warnings,
  };
}

main().then(
  (info) => { window.wgResult = { ok: true, ...info }; },
  (e) => { window.wgResult = { ok: false, error: `${e.name}: ${e.message}` }; });
