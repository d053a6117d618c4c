// The page's script: one frame of a graph over opaque black, as `watergraph render
// --scene none` draws it. Reports through window.wgResult for render_graph.mjs.
import * as THREE from 'three';
import { loadWaterGraph, createWaterGridGeometry } from '../watergraph-three.js';

const q = new URLSearchParams(location.search);
const vec = (name) => q.get(name).split(',').map(Number);

async function main() {
  const width = Number(q.get('width')), height = Number(q.get('height'));
  const canvas = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, alpha: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  renderer.setClearColor(0x000000, 1);

  const camera = new THREE.PerspectiveCamera(Number(q.get('fov')), width / height, Number(q.get('near')), Number(q.get('far')));
  camera.position.set(...vec('eye'));
  camera.up.set(...vec('up'));
  camera.lookAt(...vec('target'));

  const water = await loadWaterGraph(q.get('manifest'));
  const scene = new THREE.Scene();
  scene.add(water.createMesh(createWaterGridGeometry(Number(q.get('grid')))));
  water.update(Number(q.get('time')), camera);
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  return { renderer: gl.getParameter(gl.getExtension('WEBGL_debug_renderer_info')?.UNMASKED_RENDERER_WEBGL ?? gl.RENDERER) };
}

main().then(
  (info) => { window.wgResult = { ok: true, ...info }; },
  (e) => { window.wgResult = { ok: false, error: `${e.name}: ${e.message}` }; });
