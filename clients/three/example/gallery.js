// The gallery page: a graph picker, the graph's presets (each compiled by serve.mjs with
// --preset), sliders generated from the manifest's parameters, the view of the output
// transform (tone mapper and exposure, starting at the graph's own view), an orbit camera
// over the built-in scene, and the scene's buoys floating on the water by the graph's
// surface query (query-js; the parameters as the sliders set them). window.wgGallery
// reports state for the headless check.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { loadWaterGraph, TONE_MAPPERS } from '../watergraph-three.js';
import { loadSceneDescription, createBuiltinScene, createFloatingBuoys, presetCamera } from '../watergraph-scene.js';

const $ = (id) => document.getElementById(id);
const state = { ready: false, graph: null, preset: null, frames: 0, errors: [], view: null, frameFormat: null, buoys: [] };
window.wgGallery = state;

const [description, gallery] = await Promise.all([
  loadSceneDescription('/out/scene.json'),
  fetch('/out/gallery.json').then((r) => r.json()),
]);

const view = $('view');
const renderer = new THREE.WebGLRenderer({ antialias: false, alpha: false });
renderer.setPixelRatio(1);
view.appendChild(renderer.domElement);
const camera = presetCamera(description, 'above', 1);
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.fromArray(description.cameras.above.target);
controls.update();

const scene = new THREE.Scene();
const builtin = createBuiltinScene(description);
const buoys = createFloatingBuoys(description, builtin.userData.sunDirection);
scene.add(builtin, buoys.group);
let water = null, waterMesh = null, query = null;

// The graph's surface query: its params_default and displace (one graph per module).
// null for a spectral ocean's query, whose state takes its inverse FFTs on the CPU each
// update (0.6 s in JavaScript: not per frame; docs/queries.md).
async function loadQuery(name, preset) {
  const module = await import(`/out/${name}/${preset}/${name}.query.js`);
  const find = (suffix) => module[Object.keys(module).find((k) => k.startsWith('wg_') && k.endsWith(suffix))];
  if (find('_ocean_init')) return null;
  return { defaults: find('_params_default'), displace: find('_displace') };
}

// Each buoy where the query moves its rest point at time t, tilted to the normal there.
function floatBuoys(t) {
  buoys.group.visible = query !== null && $('buoys').checked;
  if (!buoys.group.visible) {
    state.buoys = [];
    $('buoys-state').textContent = query ? '' : 'no query for this graph';
    return;
  }
  const params = query.defaults();
  for (const u of water.manifest.uniforms ?? []) {
    if (!('parameter' in u) || !(u.parameter in params)) continue;
    const v = water.uniforms[u.name].value;
    params[u.parameter] = typeof v === 'number' ? v : v.toArray();
  }
  const position = [0, 0, 0], normal = [0, 1, 0];
  state.buoysTime = t;
  state.buoys = buoys.restPoints.map(([x0, z0], i) => {
    query.displace(params, x0, z0, t, position, normal, null);
    buoys.place(i, position, normal);
    return { position: [...position], normal: [...normal] };
  });
  $('buoys-state').textContent = `${state.buoys.length} on the query`;
}

function resize() {
  const w = Math.max(view.clientWidth, 1), h = Math.max(view.clientHeight, 1);
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}
new ResizeObserver(resize).observe(view);
resize();

// A slider's range: the manifest's min/max, else around the default.
function range(u, x) {
  const lo = typeof u.min === 'number' ? u.min : Math.min(0, 2 * x);
  const hi = typeof u.max === 'number' ? u.max : Math.max(1, 2 * Math.abs(x));
  return [lo, hi];
}

const hex = (v) => '#' + v.slice(0, 3).map((x) => Math.round(Math.min(Math.max(x, 0), 1) * 255).toString(16).padStart(2, '0')).join('');
const fromHex = (s) => [1, 3, 5].map((i) => parseInt(s.slice(i, i + 2), 16) / 255);

// One control per parameter uniform: a colour picker for the "color" hint (the sRGB floats
// the picker shows, which the shader linearises, as the runtime uploads them), a checkbox for
// bool, sliders otherwise (also for "hdr_color", whose values a picker cannot reach past 1).
function buildParameters(w) {
  const box = $('parameters');
  box.replaceChildren();
  for (const u of w.manifest.uniforms ?? []) {
    if (!('parameter' in u)) continue;
    const label = document.createElement('label');
    label.textContent = u.parameter;
    label.title = u.description ?? '';
    box.appendChild(label);
    const current = () => {
      const v = w.uniforms[u.name].value;
      return typeof v === 'number' ? [v] : v.toArray();
    };
    const values = current();
    if (u.hint === 'color' && (u.type === 'vec3' || u.type === 'vec4')) {
      const input = document.createElement('input');
      input.type = 'color';
      input.value = hex(values);
      input.oninput = () => w.setParameter(u.parameter, u.type === 'vec4' ? [...fromHex(input.value), current()[3]] : fromHex(input.value));
      box.appendChild(input);
    } else if (u.type === 'bool') {
      const input = document.createElement('input');
      input.type = 'checkbox';
      input.checked = values[0] !== 0;
      input.onchange = () => w.setParameter(u.parameter, input.checked ? 1 : 0);
      box.appendChild(input);
    } else {
      values.forEach((x, i) => {
        const [lo, hi] = range(u, x);
        const input = document.createElement('input');
        input.type = 'range';
        input.min = lo;
        input.max = hi;
        input.step = u.type === 'int' ? 1 : (hi - lo) / 200;
        input.value = x;
        const shown = document.createElement('span');
        shown.className = 'value';
        shown.textContent = Number(x).toFixed(3);
        label.appendChild(shown);
        input.oninput = () => {
          const v = current();
          v[i] = Number(input.value);
          w.setParameter(u.parameter, v.length === 1 ? v[0] : v);
          shown.textContent = Number(current()[i]).toFixed(3);  // as clamped
        };
        box.appendChild(input);
      });
    }
  }
}

const graphInfo = (name) => gallery.graphs.find((g) => g.name === name);

async function select(name, preset = 'default') {
  $('error').textContent = '';
  const next = await loadWaterGraph(`/out/${name}/${preset}/${name}.manifest.json`, { description });
  if (water) {
    scene.remove(waterMesh);
    water.dispose();
  }
  water = next;
  // An animation: a spectral ocean's foam continues from the previous frame's steps.
  water.foamHistory = 'continue';
  query = graphInfo(name).query ? await loadQuery(name, preset) : null;
  waterMesh = water.createMesh();
  scene.add(waterMesh);
  const info = graphInfo(name);
  $('about').textContent = info.description;
  $('preset').replaceChildren(...['default', ...info.presets].map((p) => new Option(p, p, false, p === preset)));
  $('graph').value = name;
  $('passes').textContent = 'passes: ' + water.passes.plan.passes.join(', ');
  buildParameters(water);
  showView(water.view);  // each graph starts at its own view
  Object.assign(state, { graph: name, preset, frames: 0 });
  history.replaceState(null, '', `?graph=${name}&preset=${preset}`);
}
state.select = select;

function report(e) {
  state.errors.push(`${e.name}: ${e.message}`);
  $('error').textContent = `${e.name}: ${e.message}`;
  console.error(e);
}

// The view the output transform shows the frame through: the controls' values.
function showView({ toneMapping, exposure }) {
  $('tonemap').value = toneMapping;
  const slider = $('exposure');  // wide enough for the graph's own exposure
  slider.min = Math.min(-8, exposure);
  slider.max = Math.max(8, exposure);
  slider.value = exposure;
  viewChanged();
}
function viewChanged() {
  state.view = { toneMapping: $('tonemap').value, exposure: Number($('exposure').value) };
  $('exposure-value').textContent = `${Number(state.view.exposure.toFixed(2))} EV`;
}
$('tonemap').replaceChildren(...TONE_MAPPERS.map((t) => new Option(t, t)));
$('tonemap').onchange = viewChanged;
$('exposure').oninput = viewChanged;

$('graph').replaceChildren(...gallery.graphs.map((g) => new Option(g.name, g.name)));
$('graph').onchange = () => select($('graph').value).catch(report);
$('preset').onchange = () => select(state.graph, $('preset').value).catch(report);

const q = new URLSearchParams(location.search);
await select(q.get('graph') ?? gallery.graphs[0].name, q.get('preset') ?? 'default').catch(report);
renderer.setAnimationLoop((ms) => {
  if (!water) return;
  controls.update();
  water.update(ms / 1000, camera);
  floatBuoys(ms / 1000);
  water.render(renderer, scene, camera, null, state.view);
  if (state.frameFormat !== water.frameFormat) {
    state.frameFormat = water.frameFormat;
    $('frame').textContent = `frame: linear ${water.frameFormat}` + (water.frameFallback ? ` (${water.frameFallback})` : '');
  }
  state.frames++;
});
state.ready = true;
