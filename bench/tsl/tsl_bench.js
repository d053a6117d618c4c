// Times three.js's TSL front end on the synthetic graphs (synthetic_tsl.js): for each
// trial a fresh node graph and a fresh material (no cache of an earlier trial can hit),
// then GLSLNodeBuilder.build() — TSL to GLSL ES 3.00, the WebGL2 backend's shaders, before
// any WebGL compile. Query: ?nodes=100,1000,10000&trials=5&warmup=3 (warm-up builds of each
// size first, untimed: the JavaScript engine compiles the builder's code on the first ones,
// as Google Benchmark warms watergraph's side up). window.wgBench receives
// { ok, revision, results: [{ nodes, count, constructMs: [...], buildMs: [...] }] } or
// { ok: false, error }.
import * as THREE from 'three/webgpu';
import * as TSL from 'three/tsl';
import { buildSynthetic } from './synthetic_tsl.js';

async function run() {
  const query = new URLSearchParams(location.search);
  const sizes = (query.get('nodes') ?? '100,1000,10000').split(',').map(Number);
  const trials = Number(query.get('trials') ?? 5);
  const warmup = Number(query.get('warmup') ?? 3);
  const renderer = new THREE.WebGPURenderer({ canvas: document.getElementById('view'), forceWebGL: true });
  await renderer.init();
  const geometry = new THREE.PlaneGeometry(1, 1, 1, 1);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(55, 1, 0.1, 200);
  const results = [];
  for (const nodes of sizes) {
    const r = { nodes, count: 0, constructMs: [], buildMs: [], vertexChars: 0, fragmentChars: 0 };
    for (let t = -warmup; t < trials; ++t) {
      const t0 = performance.now();
      const graph = buildSynthetic(nodes, TSL);
      const material = new THREE.MeshBasicNodeMaterial();
      material.colorNode = graph.colorNode;
      material.opacityNode = graph.opacityNode;
      material.positionNode = graph.positionNode;
      material.normalNode = graph.normalNode;
      material.transparent = true;
      const mesh = new THREE.Mesh(geometry, material);
      const t1 = performance.now();
      // As the renderer's node manager sets a builder up for a render object (unlit: no
      // lights, environment or fog reach a MeshBasicNodeMaterial's colour).
      const builder = new THREE.GLSLNodeBuilder(mesh, renderer);
      builder.scene = scene;
      builder.camera = camera;
      builder.material = material;
      builder.context.material = material;
      builder.lightsNode = renderer.lighting.getNode(scene, camera);
      builder.build();
      const t2 = performance.now();
      r.count = graph.count;
      if (t < 0) continue;
      r.constructMs.push(t1 - t0);
      r.buildMs.push(t2 - t1);
      r.vertexChars = builder.vertexShader.length;
      r.fragmentChars = builder.fragmentShader.length;
    }
    results.push(r);
  }
  return { ok: true, revision: THREE.REVISION, results };
}

run().then((r) => { window.wgBench = r; }, (e) => { window.wgBench = { ok: false, error: String(e && e.stack || e) }; });
