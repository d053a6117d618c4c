// For watergraph's tests: builds a WaterGraph from a compiled graph (es300, derived
// uniforms on), updates it for one camera and time, then sets each parameter named on the
// command line, and prints the derived uniforms' values after each step with the frame
// they were computed from, so the test can recompute them with the runtime's evaluator.
//   node derived_client.mjs <dir> <graph> [<parameter>=<json value>]...
import { readFileSync } from 'node:fs';
import * as THREE from 'three';
import { WaterGraph } from '../watergraph-three.js';

const [dir, graph, ...sets] = process.argv.slice(2);
const manifest = JSON.parse(readFileSync(`${dir}/${graph}.manifest.json`, 'utf8'));
const textures = {}, resources = {};
for (const t of manifest.textures ?? []) {
  const texture = t.type === 'samplerCube' ? new THREE.CubeTexture() : new THREE.Texture();
  if ('source' in t) textures[t.name] = texture;
  else resources[t.resource] = texture;
}
const water = new WaterGraph({
  manifest,
  vertexShader: readFileSync(`${dir}/${graph}.es300.vert`, 'utf8'),
  fragmentShader: readFileSync(`${dir}/${graph}.es300.frag`, 'utf8'),
  textures,
  resources,
});
const camera = new THREE.PerspectiveCamera(55, 16 / 9, 0.25, 300);
camera.position.set(6, 3.5, 9);
camera.lookAt(0.5, 0, -1);
camera.updateMatrixWorld();
camera.updateProjectionMatrix();

const derivedNames = (manifest.uniforms ?? []).filter((u) => u.builtin === 'derived').map((u) => u.name);
const snapshot = () => {
  const parameters = {};
  for (const u of manifest.uniforms ?? []) {
    if (!('parameter' in u)) continue;
    const v = water.uniforms[u.name].value;
    parameters[u.parameter] = typeof v === 'number' ? [v] : v.toArray();
  }
  const values = {};
  for (const name of derivedNames) {
    const v = water.uniforms[name].value;
    values[name] = typeof v === 'number' ? [v] : v.toArray();
  }
  const f = water.frame;
  return { frame: { time: f.time, camera_position: f.cameraPosition, near: f.near, far: f.far, view: f.view, projection: f.projection, sun_direction: f.sunDirection }, parameters, values };
};
const steps = [];
water.update(3.5, camera);
steps.push(snapshot());
for (const s of sets) {
  const at = s.indexOf('=');
  water.setParameter(s.slice(0, at), JSON.parse(s.slice(at + 1)));
  steps.push(snapshot());
}
process.stdout.write(JSON.stringify({ steps }));
