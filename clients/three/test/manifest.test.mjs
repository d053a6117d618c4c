// The client against hostile manifests (node --test): every field kind of the documented
// shape (watergraph-manifest.js) refused with a WaterGraphError naming its path, through
// checkManifest and through the WaterGraph constructor, never a TypeError or a value taken
// silently; names from the manifest ("__proto__", "constructor") kept in tables without a
// prototype. WG_THREE_FIXTURES names a folder of manifests and es300 shaders compiled from
// proto_parameter (tests/ecosystem/data), topdown, lagoon and three_environment;
// tests/ecosystem/three_client_test.cpp writes them and runs this file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import * as THREE from 'three';
import { WaterGraph, WaterGraphError, checkManifest, applySamplerState } from '../watergraph-three.js';
import { presetCamera } from '../watergraph-scene.js';

const dir = process.env.WG_THREE_FIXTURES;
const read = (file) => {
  assert.ok(dir, 'WG_THREE_FIXTURES is not set');
  return readFileSync(path.join(dir, file), 'utf8');
};
// The es300 stages as three.js takes them: the manifest's version, the body files' texts.
const shadersOf = (manifest) => {
  const form = (stage) => ({ glsl_version: manifest.three[stage].glsl_version, body: read(manifest.three[stage].body_file) });
  return { vertex: form('vertex'), fragment: form('fragment') };
};
const graph = (name) => {
  const manifest = JSON.parse(read(`${name}.manifest.json`));
  return { manifest, shaders: shadersOf(manifest), resources: { environment: new THREE.CubeTexture() },
    textures: { t0_lagoon_ripples: new THREE.Texture() } };
};
const index = (list, pred, what) => {
  const i = list.findIndex(pred);
  assert.ok(i >= 0, `the fixture has no ${what}`);
  return i;
};

test('every manifest compile writes has the documented shape', () => {
  const manifests = readdirSync(dir).filter((f) => f.endsWith('.manifest.json'));
  assert.equal(manifests.length, 4, manifests.join(', '));
  for (const f of manifests) assert.doesNotThrow(() => checkManifest(JSON.parse(read(f))), f);
});

test('parameters named __proto__ and constructor are uniforms setParameter sets', () => {
  const g = graph('proto_parameter');
  const water = new WaterGraph(g);
  const slot = (parameter) => water.uniforms[g.manifest.uniforms.find((x) => x.parameter === parameter).name];
  assert.deepEqual(slot('__proto__').value.toArray(), [0.2, 0.5, 0.8]);
  assert.equal(slot('constructor').value, 0.25);
  water.setParameter('__proto__', [1, 0.5, 0]);
  assert.deepEqual(slot('__proto__').value.toArray(), [1, 0.5, 0]);
  water.setParameter('constructor', 3);  // clamped into the manifest's [0, 1]
  assert.equal(slot('constructor').value, 1);
  assert.equal(Object.getPrototypeOf(water.uniforms), null);
});

// Each case: a change to a compiled manifest, and the field its error must name.
const u = (m, pred, what) => index(m.uniforms, pred, what);
const CASES = [
  // The review's cases.
  ['topdown', 'a builtin "__proto__"', (m) => { const i = u(m, (x) => x.builtin === 'model', 'model'); m.uniforms[i].builtin = '__proto__'; return `uniforms[${i}].builtin`; }],
  ['topdown', 'a builtin "constructor"', (m) => { const i = u(m, (x) => x.builtin === 'view_projection', 'view_projection'); m.uniforms[i].builtin = 'constructor'; return `uniforms[${i}].builtin`; }],
  ['lagoon', '"textures": 5', (m) => { m.textures = 5; return 'textures'; }],
  ['topdown', 'a null uniform', (m) => { m.uniforms.splice(1, 0, null); return 'uniforms[1]'; }],
  ['topdown', 'an angular_frequency "abc"', (m) => { const i = u(m, (x) => x.builtin === 'time_phase', 'time_phase'); m.uniforms[i].angular_frequency = 'abc'; return `uniforms[${i}].angular_frequency`; }],
  // Top level.
  ['topdown', 'a misspelt member', (m) => { m.uniform = m.uniforms; return 'uniform'; }],
  ['topdown', 'another format', (m) => { m.format = 2; return 'format'; }],
  ['topdown', 'a graph name that is not a string', (m) => { m.graph = ['x']; return 'graph'; }],
  ['topdown', '"passes" an object', (m) => { m.passes = { water_surface: true }; return 'passes'; }],
  ['topdown', 'a pass that is a number', (m) => { m.passes.push(5); return `passes[${m.passes.length - 1}]`; }],
  ['three_environment', 'a resource "__proto__"', (m) => { m.resources = ['__proto__']; return 'resources[0]'; }],
  ['three_environment', 'a scale of a pass not listed', (m) => { m.pass_scales = { refraction: 0.5 }; return 'pass_scales.refraction'; }],
  ['three_environment', 'a scale that is a string', (m) => { m.passes.unshift('depth_prepass'); m.pass_scales = { depth_prepass: '0.5' }; return 'pass_scales.depth_prepass'; }],
  ['topdown', 'es300 files that are not strings', (m) => { m.targets.es300.vert = 5; return 'targets.es300.vert'; }],
  ['topdown', '"targets" a list', (m) => { m.targets = []; return 'targets'; }],
  ['topdown', 'an attribute location -1', (m) => { m.attributes[0].location = -1; return 'attributes[0].location'; }],
  ['topdown', 'an attribute named "__proto__ x"', (m) => { m.attributes[0].name = '__proto__ x'; return 'attributes[0].name'; }],
  // Uniforms.
  ['topdown', 'a uniform of type "__proto__"', (m) => { m.uniforms[0].type = '__proto__'; return 'uniforms[0].type'; }],
  ['topdown', 'a uniform without a name', (m) => { delete m.uniforms[0].name; return 'uniforms[0].name'; }],
  ['topdown', 'two uniforms of one name', (m) => { m.uniforms[1].name = m.uniforms[0].name; return 'uniforms[1].name'; }],
  ['topdown', 'a stage "geometry"', (m) => { m.uniforms[0].stages = ['geometry']; return 'uniforms[0].stages[0]'; }],
  ['topdown', 'a builtin with a foreign member', (m) => { m.uniforms[0].angular_frequency = 1; return 'uniforms[0].angular_frequency'; }],
  ['proto_parameter', 'a default "abc"', (m) => { const i = u(m, (x) => x.parameter === 'constructor', 'parameter'); m.uniforms[i].default = 'abc'; return `uniforms[${i}].default`; }],
  ['proto_parameter', 'a default of the wrong size', (m) => { const i = u(m, (x) => x.parameter === '__proto__', 'parameter'); m.uniforms[i].default = [1, 2]; return `uniforms[${i}].default`; }],
  ['proto_parameter', 'a min that is a string', (m) => { const i = u(m, (x) => x.parameter === 'constructor', 'parameter'); m.uniforms[i].min = '0'; return `uniforms[${i}].min`; }],
  ['proto_parameter', 'a min above max', (m) => { const i = u(m, (x) => x.parameter === 'constructor', 'parameter'); m.uniforms[i].min = 2; return `uniforms[${i}].min`; }],
  ['proto_parameter', 'a parameter held twice', (m) => { const i = u(m, (x) => x.parameter === 'constructor', 'parameter'); m.uniforms[i].parameter = '__proto__'; return `uniforms[${i}].parameter`; }],
  ['proto_parameter', 'a colour space "constructor"', (m) => { const i = u(m, (x) => x.parameter === '__proto__', 'parameter'); m.uniforms[i].color_space = 'constructor'; return `uniforms[${i}].color_space`; }],
  // Textures.
  ['lagoon', 'a texture null', (m) => { m.textures[0] = null; return 'textures[0]'; }],
  ['lagoon', 'a texture with a source and a resource', (m) => { m.textures[0].resource = 'environment'; return 'textures[0]'; }],
  ['lagoon', 'a texture sampler wrap "constructor"', (m) => { m.textures[0].sampler = { wrap: 'constructor', filter: 'linear', color_space: 'srgb' }; return 'textures[0].sampler.wrap'; }],
  ['lagoon', 'a node texture without its file', (m) => { delete m.textures[0].file; return 'textures[0].file'; }],
  ['lagoon', 'a node texture file in another folder', (m) => { m.textures[0].file = '../secret.png'; return 'textures[0].file'; }],
  ['lagoon', 'a node texture file with a backslash', (m) => { m.textures[0].file = 'a\\b.png'; return 'textures[0].file'; }],
  ['lagoon', 'a texture binding "0"', (m) => { m.textures[0].binding = '0'; return 'textures[0].binding'; }],
  ['lagoon', 'a texture of type "__proto__"', (m) => { m.textures[0].type = '__proto__'; return 'textures[0].type'; }],
  ['three_environment', 'a scene texture of resource "constructor"', (m) => { m.textures[0].resource = 'constructor'; return 'textures[0].resource'; }],
  // A spectral ocean's members (the shape `compile --target es300` writes for open_ocean).
  ['topdown', 'an ocean without its module', (m) => { m.oceans = [{ node: 'sea', options: {} }]; m.passes.unshift('ocean_simulation'); return 'oceans[0].module'; }],
  ['topdown', 'an ocean module outside the manifest\'s folder', (m) => { m.oceans = [{ module: '../x.js', node: 'sea', options: {} }]; m.passes.unshift('ocean_simulation'); return 'oceans[0].module'; }],
  ['topdown', 'oceans without the ocean_simulation pass', (m) => { m.oceans = [{ module: 'topdown.ocean.js', node: 'sea', options: {} }]; return 'passes'; }],
  ['topdown', 'an ocean map of an ocean "oceans" lacks', (m) => { m.textures = [{ name: 'u_map', type: 'sampler2D', binding: 1, stages: ['vertex'], ocean: { ocean: 0, cascade: 0, map: 'displacement' } }]; return 'textures[0].ocean.ocean'; }],
  ['topdown', 'an ocean without "filtered"', (m) => { m.oceans = [{ module: 'topdown.ocean.js', node: 'sea', options: {} }]; m.passes.unshift('ocean_simulation'); return 'oceans[0].filtered'; }],
  ['topdown', 'an ocean "filtered": "yes"', (m) => { m.oceans = [{ filtered: 'yes', module: 'topdown.ocean.js', node: 'sea', options: {} }]; m.passes.unshift('ocean_simulation'); return 'oceans[0].filtered'; }],
  ['topdown', 'a filtered ocean whose moments map no texture reads', (m) => { m.oceans = [{ filtered: true, module: 'topdown.ocean.js', node: 'sea', options: {} }]; m.passes.unshift('ocean_simulation'); return 'oceans[0].filtered'; }],
  ['topdown', 'a moments map of an ocean not filtered', (m) => {
    m.oceans = [{ filtered: false, module: 'topdown.ocean.js', node: 'sea', options: {} }];
    m.passes.unshift('ocean_simulation');
    m.textures = [{ name: 'u_map', type: 'sampler2D', binding: 1, stages: ['fragment'], ocean: { ocean: 0, cascade: 0, map: 'moments' } }];
    return 'oceans[0].filtered';
  }],
  // The es300 stages' bodies (what the client fetches) and their version.
  ['topdown', 'an es300 body file in another folder', (m) => { m.three.vertex.body_file = '../secret.vert'; return 'three.vertex.body_file'; }],
  ['topdown', 'an es300 body file that is not a string', (m) => { m.three.fragment.body_file = 5; return 'three.fragment.body_file'; }],
  ['topdown', 'a body file without its glsl_version', (m) => { delete m.three.vertex.glsl_version; return 'three.vertex.glsl_version'; }],
  ['topdown', 'a "three" without the fragment stage', (m) => { delete m.three.fragment; return 'three.fragment'; }],
  ['topdown', 'a "three" stage "geometry"', (m) => { m.three.geometry = m.three.vertex; return 'three.geometry'; }],
  ['topdown', 'an ocean map "__proto__"', (m) => { m.textures = [{ name: 'u_map', type: 'sampler2D', binding: 1, stages: ['vertex'], ocean: { ocean: 0, cascade: 0, map: '__proto__' } }]; return 'textures[0].ocean.map'; }],
];

for (const [fixture, what, change] of CASES) {
  test(`refused, naming its field: ${what}`, () => {
    const g = graph(fixture);
    assert.doesNotThrow(() => checkManifest(g.manifest));  // the fixture as compiled is accepted
    const field = change(g.manifest);
    const named = (e) => {
      assert.ok(e instanceof WaterGraphError, `${e?.constructor?.name}: ${e?.message}`);
      assert.equal(e.field, field, e.message);
      assert.ok(e.message.includes(`manifest's ${field} `), e.message);
      return true;
    };
    assert.throws(() => checkManifest(g.manifest), named);
    assert.throws(() => new WaterGraph(g), named);
  });
}

test('without a scene description, a pass the client does not know is refused by name', () => {
  const g = graph('topdown');
  g.manifest.passes.push('constructor');
  assert.doesNotThrow(() => checkManifest(g.manifest));  // a name: a newer runtime's description may have it
  assert.throws(() => new WaterGraph(g), (e) => e instanceof WaterGraphError &&
    e.message.includes('constructor (a pass this client does not know)'));
});

test('without a scene description, a spectral ocean is refused naming its pass', () => {
  const g = graph('topdown');
  g.manifest.oceans = [{ filtered: false, module: 'topdown.ocean.js', node: 'sea', options: {} }];
  g.manifest.passes.unshift('ocean_simulation');
  assert.doesNotThrow(() => checkManifest(g.manifest));
  assert.throws(() => new WaterGraph(g), (e) => e instanceof WaterGraphError &&
    e.message.includes("ocean_simulation (a spectral ocean: its passes' shaders come with a scene description)"));
});

// What the removed --derived-uniforms wrote: a uniform no client computes, refused with
// what to do about it (not as an unknown builtin).
test('a derived uniform is refused, saying to compile the graph again', () => {
  const g = graph('topdown');
  const i = index(g.manifest.uniforms, (x) => x.builtin === 'model', 'model');
  g.manifest.uniforms[i].builtin = 'derived';
  g.manifest.uniforms[i].derived = { ops: [], value: { op: 0 } };
  const refused = (e) => e instanceof WaterGraphError && e.field === `uniforms[${i}].builtin` &&
    e.message.includes('no longer has: compile the graph again');
  assert.throws(() => checkManifest(g.manifest), refused);
  assert.throws(() => new WaterGraph(g), refused);
});

test('a manifest that is no object is refused', () => {
  for (const m of [null, 5, 'x', []])
    assert.throws(() => checkManifest(m), (e) => e instanceof WaterGraphError && e.field === '');
});

test('a sampler state naming a prototype member is refused', () => {
  for (const sampler of [{ wrap: 'constructor' }, { filter: '__proto__' }, { color_space: 'toString' }])
    assert.throws(() => applySamplerState(new THREE.Texture(), sampler), WaterGraphError);
});

test('a camera preset named after a prototype member is no preset', () => {
  const description = { cameras: JSON.parse('{"above": {"fov_y_degrees": 50, "near": 0.1, "far": 100, ' +
    '"position": [0, 5, 10], "up": [0, 1, 0], "target": [0, 0, 0]}}') };
  assert.equal(presetCamera(description, 'above', 1).fov, 50);
  for (const name of ['__proto__', 'constructor', 'toString'])
    assert.throws(() => presetCamera(description, name, 1), (e) => e instanceof WaterGraphError && e.message.includes(`no camera '${name}'`));
});
